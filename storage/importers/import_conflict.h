// An import that contradicts what the database holds: a capture label already stored with other
// content, or a dataset name already used by another format. The HTTP API answers it with 409
// (docs/data-api.md); a malformed archive is a KiderFormatError instead (400).
#pragma once

#include <stdexcept>
#include <string>

namespace clearsky::storage {

class ImportConflict : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace clearsky::storage
