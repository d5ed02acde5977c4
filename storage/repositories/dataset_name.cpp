// The dataset name rule (dataset_name.h).
#include "storage/repositories/dataset_name.h"

namespace clearsky::storage {
namespace {

bool is_letter_or_digit(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
}

}  // namespace

bool is_valid_dataset_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxDatasetNameChars || !is_letter_or_digit(name.front()))
    return false;
  for (const char c : name)
    if (!is_letter_or_digit(c) && c != '.' && c != '_' && c != '-') return false;
  return true;
}

}  // namespace clearsky::storage
