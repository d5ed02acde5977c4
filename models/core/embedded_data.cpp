// Lookup by path in the generated table of embedded files.
#include "models/core/embedded_data.h"

#include <stdexcept>
#include <string>

namespace clearsky::data {

std::string_view embedded_file(std::string_view path) {
  for (const EmbeddedFile& file : embedded_files()) {
    if (file.path == path) return file.content;
  }
  throw std::out_of_range("no embedded data file '" + std::string(path) + "'");
}

}  // namespace clearsky::data
