// Containment of canonical paths (path_containment.h).
#include "storage/importers/path_containment.h"

namespace clearsky::storage {

bool lies_within(const std::filesystem::path& canonical_path,
                 const std::filesystem::path& canonical_folder) {
  if (canonical_folder.empty() || !canonical_path.is_absolute() || !canonical_folder.is_absolute())
    return false;
  auto path_it = canonical_path.begin();
  for (const std::filesystem::path& component : canonical_folder) {
    // A trailing separator gives an empty last component, which names nothing.
    if (component.empty()) continue;
    if (path_it == canonical_path.end() || *path_it != component) return false;
    ++path_it;
  }
  return true;
}

}  // namespace clearsky::storage
