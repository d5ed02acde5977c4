// SQL of the captures and samples tables (capture_repository.h).
#include "storage/repositories/capture_repository.h"

#include <map>

#include "storage/repositories/utc_clock.h"
#include "storage/sqlite/blob.h"

namespace clearsky::storage {

std::optional<std::int64_t> CaptureRepository::find_by_hash(std::int64_t dataset_id, const std::string& content_hash) {
  auto query = db_.prepare("SELECT id FROM captures WHERE dataset_id = ? AND content_hash = ?");
  query.bind(1, dataset_id).bind(2, content_hash);
  if (!query.step()) return std::nullopt;
  return query.column_int64(0);
}

std::optional<std::pair<std::int64_t, std::string>> CaptureRepository::find_by_label(std::int64_t dataset_id,
                                                                                      const std::string& label) {
  auto query = db_.prepare("SELECT id, content_hash FROM captures WHERE dataset_id = ? AND label = ?");
  query.bind(1, dataset_id).bind(2, label);
  if (!query.step()) return std::nullopt;
  return std::make_pair(query.column_int64(0), query.column_text(1));
}

std::int64_t CaptureRepository::insert(std::int64_t dataset_id, const MeasuredCapture& capture,
                                       const std::string& content_hash, const std::string& source) {
  auto insert_capture = db_.prepare(
      "INSERT INTO captures (dataset_id, label, time_utc_s, utc_offset_minutes, latitude_deg, longitude_deg,"
      " elevation_m, sun_zenith_computed_deg, sun_azimuth_computed_deg, sun_azimuth_estimated_deg, content_hash,"
      " source, imported_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert_capture.bind(1, dataset_id)
      .bind(2, capture.label)
      .bind(3, capture.unix_time_utc_s)
      .bind(4, capture.utc_offset_minutes)
      .bind(5, capture.site.latitude_deg)
      .bind(6, capture.site.longitude_deg)
      .bind(7, capture.site.elevation_m)
      .bind(8, capture.sun_zenith_computed_deg)
      .bind(9, capture.sun_azimuth_computed_deg)
      .bind(10, capture.sun_azimuth_estimated_deg)
      .bind(11, content_hash)
      .bind(12, source)
      .bind(13, utc_now_iso8601());
  insert_capture.run();
  const std::int64_t capture_id = db_.last_insert_rowid();
  auto insert_sample = db_.prepare(
      "INSERT INTO samples (capture_id, scan_index, view_zenith_rad, view_azimuth_rad, wavelengths_nm, radiance,"
      " quality_flags) VALUES (?, ?, ?, ?, ?, ?, ?)");
  for (const MeasuredSample& s : capture.samples) {
    insert_sample.reset();
    insert_sample.bind(1, capture_id)
        .bind(2, s.index)
        .bind(3, s.view.zenith_rad)
        .bind(4, s.view.azimuth_rad)
        .bind_blob(5, encode_doubles(s.radiance.wavelengths_nm()))
        .bind_blob(6, encode_doubles(s.radiance.values()))
        .bind(7, static_cast<std::int64_t>(s.quality_flags));
    insert_sample.run();
  }
  return capture_id;
}

std::vector<StoredCapture> CaptureRepository::load(std::int64_t dataset_id) {
  std::vector<StoredCapture> result;
  std::map<std::int64_t, std::size_t> position;
  auto captures = db_.prepare(
      "SELECT id, label, time_utc_s, utc_offset_minutes, latitude_deg, longitude_deg, elevation_m,"
      " sun_zenith_computed_deg, sun_azimuth_computed_deg, sun_azimuth_estimated_deg, content_hash, source"
      " FROM captures WHERE dataset_id = ? ORDER BY time_utc_s, label");
  captures.bind(1, dataset_id);
  while (captures.step()) {
    StoredCapture stored;
    stored.id = captures.column_int64(0);
    MeasuredCapture& c = stored.capture;
    c.label = captures.column_text(1);
    c.unix_time_utc_s = captures.column_double(2);
    c.utc_offset_minutes = static_cast<int>(captures.column_int64(3));
    c.site = {captures.column_double(4), captures.column_double(5), captures.column_double(6)};
    c.sun_zenith_computed_deg = captures.column_double_or_nan(7);
    c.sun_azimuth_computed_deg = captures.column_double_or_nan(8);
    c.sun_azimuth_estimated_deg = captures.column_double_or_nan(9);
    stored.content_hash = captures.column_text(10);
    stored.source = captures.column_text(11);
    position[stored.id] = result.size();
    result.push_back(std::move(stored));
  }
  auto samples = db_.prepare(
      "SELECT s.capture_id, s.scan_index, s.view_zenith_rad, s.view_azimuth_rad, s.wavelengths_nm, s.radiance,"
      " s.quality_flags FROM samples s JOIN captures c ON s.capture_id = c.id WHERE c.dataset_id = ?"
      " ORDER BY s.capture_id, s.scan_index");
  samples.bind(1, dataset_id);
  while (samples.step()) {
    MeasuredSample s;
    s.index = static_cast<int>(samples.column_int64(1));
    s.view = {samples.column_double(2), samples.column_double(3)};
    s.radiance = TabulatedSpectrum(decode_doubles(samples.column_blob(4)), decode_doubles(samples.column_blob(5)));
    s.quality_flags = static_cast<std::uint32_t>(samples.column_int64(6));
    result[position.at(samples.column_int64(0))].capture.samples.push_back(std::move(s));
  }
  return result;
}

void CaptureRepository::set_estimated_sun_azimuth(std::int64_t capture_id, double azimuth_deg) {
  auto statement = db_.prepare("UPDATE captures SET sun_azimuth_estimated_deg = ? WHERE id = ?");
  statement.bind(1, azimuth_deg).bind(2, capture_id);
  statement.run();
}

}  // namespace clearsky::storage
