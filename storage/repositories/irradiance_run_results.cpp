// SQL of the evaluation_irradiance_results table (irradiance_run_results.h).
#include "storage/repositories/irradiance_run_results.h"

#include "storage/sqlite/blob.h"

namespace clearsky::storage {

void IrradianceRunResultRepository::store(std::int64_t run_id,
                                          const std::vector<IrradianceRunResult>& results) {
  Transaction transaction(db_);
  auto statement = db_.prepare(
      "INSERT INTO evaluation_irradiance_results (run_id, component, rmse_w_m2, mean_bias_w_m2,"
      " samples_compared, errors_w_m2) VALUES (?, ?, ?, ?, ?, ?)");
  for (const IrradianceRunResult& r : results) {
    statement.reset();
    const std::vector<std::byte> errors = encode_doubles(r.errors_w_m2);
    statement.bind(1, run_id)
        .bind(2, r.component)
        .bind_optional(3, r.rmse_w_m2)
        .bind_optional(4, r.mean_bias_w_m2)
        .bind(5, r.samples_compared)
        .bind_blob(6, errors);
    statement.run();
  }
  transaction.commit();
}

std::vector<IrradianceRunResult> IrradianceRunResultRepository::load(std::int64_t run_id) {
  auto query = db_.prepare(
      "SELECT component, rmse_w_m2, mean_bias_w_m2, samples_compared, errors_w_m2"
      " FROM evaluation_irradiance_results WHERE run_id = ?"
      " ORDER BY CASE component WHEN 'ghi' THEN 0 WHEN 'dhi' THEN 1 ELSE 2 END");
  query.bind(1, run_id);
  std::vector<IrradianceRunResult> results;
  while (query.step()) {
    IrradianceRunResult r;
    r.component = query.column_text(0);
    if (!query.is_null(1)) r.rmse_w_m2 = query.column_double(1);
    if (!query.is_null(2)) r.mean_bias_w_m2 = query.column_double(2);
    r.samples_compared = query.column_int64(3);
    const std::vector<std::byte> errors = query.column_blob(4);
    r.errors_w_m2 = decode_doubles(errors);
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace clearsky::storage
