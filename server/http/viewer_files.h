// The browser viewer's static files (docs/viewer.md), served by the HTTP server at / from the
// folder `clearsky serve --viewer-dir` names (by default the viewer built into the build tree by
// deploy/build.sh). The folder's files are listed once, when the server starts: only those
// paths are served (cpp-httplib's mount point reads them), every other unknown path stays a 404
// in the API's error format, and a rebuilt viewer is served after a restart.
// Cache headers: files under assets/ carry a hash of their content in their name (the build
// writes them so) and are cached for a year as immutable; the others (index.html, which names
// the current assets) are revalidated at every load (no-cache).
// Thread-safety: immutable after construction.
#pragma once

#include <set>
#include <string>
#include <string_view>

namespace clearsky::server {

class ViewerFiles {
 public:
  // An empty dir, or one without index.html: no viewer (serves() is always false).
  explicit ViewerFiles(const std::string& dir);

  bool enabled() const { return !paths_.empty(); }
  const std::string& dir() const { return dir_; }
  // A GET of url_path is a viewer file ("/" is index.html).
  bool serves(std::string_view url_path) const;
  // The Cache-Control header of the file at url_path.
  static const char* cache_control(std::string_view url_path);
  // The Content-Security-Policy of the viewer's files: everything from this server only.
  static const char* content_security_policy();

 private:
  std::string dir_;
  std::set<std::string, std::less<>> paths_;  // "/index.html", "/assets/app-1f2e3d.js", ...
};

}  // namespace clearsky::server
