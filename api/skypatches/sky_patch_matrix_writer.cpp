// A sky matrix as JSON, CSV or Radiance's matrix format (sky_patch_matrix_writer.h).
#include "api/skypatches/sky_patch_matrix_writer.h"

#include "api/encode/csv_number.h"
#include "api/encode/iso8601_time.h"

namespace clearsky::api {

namespace {

// Text is handed to the sink in blocks of about this many bytes.
constexpr std::size_t kBlockBytes = 1 << 16;

// Collects text and hands it to the sink a block at a time.
class BlockWriter {
 public:
  explicit BlockWriter(const ByteSink& sink) : sink_(sink) {}
  std::string& text() { return text_; }
  // After each piece: false once the sink refused.
  bool flush_if_full() { return text_.size() < kBlockBytes || flush(); }
  bool flush() {
    const bool ok = text_.empty() || sink_(text_.data(), text_.size());
    text_.clear();
    return ok;
  }

 private:
  const ByteSink& sink_;
  std::string text_;
};

nlohmann::json value_json(const SkyPatchMatrix& m, std::size_t patch, std::size_t step,
                          bool single) {
  if (single) return finite(m.at(patch, step, 0));
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t c = 0; c < m.components; ++c) out.push_back(finite(m.at(patch, step, c)));
  return out;
}

}  // namespace

bool write_sky_matrix_json(const SkyMatrixAnswer& a, nlohmann::json head, const ByteSink& sink) {
  const SkyPatchMatrix& m = a.matrix;
  const TimeSteps& times = a.times;
  nlohmann::json patches = nlohmann::json::array();
  for (std::size_t k = 0; k < m.patch_count; ++k) {
    const PatchGeometry g = patch_geometry(a.scheme, k);
    patches.push_back({{"patch", k},
                       {"altitude_deg", g.altitude_deg},
                       {"azimuth_deg", g.azimuth_deg},
                       {"solid_angle_sr", g.solid_angle_sr}});
  }
  nlohmann::json columns = nlohmann::json::array();
  const bool single = a.component_suffixes.size() == 1;
  for (std::size_t step = 0; step < m.steps; ++step) {
    const double t = times.unix_time_s(step);
    nlohmann::json column = {{"time_utc", format_iso8601_time(t, 0, true)},
                             {"night", times.night(step)},
                             {"answered", static_cast<bool>(m.answered[step])},
                             {"sun_zenith_deg", finite(times.zenith_deg[step])},
                             {"sun_azimuth_deg", finite(times.azimuth_deg[step])},
                             {"sun_patch", m.sun_patch[step]}};
    if (times.tz) column["time_local"] = format_iso8601_time_in_zone(t, *times.tz);
    if (m.suns[step]) {
      const SkyMatrixSun& sun = *m.suns[step];
      nlohmann::json value = nlohmann::json::array();
      for (double x : sun.value) value.push_back(finite(x));
      column["sun_source"] = {{"direction", sun.direction},
                              {"solid_angle_sr", sun_disk_solid_angle_sr()},
                              {"value", single ? value[0] : value}};
    } else {
      column["sun_source"] = nullptr;
    }
    columns.push_back(std::move(column));
  }
  head["patches"] = std::move(patches);
  head["times"] = std::move(columns);
  BlockWriter out(sink);
  out.text() = head.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  out.text().pop_back();  // the closing brace: the matrix follows
  out.text() += ",\"matrix\":[";
  for (std::size_t patch = 0; patch < m.patch_count; ++patch) {
    if (patch > 0) out.text() += ',';
    out.text() += '[';
    for (std::size_t step = 0; step < m.steps; ++step) {
      if (step > 0) out.text() += ',';
      out.text() += value_json(m, patch, step, single).dump();
      if (!out.flush_if_full()) return false;
    }
    out.text() += ']';
  }
  out.text() += "],\"unanswered_steps\":" + std::to_string(m.unanswered_steps) + "}";
  return out.flush();
}

bool write_sky_matrix_csv(const SkyMatrixAnswer& a, const ByteSink& sink) {
  const SkyPatchMatrix& m = a.matrix;
  BlockWriter out(sink);
  std::string& text = out.text();
  text = "patch,altitude_deg,azimuth_deg,solid_angle_sr";
  for (std::size_t step = 0; step < m.steps; ++step) {
    const std::string time = format_iso8601_time(a.times.unix_time_s(step), 0, true);
    for (const std::string& suffix : a.component_suffixes) text += ',' + time + suffix;
    if (!out.flush_if_full()) return false;
  }
  text += "\nnight,,,";
  for (std::size_t step = 0; step < m.steps; ++step) {
    for (std::size_t c = 0; c < m.components; ++c) text += a.times.night(step) ? ",1" : ",0";
  }
  text += '\n';
  for (std::size_t patch = 0; patch < m.patch_count; ++patch) {
    const PatchGeometry g = patch_geometry(a.scheme, patch);
    text += std::to_string(patch) + ',' + csv_number(g.altitude_deg) + ',' +
            csv_number(g.azimuth_deg) + ',' + csv_number(g.solid_angle_sr);
    for (std::size_t step = 0; step < m.steps; ++step) {
      for (std::size_t c = 0; c < m.components; ++c) text += ',' + csv_number(m.at(patch, step, c));
      if (!out.flush_if_full()) return false;
    }
    text += '\n';
  }
  return out.flush();
}

bool write_sky_matrix_radiance(const SkyMatrixAnswer& a, const ByteSink& sink) {
  const SkyPatchMatrix& m = a.matrix;
  BlockWriter out(sink);
  std::string& text = out.text();
  text = "#?RADIANCE\nNROWS=" + std::to_string(m.patch_count) +
         "\nNCOLS=" + std::to_string(m.steps) + "\nNCOMP=" + std::to_string(m.components) +
         "\nFORMAT=ascii\n\n";
  for (std::size_t patch = 0; patch < m.patch_count; ++patch) {
    for (std::size_t step = 0; step < m.steps; ++step) {
      for (std::size_t c = 0; c < m.components; ++c) {
        if (c > 0) text += '\t';
        text += csv_number(m.at(patch, step, c));
      }
      text += '\n';
      if (!out.flush_if_full()) return false;
    }
    text += '\n';
  }
  return out.flush();
}

}  // namespace clearsky::api
