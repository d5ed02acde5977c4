// The one rule for dataset names, checked wherever a dataset is created (the upload and path
// imports of POST /v1/datasets, `clearsky import`, the importer itself): 1 to 128 characters of
// A-Z, a-z, 0-9, '.', '_' and '-', the first a letter or a digit. Such a name is one URL path
// segment as it is (RFC 3986 section 3.3: no '/', no percent-encoding needed), so every dataset
// can be read and deleted at /v1/datasets/{name}, and it is never "." or "..". Datasets stored
// before the rule keep their names and stay readable where their names allow
// (docs/data-api.md "Datasets").
#pragma once

#include <cstddef>
#include <string_view>

namespace clearsky::storage {

inline constexpr std::size_t kMaxDatasetNameChars = 128;
inline constexpr std::string_view kDatasetNameRule =
    "1 to 128 characters of A-Z a-z 0-9 . _ -, the first a letter or a digit";

bool is_valid_dataset_name(std::string_view name);

}  // namespace clearsky::storage
