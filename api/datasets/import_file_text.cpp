// The whole text of an open-format file (import_file_text.h).
#include "api/datasets/import_file_text.h"

#include <fstream>
#include <stdexcept>

#include "api/error/api_error.h"

namespace clearsky::api {

std::string read_import_file_text(const std::filesystem::path& file,
                                  const storage::ImportByteLimits& limits,
                                  const std::string& shown_as) {
  const std::int64_t limit = limits.max_entry_bytes;
  const std::string limit_name = "max_entry_bytes";
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) throw std::runtime_error(shown_as + ": cannot be read");
  if (size > static_cast<std::uintmax_t>(limit))
    throw ApiError(413, "too_large", limit_name,
                   shown_as + ": " + std::to_string(size) + " bytes, above " + limit_name + " (" +
                       std::to_string(limit) + " bytes)");
  std::string text(size, '\0');
  std::ifstream in(file, std::ios::binary);
  if (!in.read(text.data(), static_cast<std::streamsize>(size)))
    throw std::runtime_error(shown_as + ": cannot be read");
  return text;
}

}  // namespace clearsky::api
