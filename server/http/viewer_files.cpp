// The viewer's files and their cache headers (viewer_files.h).
#include "server/http/viewer_files.h"

#include <filesystem>
#include <system_error>

namespace clearsky::server {

ViewerFiles::ViewerFiles(const std::string& dir) : dir_(dir) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (dir.empty() || !fs::is_regular_file(fs::path(dir) / "index.html", error)) return;
  const fs::path root = fs::canonical(dir, error);
  if (error) return;
  for (auto it = fs::recursive_directory_iterator(root, error);
       !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (!it->is_regular_file(error)) continue;
    paths_.insert("/" + fs::relative(it->path(), root, error).generic_string());
  }
}

bool ViewerFiles::serves(std::string_view url_path) const {
  if (url_path == "/") return enabled();
  return paths_.find(url_path) != paths_.end();
}

const char* ViewerFiles::cache_control(std::string_view url_path) {
  if (url_path.starts_with("/assets/")) return "public, max-age=31536000, immutable";
  return "no-cache";
}

const char* ViewerFiles::content_security_policy() {
  return "default-src 'self'; img-src 'self' blob: data:; style-src 'self' 'unsafe-inline'; "
         "frame-ancestors 'none'";
}

}  // namespace clearsky::server
