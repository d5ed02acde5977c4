// SQL of the irradiance_samples table (irradiance_sample_repository.h).
#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::storage {

std::int64_t IrradianceSampleRepository::insert(std::int64_t dataset_id,
                                                const std::vector<IrradianceSample>& samples) {
  // IS compares NULLs as equal, as a missing component is the same on both sides.
  auto statement = db_.prepare(
      "INSERT INTO irradiance_samples (dataset_id, time_utc_s, utc_offset_minutes, latitude_deg,"
      " longitude_deg, elevation_m, ghi_w_m2, dhi_w_m2, dni_w_m2, averaging_s)"
      " SELECT ?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10 WHERE NOT EXISTS ("
      " SELECT 1 FROM irradiance_samples WHERE dataset_id = ?1 AND time_utc_s = ?2"
      " AND utc_offset_minutes = ?3 AND latitude_deg = ?4 AND longitude_deg = ?5"
      " AND elevation_m = ?6 AND ghi_w_m2 IS ?7 AND dhi_w_m2 IS ?8 AND dni_w_m2 IS ?9"
      " AND averaging_s IS ?10)");
  std::int64_t added = 0;
  for (const IrradianceSample& sample : samples) {
    statement.reset();
    statement.bind(1, dataset_id)
        .bind(2, sample.time_utc_s)
        .bind(3, sample.utc_offset_minutes)
        .bind(4, sample.latitude_deg)
        .bind(5, sample.longitude_deg)
        .bind(6, sample.elevation_m)
        .bind_optional(7, sample.ghi_w_m2)
        .bind_optional(8, sample.dhi_w_m2)
        .bind_optional(9, sample.dni_w_m2)
        .bind_optional(10, sample.averaging_s);
    statement.run();
    added += db_.changes();
  }
  return added;
}

std::vector<IrradianceSample> IrradianceSampleRepository::list(std::int64_t dataset_id) {
  auto query = db_.prepare(
      "SELECT time_utc_s, utc_offset_minutes, latitude_deg, longitude_deg, elevation_m, ghi_w_m2,"
      " dhi_w_m2, dni_w_m2, averaging_s FROM irradiance_samples WHERE dataset_id = ?"
      " ORDER BY time_utc_s, id");
  query.bind(1, dataset_id);
  const auto optional_column = [&query](int column) -> std::optional<double> {
    if (query.is_null(column)) return std::nullopt;
    return query.column_double(column);
  };
  std::vector<IrradianceSample> samples;
  while (query.step()) {
    IrradianceSample sample;
    sample.time_utc_s = query.column_double(0);
    sample.utc_offset_minutes = static_cast<int>(query.column_int64(1));
    sample.latitude_deg = query.column_double(2);
    sample.longitude_deg = query.column_double(3);
    sample.elevation_m = query.column_double(4);
    sample.ghi_w_m2 = optional_column(5);
    sample.dhi_w_m2 = optional_column(6);
    sample.dni_w_m2 = optional_column(7);
    sample.averaging_s = optional_column(8);
    samples.push_back(sample);
  }
  return samples;
}

}  // namespace clearsky::storage
