// The results of an evaluation run on a broadband irradiance dataset (schema version 9,
// docs/data-api.md "Evaluations of broadband irradiance"): per measured component (ghi, dhi,
// dni), the RMSE and mean bias (model minus measured, W/m2) and every sample's error in the
// dataset's sample order (NaN where not compared). The run itself is an evaluation_runs row
// (evaluation_run_repository.h). SQL on evaluation_irradiance_results lives only here.
// Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "storage/sqlite/database.h"

namespace clearsky::storage {

struct IrradianceRunResult {
  std::string component;  // ghi, dhi or dni
  std::optional<double> rmse_w_m2;
  std::optional<double> mean_bias_w_m2;
  std::int64_t samples_compared = 0;
  std::vector<double> errors_w_m2;
};

class IrradianceRunResultRepository {
 public:
  explicit IrradianceRunResultRepository(Database& db) : db_(db) {}
  void store(std::int64_t run_id, const std::vector<IrradianceRunResult>& results);
  // In the order ghi, dhi, dni; empty for a run of another kind.
  std::vector<IrradianceRunResult> load(std::int64_t run_id);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
