// Which samples an evaluation run compared (docs/data-api.md "History comparison"): the run's
// captures by label and, per capture, the samples it left out or clamped, as one key, so that
// the history compares a run only with runs over the same samples. Per capture the handling is
// canonical text, `<excluded|clamped> <reason> <i1>,<i2>,...` entries joined by ';' (excluded
// first, reasons and scan indices ascending; empty when every sample was compared as measured);
// the key is the FNV-1a 64 hex of the captures' lines `<label>\t<handling>` sorted by label
// (bytes) and joined by '\n'. register_compared_samples_key() makes compared_samples_key(text)
// an SQL function (text: those joined lines; NULL as empty), with which the schema migration
// keys the runs stored before it (which compared every sample of their captures).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "storage/sqlite/database.h"

namespace clearsky::storage {

// The samples of a capture left out or clamped for one reason (SampleStatus names).
struct SampleHandling {
  std::string handling;  // "excluded" or "clamped"
  std::string reason;    // e.g. "outside_fit_domain"
  std::vector<std::int32_t> indices;
  bool operator==(const SampleHandling&) const = default;
};

std::string encode_sample_handling(const std::vector<SampleHandling>& entries);
// Throws std::runtime_error for text encode_sample_handling() did not write.
std::vector<SampleHandling> decode_sample_handling(std::string_view text);

// The key of (label, encoded handling) pairs, in any order.
std::string compared_samples_key(std::vector<std::pair<std::string, std::string>> captures);
void register_compared_samples_key(Database& db);

}  // namespace clearsky::storage
