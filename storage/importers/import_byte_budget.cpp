// Byte budgets counted while reading (import_byte_budget.h).
#include "storage/importers/import_byte_budget.h"

namespace clearsky::storage {

void ImportByteBudget::charge(std::int64_t& entry_bytes, std::size_t n, const std::string& what) {
  const auto more = static_cast<std::int64_t>(n);
  if (more > limits_.max_entry_bytes - entry_bytes)
    throw ImportLimitExceeded("max_entry_bytes", limits_.max_entry_bytes,
                              what + ": the entry is above max_entry_bytes (" +
                                  std::to_string(limits_.max_entry_bytes) + " bytes)");
  const std::int64_t total = import_bytes_.fetch_add(more) + more;
  if (total > limits_.max_import_bytes)
    throw ImportLimitExceeded("max_import_bytes", limits_.max_import_bytes,
                              what + ": the import is above max_import_bytes (" +
                                  std::to_string(limits_.max_import_bytes) + " bytes read)");
  entry_bytes += more;
}

}  // namespace clearsky::storage
