// Resolution of server-side import paths inside the import roots (import_roots.h).
#include "api/datasets/import_roots.h"

#include <stdexcept>

#include "api/error/api_error.h"
#include "storage/importers/path_containment.h"

namespace clearsky::api {
namespace {

ApiError not_importable() {
  return ApiError::about(404, "path_not_importable", "path",
                         "no file or folder of that name can be imported from this server's "
                         "import roots");
}

}  // namespace

ImportRoots::ImportRoots(const std::vector<std::string>& roots) {
  for (const std::string& root : roots) {
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::canonical(root, error);
    if (error || !std::filesystem::is_directory(canonical, error))
      throw std::invalid_argument("import root " + root + " is not an existing folder");
    roots_.push_back(canonical);
  }
}

ResolvedImportPath ImportRoots::resolve(const std::string& requested) const {
  if (roots_.empty())
    throw ApiError::about(403, "path_imports_disabled", "path",
                          "this server imports no server-side paths (no --import-root); upload "
                          "the archive as the body instead");
  // A NUL byte would cut the path short where the system reads it.
  if (requested.empty() || requested.find('\0') != std::string::npos) throw not_importable();
  const std::filesystem::path asked(requested);
  for (const std::filesystem::path& root : roots_) {
    std::error_code error;
    const std::filesystem::path canonical =
        std::filesystem::canonical(asked.is_absolute() ? asked : root / asked, error);
    if (error || !storage::lies_within(canonical, root)) continue;
    const std::filesystem::file_status status = std::filesystem::symlink_status(canonical, error);
    if (error) continue;
    if (std::filesystem::is_regular_file(status) || std::filesystem::is_directory(status))
      return {canonical, root};
  }
  throw not_importable();
}

}  // namespace clearsky::api
