// The samples of a broadband irradiance dataset (schema version 9, docs/measurement-formats.md
// "Broadband irradiance"): horizontal irradiance measured at instants, W/m2. SQL on the
// irradiance_samples table lives only here.
// Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "storage/sqlite/database.h"

namespace clearsky::storage {

// One measured instant. At least one of the three components is present; each is W/m2 on the
// plane it names: global and diffuse on the horizontal plane, direct on the plane normal to the
// sun (ISO 9488 terms).
struct IrradianceSample {
  double time_utc_s = 0;       // unix seconds
  int utc_offset_minutes = 0;  // local time of the instrument's clock minus UTC
  double latitude_deg = 0;
  double longitude_deg = 0;
  double elevation_m = 0;
  std::optional<double> ghi_w_m2;
  std::optional<double> dhi_w_m2;
  std::optional<double> dni_w_m2;
  std::optional<double> averaging_s;  // the period each value averages, when known
};

class IrradianceSampleRepository {
 public:
  explicit IrradianceSampleRepository(Database& db) : db_(db) {}
  // Appends the samples to the dataset in their order, but for those identical (instant, clock,
  // site, values) to one it holds, so that importing a file again adds nothing; the number
  // added. The caller holds the transaction.
  std::int64_t insert(std::int64_t dataset_id, const std::vector<IrradianceSample>& samples);
  // The dataset's samples by instant, then in the order they were stored.
  std::vector<IrradianceSample> list(std::int64_t dataset_id);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
