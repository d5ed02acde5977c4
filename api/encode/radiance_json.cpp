// The /v1/radiance JSON answer as text (radiance_json.h).
#include "api/encode/radiance_json.h"

#include "api/encode/json_text.h"
#include "api/request/quality_statement.h"

namespace clearsky::api {

namespace {

// The text of the answered wavelengths, kept per thread for the last list: most requests ask
// the model's default grid, whose 40 numbers cost as much to format as the radiance values.
const std::string& wavelengths_text(const std::vector<double>& wavelengths_nm) {
  thread_local std::vector<double> last_values;
  thread_local std::string last_text;
  thread_local bool known = false;
  if (!known || last_values != wavelengths_nm) {
    last_text.clear();
    append_json_number_array(last_text, wavelengths_nm);
    last_values = wavelengths_nm;
    known = true;
  }
  return last_text;
}

// sun_json(): {"azimuth_deg", "source", "zenith_deg"}.
std::string sun_text(const SunSpec& sun) {
  std::string out = "{\"azimuth_deg\":";
  append_finite_json_number(out, sun.azimuth_deg);
  out += sun.from_place_and_time ? ",\"source\":\"spa\",\"zenith_deg\":"
                                 : ",\"source\":\"given\",\"zenith_deg\":";
  append_finite_json_number(out, sun.zenith_deg);
  out += '}';
  return out;
}

std::string samples_text(const RadianceAnswer& a) {
  std::string out;
  // About 20 bytes a number, and 60 of keys and angles a view.
  out.reserve(2 + a.batch.size() * (64 + 24 * a.indices.size()));
  out += '[';
  for (std::size_t v = 0; v < a.batch.size(); ++v) {
    if (v > 0) out += ',';
    const auto spectrum = a.batch.spectrum(v);
    out += "{\"radiance\":[";
    for (std::size_t k = 0; k < a.indices.size(); ++k) {
      if (k > 0) out += ',';
      append_finite_json_number(out, spectrum[a.indices[k]]);
    }
    out += "],\"view_azimuth_deg\":";
    append_json_number(out, a.views.azimuth_deg[v]);
    out += ",\"view_zenith_deg\":";
    append_json_number(out, a.views.zenith_deg[v]);
    out += '}';
  }
  out += ']';
  return out;
}

std::string string_text(std::string_view s) {
  std::string out;
  append_json_string(out, s);
  return out;
}

std::string number_text(double x) {
  std::string out;
  append_json_number(out, x);
  return out;
}

}  // namespace

std::string radiance_json(const RadianceAnswer& a) {
  const bool bins = a.grid.kind() == WavelengthGrid::Kind::bins;
  const std::string samples = samples_text(a);
  const std::string sun = sun_text(a.sun);
  const std::string model = string_text(a.descriptor.id);
  const std::string version = string_text(a.descriptor.version);
  const std::string altitude = number_text(a.viewpoint.altitude_m);
  const std::string bin_width = bins ? number_text(a.grid.bin_width_nm()) : std::string();
  const std::string fit = a.fit ? applied_fit_json(*a.fit).dump() : std::string();
  const QualityStatement& quality = quality_statement(a.quality, a.served_quality);

  JsonObjectText body;
  body.add("model", model);
  body.add("model_version", version);
  body.add("sun", sun);
  body.add("altitude_m", altitude);
  body.add("unit", "\"W/(m2.sr.nm)\"");
  body.add("grid", bins ? R"("bins")" : R"("points")");
  body.add("wavelengths_nm", wavelengths_text(a.wavelengths_nm));
  body.add("samples", samples);
  if (bins) body.add("bin_width_nm", bin_width);
  for (const auto& [key, value] : quality.members) body.add(key, value);
  if (a.fit) body.add("fit", fit);
  std::string out;
  body.append_to(out);
  return out;
}

}  // namespace clearsky::api
