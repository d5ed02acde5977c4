// Parsing of the embedded Hosek-Wilkie tables; every row is placed by the indices it names
// (never by its position), and a table with a missing or duplicated entry is an error.
#include "models/hosek/hosek_tables.h"

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "models/core/embedded_data.h"
#include "models/spectral/tabulated_spectrum.h"

namespace clearsky::hosek {
namespace {

NumericTable read_embedded(const std::string& path) {
  std::istringstream in{std::string(data::embedded_file(path))};
  return read_numeric_table(in, path);
}

// An integer index from a table cell, checked against [0, count).
int index_of(double value, double first, double step, int count, const std::string& what,
             const std::string& source) {
  const double position = (value - first) / step;
  const double rounded = std::round(position);
  if (!(std::abs(position - rounded) < 1e-9 && rounded >= 0 && rounded < count)) {
    throw std::runtime_error(source + ": " + what + " " + std::to_string(value) +
                             " is not in the table");
  }
  return static_cast<int>(rounded);
}

// Reads one sky dataset (coefficients and radiance scale). The channel column is
// "wavelength_nm" for the spectral tables and "channel" for the RGB and XYZ ones.
template <std::size_t N>
void read_sky(const std::string& coefficients_path, const std::string& radiance_path,
              const std::string& channel_column, double first_channel, double channel_step,
              std::array<SkyChannel, N>& channels) {
  const int channel_count = static_cast<int>(N);
  constexpr std::size_t kEntries = 2 * kTurbidityCount * kControlPoints;
  {
    const NumericTable table = read_embedded(coefficients_path);
    const std::size_t c = table.column_index(channel_column);
    const std::size_t a = table.column_index("albedo");
    const std::size_t t = table.column_index("turbidity");
    const std::size_t p = table.column_index("control_point");
    const std::size_t first = table.column_index("A");
    std::vector<int> seen(N * kEntries, 0);
    for (const auto& row : table.rows) {
      const int ci = index_of(row[c], first_channel, channel_step, channel_count, channel_column,
                              coefficients_path);
      const int ai = index_of(row[a], 0, 1, 2, "albedo", coefficients_path);
      const int ti = index_of(row[t], 1, 1, kTurbidityCount, "turbidity", coefficients_path);
      const int pi = index_of(row[p], 0, 1, kControlPoints, "control_point", coefficients_path);
      for (int k = 0; k < kCoefficientCount; ++k) {
        channels[ci].coefficients[ai][ti][pi][k] = row[first + k];
      }
      ++seen[static_cast<std::size_t>(ci) * kEntries +
             (ai * kTurbidityCount + ti) * kControlPoints + pi];
    }
    for (int s : seen) {
      if (s != 1) throw std::runtime_error(coefficients_path + ": missing or duplicated entries");
    }
  }
  {
    const NumericTable table = read_embedded(radiance_path);
    const std::size_t c = table.column_index(channel_column);
    const std::size_t a = table.column_index("albedo");
    const std::size_t t = table.column_index("turbidity");
    const std::size_t p = table.column_index("control_point");
    const std::size_t r = table.column_index("radiance");
    std::vector<int> seen(N * kEntries, 0);
    for (const auto& row : table.rows) {
      const int ci = index_of(row[c], first_channel, channel_step, channel_count, channel_column,
                              radiance_path);
      const int ai = index_of(row[a], 0, 1, 2, "albedo", radiance_path);
      const int ti = index_of(row[t], 1, 1, kTurbidityCount, "turbidity", radiance_path);
      const int pi = index_of(row[p], 0, 1, kControlPoints, "control_point", radiance_path);
      channels[ci].radiance[ai][ti][pi] = row[r];
      ++seen[static_cast<std::size_t>(ci) * kEntries +
             (ai * kTurbidityCount + ti) * kControlPoints + pi];
    }
    for (int s : seen) {
      if (s != 1) throw std::runtime_error(radiance_path + ": missing or duplicated entries");
    }
  }
}

// On the heap: the tables are about 300 kB, too much for a worker thread's stack.
std::unique_ptr<Tables> load() {
  auto owned = std::make_unique<Tables>();
  Tables& tables = *owned;
  read_sky("hosek/spectral_sky_coefficients.csv", "hosek/spectral_sky_radiance_scale.csv",
           "wavelength_nm", kFirstBandNm, kBandSpacingNm, tables.spectral);
  read_sky("hosek/rgb_sky_coefficients.csv", "hosek/rgb_sky_radiance_scale.csv", "channel", 0, 1,
           tables.rgb);
  read_sky("hosek/xyz_sky_coefficients.csv", "hosek/xyz_sky_radiance_scale.csv", "channel", 0, 1,
           tables.xyz);
  {
    const std::string path = "hosek/solar_radiance_coefficients.csv";
    const NumericTable table = read_embedded(path);
    const std::size_t w = table.column_index("wavelength_nm");
    const std::size_t t = table.column_index("turbidity");
    const std::size_t s = table.column_index("segment");
    const std::size_t first = table.column_index("c0");
    std::vector<int> seen(kBandCount * kTurbidityCount * kSolarSegments, 0);
    for (const auto& row : table.rows) {
      const int wi =
          index_of(row[w], kFirstBandNm, kBandSpacingNm, kBandCount, "wavelength_nm", path);
      const int ti = index_of(row[t], 1, 1, kTurbidityCount, "turbidity", path);
      const int si = index_of(row[s], 0, 1, kSolarSegments, "segment", path);
      for (int k = 0; k < kSolarOrder; ++k) tables.solar[wi][ti][si][k] = row[first + k];
      ++seen[(wi * kTurbidityCount + ti) * kSolarSegments + si];
    }
    for (int n : seen) {
      if (n != 1) throw std::runtime_error(path + ": missing or duplicated entries");
    }
  }
  {
    const std::string path = "hosek/limb_darkening.csv";
    const NumericTable table = read_embedded(path);
    const std::size_t w = table.column_index("wavelength_nm");
    const std::size_t first = table.column_index("c0");
    std::vector<int> seen(kBandCount, 0);
    for (const auto& row : table.rows) {
      const int wi =
          index_of(row[w], kFirstBandNm, kBandSpacingNm, kBandCount, "wavelength_nm", path);
      for (int k = 0; k < kLimbDarkeningOrder; ++k) tables.limb_darkening[wi][k] = row[first + k];
      ++seen[wi];
    }
    for (int n : seen) {
      if (n != 1) throw std::runtime_error(path + ": missing or duplicated entries");
    }
  }
  {
    const std::string path = "hosek/original_solar_radiance.csv";
    const NumericTable table = read_embedded(path);
    const std::size_t w = table.column_index("wavelength_nm");
    const std::size_t r = table.column_index("radiance");
    std::vector<int> seen(kBandCount, 0);
    for (const auto& row : table.rows) {
      const int wi =
          index_of(row[w], kFirstBandNm, kBandSpacingNm, kBandCount, "wavelength_nm", path);
      tables.original_solar_radiance[wi] = row[r];
      ++seen[wi];
    }
    for (int n : seen) {
      if (n != 1) throw std::runtime_error(path + ": missing or duplicated entries");
    }
  }
  return owned;
}

}  // namespace

const Tables& Tables::get() {
  static const std::unique_ptr<const Tables> tables = load();
  return *tables;
}

}  // namespace clearsky::hosek
