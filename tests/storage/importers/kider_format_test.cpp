// Tests of the Kider et al. 2014 format: file names, the azimuth convention, spectra, and the
// errors for malformed and short files (storage/importers/kider_format.h).
#include "storage/importers/kider_format.h"

#include <gtest/gtest.h>

#include <sstream>

#include "models/core/numeric.h"

namespace clearsky::storage {
namespace {

TEST(KiderFileName, DecodesTimeIndexAndDirection) {
  const auto name = parse_kider_file_name("2013-05-27___09.30.00_-_42____195.0___33.749.asd.rad.txt");
  ASSERT_TRUE(name.has_value());
  EXPECT_EQ(name->capture_label, "2013-05-27___09.30.00");
  EXPECT_EQ(name->year, 2013);
  EXPECT_EQ(name->month, 5);
  EXPECT_EQ(name->day, 27);
  EXPECT_EQ(name->hour, 9);
  EXPECT_EQ(name->minute, 30);
  EXPECT_EQ(name->index, 42);
  EXPECT_DOUBLE_EQ(name->azimuth_ccw_deg, 195.0);
  EXPECT_DOUBLE_EQ(name->elevation_deg, 33.749);
}

TEST(KiderFileName, IgnoresOtherFiles) {
  EXPECT_FALSE(parse_kider_file_name("2013-05-27___10.30.00_-_0____0.0___12.1151.asd.txt"));
  EXPECT_FALSE(parse_kider_file_name("notes.txt"));
  EXPECT_FALSE(parse_kider_file_name("2013-05-27___09.30.00_-_42____195.0___95.0.asd.rad.txt"));
}

TEST(KiderViewDirection, CounterClockwiseFileAzimuthBecomesClockwise) {
  // File azimuth 90 (counter-clockwise: West) is clockwise 270.
  const ViewDirection west = kider_view_direction(90.0, 12.1151);
  EXPECT_NEAR(west.azimuth_rad, 270.0 * kDegree, 1e-12);
  EXPECT_NEAR(west.zenith_rad, 77.8849 * kDegree, 1e-12);
  EXPECT_NEAR(kider_view_direction(11.25, 12.1151).azimuth_rad, 348.75 * kDegree, 1e-12);
  EXPECT_NEAR(kider_view_direction(0.0, 90.0).azimuth_rad, 0.0, 1e-12);
  EXPECT_NEAR(kider_view_direction(0.0, 90.0).zenith_rad, 0.0, 1e-12);
}

TEST(KiderSpectrum, ReadsRowsWithCarriageReturnsAndExponents) {
  std::ostringstream text;
  text << "Wavelength\tfile.asd.rad\r\n";
  for (int w = 350; w <= 2500; ++w) text << w << "\t " << (w == 351 ? "5.70084191858768E-02" : "0.5") << " \r\n";
  std::istringstream in(text.str());
  const TabulatedSpectrum s = read_kider_spectrum(in, "file");
  EXPECT_EQ(s.wavelengths_nm().size(), 2151u);
  EXPECT_DOUBLE_EQ(s.at(351, OutOfRange::error), 5.70084191858768E-02);
  EXPECT_DOUBLE_EQ(s.at(350.5, OutOfRange::error), 0.5 * (0.5 + 5.70084191858768E-02));
}

std::string spectrum_text(int last_nm, const std::string& bad_row = "", int bad_at = -1) {
  std::ostringstream text;
  text << "Wavelength\tx\n";
  for (int w = 350; w <= last_nm; ++w) {
    if (w == bad_at)
      text << bad_row << "\n";
    else
      text << w << "\t0.1\n";
  }
  return text.str();
}

void expect_error_at(const std::string& text, long line, const std::string& fragment) {
  std::istringstream in(text);
  try {
    read_kider_spectrum(in, "sky/a.asd.rad.txt");
    FAIL() << "no error, expected line " << line;
  } catch (const KiderFormatError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.source(), "sky/a.asd.rad.txt");
    EXPECT_NE(std::string(e.what()).find("sky/a.asd.rad.txt:" + std::to_string(line) + ": "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(KiderSpectrum, MalformedRowsAreReportedWithTheirLine) {
  // Row of 400 nm is line 2 + (400 - 350) = 52.
  expect_error_at(spectrum_text(2500, "400\t", 400), 52, "expected two numbers");
  expect_error_at(spectrum_text(2500, "400\tabc", 400), 52, "expected two numbers");
  expect_error_at(spectrum_text(2500, "400\t0.1\t7", 400), 52, "expected two numbers");
  expect_error_at(spectrum_text(2500, "399\t0.1", 400), 52, "does not increase");
  expect_error_at(spectrum_text(2500, "400\tnan", 400), 52, "expected two numbers");
}

TEST(KiderSpectrum, ShortFilesAreReportedAtTheirLastLine) {
  expect_error_at(spectrum_text(1000), 652, "short file");
  expect_error_at("Wavelength\tx\n", 1, "no data rows");
  expect_error_at("350\t0.1\n351\t0.2\n", 1, "expected a header line");
  std::istringstream empty("");
  EXPECT_THROW(read_kider_spectrum(empty, "e"), KiderFormatError);
}

KiderSampleFile sample_file(int index, double azimuth_ccw, double elevation) {
  KiderSampleFile f;
  f.source = std::string("sample ").append(std::to_string(index));
  f.name.capture_label = "2013-05-27___09.30.00";
  f.name.year = 2013;
  f.name.month = 5;
  f.name.day = 27;
  f.name.hour = 9;
  f.name.minute = 30;
  f.name.index = index;
  f.name.azimuth_ccw_deg = azimuth_ccw;
  f.name.elevation_deg = elevation;
  f.radiance = TabulatedSpectrum({350, 2500}, {0.1, 0.1});
  return f;
}

TEST(KiderCapture, AssemblesTimeSiteAndFlagsTheNorthSample) {
  std::vector<KiderSampleFile> files;
  for (int i = 80; i >= 0; --i) files.push_back(sample_file(i, i * 1.0, 12.1151));
  const MeasuredCapture c = assemble_kider_capture(files, {});
  EXPECT_EQ(c.samples.size(), 81u);
  EXPECT_EQ(c.samples[0].index, 0);
  EXPECT_EQ(c.samples[0].quality_flags, kSampleKnownDefective);
  EXPECT_EQ(c.samples[1].quality_flags, 0u);
  EXPECT_DOUBLE_EQ(c.unix_time_utc_s, 1369661400.0);  // 13:30 UTC
  EXPECT_EQ(local_time_iso8601(c), "2013-05-27T09:30:00-04:00");
  EXPECT_DOUBLE_EQ(c.site.latitude_deg, 42.443449);
}

TEST(KiderCapture, MissingOrRepeatedSamplesAreRefused) {
  std::vector<KiderSampleFile> files;
  for (int i = 0; i < 81; ++i) files.push_back(sample_file(i, 0, 12.1151));
  auto missing = files;
  missing.erase(missing.begin() + 17);
  try {
    assemble_kider_capture(missing, {});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("missing 17"), std::string::npos) << e.what();
  }
  auto repeated = files;
  repeated[3] = sample_file(4, 0, 12.1151);
  EXPECT_THROW(assemble_kider_capture(repeated, {}), std::invalid_argument);
}

}  // namespace
}  // namespace clearsky::storage
