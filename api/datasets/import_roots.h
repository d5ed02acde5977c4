// The folders from which POST /v1/datasets?path= may import (`clearsky serve --import-root DIR`,
// repeatable, or import_root in the config file): the operator's promise that token holders
// may read what lies in them (docs/threat-model.md "read the server's files"). None by default:
// path imports are refused.
//
// A requested path is resolved relative to each root in turn (an absolute one must lie inside a
// root as it is): every link is followed to its canonical form, which must still lie inside that
// root (a link out of it is refused, a link within it is fine), and it must be a regular file or
// a folder (devices, fifos and sockets are refused). Every refusal is the same error, 404
// path_not_importable naming "path", with a message that does not depend on why (missing,
// outside the roots, leading out through a link, a special file, unreadable), so that answers
// do not tell which paths exist on the server. The importer then reads the canonical path
// confined to its root (storage/importers/kider_reader.h), so a link swapped in afterwards is
// not followed out either.
// Thread-safety: immutable after construction; resolve may be called from any thread.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace clearsky::api {

struct ResolvedImportPath {
  std::filesystem::path path;  // canonical
  std::filesystem::path root;  // canonical, path lies inside it
};

class ImportRoots {
 public:
  ImportRoots() = default;
  // Canonicalises each root; throws std::invalid_argument naming one that is not an existing
  // folder (a server misconfiguration is refused at start).
  explicit ImportRoots(const std::vector<std::string>& roots);

  bool empty() const { return roots_.empty(); }
  const std::vector<std::filesystem::path>& roots() const { return roots_; }

  // The file or folder requested names under a root; throws ApiError 404 path_not_importable
  // (one refusal, see above), or 403 path_imports_disabled when there is no root.
  ResolvedImportPath resolve(const std::string& requested) const;

 private:
  std::vector<std::filesystem::path> roots_;
};

}  // namespace clearsky::api
