// The pyranometer records published with the Kider et al. 2014 captures (ACM TOG 33(6)): global
// horizontal irradiance, W/m2, of the site's roof, in two layouts.
// - Per-capture files (one for each radiance capture): rows `value  YYYY.MM.DD.HH.MM.SS`, the
//   clock the local time of the site (utc_offset_minutes of the options), a record every 4 or
//   5 seconds during the capture.
// - The whole day (`pyranometer_full_day.txt`): rows `offset  value`, the offset counting
//   MINUTES from the first record (consecutive records 0.0667 apart match the per-capture
//   files' 4-second steps; as hours the day would last 25 days), to three decimals (so about
//   0.06 s). The file gives no clock: the first record's local time is given
//   (first_record_local), or taken from the per-capture files read with it, whose earliest
//   record must then be the day file's first, value for value.
// Throws std::invalid_argument naming the file and line of a malformed row.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "storage/importers/kider_format.h"
#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::storage {

struct KiderPyranometerRead {
  std::vector<IrradianceSample> samples;  // by instant
  // What was read and how the day file's clock was set, for the import report.
  std::vector<std::string> notes;
};

// The records of the files (per-capture files, a day file, or folders holding them, read
// recursively: *.txt whose name is a `YYYY.MM.DD.HH.MM.SS.txt` clock, and
// pyranometer_full_day.txt). With a day file, its records are the samples and the per-capture
// files only set and check its clock (their records are the same instrument's, a second copy).
// first_record_local: YYYY.MM.DD.HH.MM.SS or YYYY-MM-DDThh:mm:ss, local time.
KiderPyranometerRead read_kider_pyranometer(const std::vector<std::filesystem::path>& paths,
                                            const KiderImportOptions& options,
                                            const std::optional<std::string>& first_record_local);

}  // namespace clearsky::storage
