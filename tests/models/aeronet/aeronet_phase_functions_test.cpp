// The AERONET phase-function inversion reader (models/aeronet/aeronet_phase_functions.h) on the
// file of models/data/aeronet and on damaged copies of it.
#include "models/aeronet/aeronet_phase_functions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "models/core/embedded_data.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"

namespace clearsky::aeronet {
namespace {

std::string egbert() {
  return std::string(data::embedded_file("aeronet/130527_130527_Egbert.pfn"));
}

// The reason of the InvalidInput parsing `text` throws (field "inversion"), or "" if none.
std::string refusal(const std::string& text) {
  try {
    parse_phase_function_file(text);
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "inversion");
    return e.reason();
  }
  return "";
}

// Replaces the n-th (0-based) comma-separated field of line `line` (0-based).
std::string with_field(const std::string& text, int line, int field, const std::string& value) {
  std::size_t start = 0;
  for (int l = 0; l < line; ++l) start = text.find('\n', start) + 1;
  for (int f = 0; f < field; ++f) start = text.find(',', start) + 1;
  const std::size_t end = text.find_first_of(",\n", start);
  return text.substr(0, start) + value + text.substr(end);
}

TEST(AeronetPhaseFunctions, ReadsTheEgbertInversion) {
  const PhaseFunctionFile file = parse_phase_function_file(egbert());
  EXPECT_EQ(file.site, "Egbert");
  EXPECT_DOUBLE_EQ(file.latitude_deg, 44.226);
  EXPECT_DOUBLE_EQ(file.longitude_deg, -79.75);
  EXPECT_EQ(file.level, "Level 1.5 Almucantar Retrievals, Version 2");
  EXPECT_EQ(file.wavelengths_nm, (std::vector<double>{442, 674, 871, 1020}));
  ASSERT_EQ(file.angles_deg.size(), 83u);
  EXPECT_EQ(file.angles_deg.front(), 0.0);
  EXPECT_EQ(file.angles_deg[1], 1.71);
  EXPECT_EQ(file.angles_deg.back(), 180.0);
  ASSERT_EQ(file.retrievals.size(), 5u);
  const PhaseFunctionRetrieval& first = file.retrievals[0];
  EXPECT_EQ(first.date, "27:05:2013");
  EXPECT_EQ(first.time, "11:19:04");
  EXPECT_NEAR(first.time_utc_h, 11.0 + 19.0 / 60 + 4.0 / 3600, 1e-12);
  EXPECT_DOUBLE_EQ(first.aod_440, 0.113925);
  EXPECT_DOUBLE_EQ(first.angstrom_440_870, 1.174858);
  ASSERT_EQ(first.phase.size(), 4u);
  EXPECT_DOUBLE_EQ(first.phase[0][0], 73.34549);
  EXPECT_DOUBLE_EQ(first.phase[0][1], 41.61686);
  EXPECT_NEAR(first.aod_at(440.0), 0.113925, 1e-15);
  EXPECT_NEAR(first.aod_at(880.0), 0.113925 * std::pow(2.0, -1.174858), 1e-12);
  EXPECT_EQ(file.retrievals[4].time, "14:18:59");
  // AERONET's normalisation: (1/2) int P sin(theta) dtheta = 1, to the trapezoid's ~0.5%.
  for (const auto& r : file.retrievals) {
    for (const auto& p : r.phase) {
      double sum = 0.0;
      for (std::size_t a = 0; a + 1 < p.size(); ++a) {
        const double t0 = file.angles_deg[a] * kDegree;
        const double t1 = file.angles_deg[a + 1] * kDegree;
        sum += 0.5 * (p[a] * std::sin(t0) + p[a + 1] * std::sin(t1)) * (t1 - t0);
      }
      EXPECT_NEAR(sum / 2.0, 1.0, 0.01);
    }
  }
  // The content hash identifies the text.
  EXPECT_NE(file.content_hash, parse_phase_function_file(egbert() + "\n\n").content_hash);
}

TEST(AeronetPhaseFunctions, MissingValueNamesLineAndColumn) {
  // Line 5, field 3: the 0-degree value at 442 nm.
  const std::string reason = refusal(with_field(egbert(), 4, 3, "-999.000000"));
  EXPECT_NE(reason.find("line 5"), std::string::npos) << reason;
  EXPECT_NE(reason.find("0.0000[442nm]"), std::string::npos) << reason;
  EXPECT_NE(reason.find("-999"), std::string::npos) << reason;
  // tau440(measured) is column 342 (1-based), field 341.
  const std::string aod = refusal(with_field(egbert(), 6, 341, "-999."));
  EXPECT_NE(aod.find("line 7"), std::string::npos) << aod;
  EXPECT_NE(aod.find("tau440(measured)"), std::string::npos) << aod;
  // A column the models do not use may be missing.
  EXPECT_NO_THROW(parse_phase_function_file(with_field(egbert(), 4, 338, "-999.000000")));
}

TEST(AeronetPhaseFunctions, TruncatedAndMalformedLines) {
  const std::string text = egbert();
  const std::string cut = text.substr(0, text.rfind(',', text.size() - 400));
  const std::string reason = refusal(cut);
  EXPECT_NE(reason.find("line 9"), std::string::npos) << reason;
  EXPECT_NE(reason.find("fields"), std::string::npos) << reason;
  EXPECT_NE(refusal(with_field(text, 5, 10, "abc")).find("is not a number"), std::string::npos);
  EXPECT_NE(refusal(with_field(text, 5, 1, "25:00")).find("not a time"), std::string::npos);
  EXPECT_NE(refusal(with_field(text, 5, 20, "0")).find("must be positive"), std::string::npos);
  // Header only, or less.
  std::size_t header_end = 0;
  for (int l = 0; l < 4; ++l) header_end = text.find('\n', header_end) + 1;
  EXPECT_NE(refusal(text.substr(0, header_end)).find("no retrieval"), std::string::npos);
  EXPECT_NE(refusal(text.substr(0, 200)).find("truncated"), std::string::npos);
  EXPECT_NE(refusal("").find("truncated"), std::string::npos);
}

TEST(AeronetPhaseFunctions, RefusesOtherProductsAndLayouts) {
  const std::string text = egbert();
  const std::size_t line3 = text.find('\n', text.find('\n') + 1) + 1;
  const std::string ssa =
      text.substr(0, line3) + "Single Scattering Albedo" + text.substr(text.find(',', line3));
  EXPECT_NE(refusal(ssa).find("not a phase-function product"), std::string::npos);
  EXPECT_NE(refusal("not,a,header\n" + text.substr(text.find('\n') + 1)).find("line 1"),
            std::string::npos);
  const std::string no_aod = with_field(text, 3, 341, "tau500(measured)");
  EXPECT_NE(refusal(no_aod).find("tau440(measured) missing"), std::string::npos);
  const std::string wrong_date = with_field(text, 3, 0, "Date(yyyy-mm-dd)");
  EXPECT_NE(refusal(wrong_date).find("line 4"), std::string::npos);
  // An angle missing at one wavelength only.
  const std::string ragged = with_field(text, 3, 5, "3.9400[442nm]");
  EXPECT_NE(refusal(ragged).find("other angles"), std::string::npos);
}

// A small forged inversion: two wavelengths, `angles` angles from 0 to 180 degrees, the given
// retrieval lines (date, time and the values of one row, the same for every retrieval).
struct Forged {
  std::vector<double> angles_deg = {0, 5, 10, 20, 40, 60, 90, 120, 150, 170, 180};
  std::vector<std::string> wavelengths = {"442", "871"};
  std::vector<std::pair<std::string, std::string>> times = {{"27:05:2013", "11:19:04"},
                                                            {"27:05:2013", "12:00:00"}};
  std::string value = "1.5";  // every phase-function value
  std::string aod = "0.1";    // tau440(measured)
  std::string alpha = "1.2";  // alpha440-870
  std::string text() const {
    std::string t =
        "27:05:2013,Locations=Forged,long=-79.750,lat=44.226,elev=264,Nmeas=2\n"
        "Level 1.5 Almucantar Retrievals, Version 2\n"
        "Phase Functions - Total Mode,ALL POINTS DATA\n"
        "Date(dd-mm-yyyy),Time(hh:mm:ss),Julian_Day";
    for (const std::string& w : wavelengths)
      for (double a : angles_deg)
        t.append(",").append(std::to_string(a)).append("[").append(w).append("nm]");
    t += ",alpha440-870,tau440(measured)\n";
    for (const auto& [date, time] : times) {
      t.append(date).append(",").append(time).append(",147.0");
      for (std::size_t i = 0; i < wavelengths.size() * angles_deg.size(); ++i)
        t.append(",").append(value);
      t.append(",").append(alpha).append(",").append(aod).append("\n");
    }
    return t;
  }
};

TEST(AeronetPhaseFunctions, ReadsAForgedInversion) {
  const PhaseFunctionFile file = parse_phase_function_file(Forged{}.text());
  EXPECT_EQ(file.site, "Forged");
  EXPECT_EQ(file.wavelengths_nm, (std::vector<double>{442, 871}));
  EXPECT_EQ(file.angles_deg.size(), 11u);
  ASSERT_EQ(file.retrievals.size(), 2u);
  EXPECT_EQ(file.first_day, "2013-05-27");
  EXPECT_EQ(file.last_day, "2013-05-27");
  EXPECT_DOUBLE_EQ(file.retrievals[1].aod_440, 0.1);
  EXPECT_EQ(parse_phase_function_file(egbert()).first_day, "2013-05-27");
}

TEST(AeronetPhaseFunctions, ForgedFillAndEmptyValues) {
  Forged f;
  f.value = "-999.";
  EXPECT_NE(refusal(f.text()).find("is missing (-999)"), std::string::npos);
  f = Forged{};
  f.alpha = "";
  const std::string empty = refusal(f.text());
  EXPECT_NE(empty.find("alpha440-870 is empty"), std::string::npos) << empty;
  EXPECT_NE(empty.find("line 5"), std::string::npos) << empty;
  f = Forged{};
  f.aod = "-999.000000";
  EXPECT_NE(refusal(f.text()).find("tau440(measured) is missing"), std::string::npos);
}

TEST(AeronetPhaseFunctions, ForgedNonFiniteNumbers) {
  for (const std::string bad : {"nan", "inf", "-INF", "infinity", "1e999"}) {
    Forged f;
    f.value = bad;
    const std::string reason = refusal(f.text());
    EXPECT_NE(reason.find("is not finite"), std::string::npos) << bad << ": " << reason;
  }
  Forged f;
  f.aod = "nan";
  EXPECT_NE(refusal(f.text()).find("tau440(measured): \"nan\" is not finite"), std::string::npos);
  f = Forged{};
  f.value = "1.5x";
  EXPECT_NE(refusal(f.text()).find("is not a number"), std::string::npos);
}

TEST(AeronetPhaseFunctions, ForgedAngleCountsAndOrder) {
  Forged f;
  f.angles_deg = {0, 10, 30, 60, 90, 180};
  EXPECT_NE(refusal(f.text()).find("10 at least expected"), std::string::npos);
  f = Forged{};
  f.angles_deg = {0, 5, 10, 40, 20, 60, 90, 120, 150, 170, 180};
  EXPECT_NE(refusal(f.text()).find("angles must increase"), std::string::npos);
  f = Forged{};
  f.angles_deg = {0, 5, 10, 20, 20, 60, 90, 120, 150, 170, 180};
  EXPECT_NE(refusal(f.text()).find("angles must increase"), std::string::npos);
  f = Forged{};
  f.angles_deg = {0, 5, 10, 20, 40, 60, 90, 120, 150, 170, 179};
  EXPECT_NE(refusal(f.text()).find("from 0 to 180"), std::string::npos);
  // One wavelength (442 nm) with one angle more than the other.
  f = Forged{};
  std::string text = f.text();
  const std::size_t at = text.find(",0.000000[871nm]");
  ASSERT_NE(at, std::string::npos);
  text.insert(at, ",175.000000[442nm]");
  const std::string reason = refusal(text);
  EXPECT_NE(reason.find("11 phase-function angles at 871"), std::string::npos) << reason;
}

TEST(AeronetPhaseFunctions, ForgedRetrievalsOfOneDayInTimeOrder) {
  Forged f;
  f.times = {{"27:05:2013", "11:00:00"}, {"27:05:2013", "12:00:00"}, {"27:05:2013", "13:30:00"}};
  EXPECT_EQ(parse_phase_function_file(f.text()).retrievals.size(), 3u);
  f.times = {{"27:05:2013", "12:00:00"}, {"27:05:2013", "11:00:00"}};
  const std::string order = refusal(f.text());
  EXPECT_NE(order.find("not after the previous one"), std::string::npos) << order;
  EXPECT_NE(order.find("line 6"), std::string::npos) << order;
  f.times = {{"27:05:2013", "12:00:00"}, {"27:05:2013", "12:00:00"}};
  EXPECT_NE(refusal(f.text()).find("not after the previous one"), std::string::npos);
  f.times = {{"27:05:2013", "12:00:00"}, {"28:05:2013", "09:00:00"}};
  EXPECT_NE(refusal(f.text()).find("several days"), std::string::npos);
  f.times = {{"2013-05-27", "12:00:00"}};
  EXPECT_NE(refusal(f.text()).find("is not a date"), std::string::npos);
}

TEST(AeronetPhaseFunctions, ForgedEmptyAndHeaderOnly) {
  EXPECT_NE(refusal("").find("truncated"), std::string::npos);
  EXPECT_NE(refusal("\n\n\r\n").find("truncated"), std::string::npos);
  Forged f;
  f.times.clear();
  EXPECT_NE(refusal(f.text()).find("no retrieval"), std::string::npos);
}

}  // namespace
}  // namespace clearsky::aeronet
