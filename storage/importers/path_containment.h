// Whether a file lies in a folder, for server-side imports confined to the operator's import
// roots (docs/data-api.md "Server-side paths"): both paths must already be canonical
// (std::filesystem::canonical: absolute, no ".", "..", or symbolic links), and the file is
// inside when the folder's components are a prefix of its own. The folder itself counts as
// inside. Pure function of the two paths; thread-safe.
#pragma once

#include <filesystem>

namespace clearsky::storage {

bool lies_within(const std::filesystem::path& canonical_path,
                 const std::filesystem::path& canonical_folder);

}  // namespace clearsky::storage
