// The sky methods of clearsky::client::Client against a real `clearsky serve` (Preetham, the
// cheap analytic model): models, sun, radiance (one view and a batch), irradiance, RGB (one
// view and a batch), the skydome streamed to a stream and to a file, and the refusals as Error
// naming the parameter.
#include <clearsky/client/client.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>

#include "tests/clients/cpp/client_server.h"

namespace clearsky::client {
namespace {

class SkyClient : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server_ = new testing::ClientServer({}, "preetham");
    ASSERT_GT(server_->port(), 0) << server_->log();
    ASSERT_TRUE(server_->ready()) << server_->log();
  }
  static void TearDownTestSuite() {
    delete server_;
    server_ = nullptr;
  }
  static Client client() { return server_->client(); }
  template <typename Request>
  static Request sky(Request request) {
    request.model = "preetham";
    request.sun = SunAngles{40, 100};
    return request;
  }
  static testing::ClientServer* server_;
};
testing::ClientServer* SkyClient::server_ = nullptr;

TEST_F(SkyClient, ModelsListTheServedModelWithItsParameters) {
  const auto models = client().models();
  ASSERT_EQ(models.size(), 1u);
  EXPECT_EQ(models[0].id, "preetham");
  EXPECT_EQ(models[0].table_status, "ready");
  EXPECT_TRUE(models[0].capabilities.sky_irradiance);
  EXPECT_GT(models[0].capabilities.max_sun_zenith_deg, 80);
  // Preetham answers no sun below the horizon, so it declares no dark sun zenith (null).
  EXPECT_FALSE(models[0].capabilities.dark_beyond_sun_zenith_deg.has_value());
  EXPECT_TRUE(std::any_of(models[0].parameters.begin(), models[0].parameters.end(),
                          [](const ModelParameterInfo& p) { return p.name == "turbidity"; }));
  EXPECT_TRUE(client().healthy());
  EXPECT_EQ(client().readiness(), "ready");
}

TEST_F(SkyClient, SunFromPlaceAndTime) {
  SunRequest request;
  request.place_time.latitude = "42.444";
  request.place_time.longitude = "-76.5";
  request.place_time.time = "2013-05-27T12:00:00-04:00";
  const SunPosition sun = client().sun(request);
  EXPECT_GT(sun.zenith_deg, 20);
  EXPECT_LT(sun.zenith_deg, 30);
  EXPECT_GT(sun.azimuth_deg, 90);
  EXPECT_LT(sun.azimuth_deg, 180);
  EXPECT_EQ(sun.day, "normal");
  ASSERT_TRUE(sun.sunrise.has_value());
}

TEST_F(SkyClient, RadianceOfOneViewAndOfABatchAgree) {
  RadianceRequest one = sky(RadianceRequest{});
  one.view = {60, 10};
  const RadianceResult single = client().radiance(one);
  EXPECT_EQ(single.model, "preetham");
  EXPECT_EQ(single.unit, "W/(m2.sr.nm)");
  EXPECT_EQ(single.grid, "bins");
  EXPECT_EQ(single.sun.source, "given");
  EXPECT_EQ(single.wavelengths_nm.size(), 40u);
  ASSERT_EQ(single.samples.size(), 1u);
  EXPECT_EQ(single.samples[0].radiance_w_m2_sr_nm.size(), 40u);

  RadianceBatchRequest batch = sky(RadianceBatchRequest{});
  batch.views = {{30, 200}, {60, 10}, {80, 100}};
  const RadianceResult answered = client().radiance(batch);
  ASSERT_EQ(answered.samples.size(), 3u);
  EXPECT_DOUBLE_EQ(answered.samples[1].view.zenith_deg, 60);
  EXPECT_DOUBLE_EQ(answered.samples[1].view.azimuth_deg, 10);
  for (std::size_t w = 0; w < 40; ++w)
    EXPECT_DOUBLE_EQ(answered.samples[1].radiance_w_m2_sr_nm[w],
                     single.samples[0].radiance_w_m2_sr_nm[w]);
}

TEST_F(SkyClient, RadianceAtChosenWavelengthsAndWithModelParameters) {
  RadianceRequest request = sky(RadianceRequest{});
  request.view = {50, 300};
  request.wavelengths_nm = {450, 550.5, 650};
  const RadianceResult clear = client().radiance(request);
  EXPECT_EQ(clear.grid, "points");
  ASSERT_EQ(clear.wavelengths_nm, (std::vector<double>{450, 550.5, 650}));
  request.parameters["turbidity"] = 6.0;
  const RadianceResult hazy = client().radiance(request);
  ASSERT_EQ(hazy.samples.size(), 1u);
  EXPECT_NE(hazy.samples[0].radiance_w_m2_sr_nm[0], clear.samples[0].radiance_w_m2_sr_nm[0]);
}

TEST_F(SkyClient, IrradianceOnATiltedPlane) {
  IrradianceRequest request = sky(IrradianceRequest{});
  request.tilt_deg = 30;
  request.surface_azimuth_deg = 180;
  request.spectral = true;
  const IrradianceResult result = client().irradiance(request);
  EXPECT_DOUBLE_EQ(result.tilt_deg, 30);
  ASSERT_TRUE(result.global.has_value());
  ASSERT_TRUE(result.diffuse.has_value());
  EXPECT_GT(result.global->irradiance_w_m2, 0);
  EXPECT_GT(result.global->illuminance_lx, 0);
  EXPECT_EQ(result.global->spectral_w_m2_nm.size(), result.wavelengths_nm.size());
  EXPECT_FALSE(result.wavelengths_nm.empty());
  EXPECT_EQ(result.global->model_range_irradiance_w_m2, result.global->irradiance_w_m2);
  // The analytic test model has no aerosols to continue: no broadband figure, a reason.
  request.precipitable_water_cm = 2.0;
  request.ozone_atm_cm = 0.3;
  const IrradianceResult absorbed = client().irradiance(request);
  EXPECT_FALSE(absorbed.global->broadband_irradiance_w_m2.has_value());
  ASSERT_TRUE(absorbed.broadband_unavailable.has_value());
  EXPECT_FALSE(absorbed.broadband_unavailable->empty());
}

TEST_F(SkyClient, IrradianceWithTheGroundsReflection) {
  IrradianceRequest wall = sky(IrradianceRequest{});
  wall.tilt_deg = 90;
  wall.ground_albedo = 0.3;
  const IrradianceResult with_ground = client().irradiance(wall);
  const IrradianceResult flat = client().irradiance(sky(IrradianceRequest{}));
  ASSERT_TRUE(with_ground.ground_diffuse.has_value());
  ASSERT_TRUE(flat.global.has_value());
  // An isotropic ground on a vertical plane: albedo x global horizontal / 2.
  EXPECT_NEAR(with_ground.ground_diffuse->irradiance_w_m2, 0.3 * flat.global->irradiance_w_m2 / 2,
              1e-9 * flat.global->irradiance_w_m2);
  wall.ground_albedo.reset();
  wall.ground_reflection = "exclude";
  EXPECT_FALSE(client().irradiance(wall).ground_diffuse.has_value());
}

TEST_F(SkyClient, IrradianceSeriesOfADayOnTwoPlanes) {
  IrradianceSeriesRequest request;
  request.model = "preetham";
  request.latitude = "48.85";
  request.longitude = "2.35";
  request.start = "2024-10-27T00:00:00";
  request.end = "2024-10-27T23:00:00";
  request.tz = "Europe/Paris";
  request.planes = {{30, 180}, {90, 90}};
  request.ground_albedo = 0.2;
  const IrradianceSeriesResult series = client().irradiance_series(request);
  // The day clocks go back in Paris has 25 local hours: 00:00 to 23:00 is 24 hours, 25 rows.
  ASSERT_EQ(series.time_utc.size(), 25u);
  ASSERT_EQ(series.time_local.size(), 25u);
  EXPECT_EQ(series.time_local[2], "2024-10-27T02:00:00+02:00");
  EXPECT_EQ(series.time_local[3], "2024-10-27T02:00:00+01:00");
  EXPECT_EQ(series.unanswered_steps, 0);
  // Preetham cannot go broadband: ghi is null (NaN) in every row, its own figure is
  // model_range_ghi.
  for (double x : series.values.at("ghi")) EXPECT_TRUE(std::isnan(x));
  const auto& ghi = series.values.at("model_range_ghi");
  const auto& ground = series.values.at("model_range_poa_ground_diffuse_90_90");
  std::size_t days = 0;
  for (std::size_t i = 0; i < ghi.size(); ++i) {
    if (series.night[i]) {
      EXPECT_EQ(ghi[i], 0.0);
      continue;
    }
    ++days;
    EXPECT_NEAR(ground[i], 0.2 * ghi[i] / 2, 1e-9 * ghi[i]);
  }
  EXPECT_GT(days, 6u);
  EXPECT_TRUE(series.values.count("poa_global_30_180"));

  request.step = "PT1S";
  try {
    client().irradiance_series(request);
    FAIL() << "a day every second was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 413);
    EXPECT_EQ(e.parameter(), "step");
  }
}

TEST_F(SkyClient, RgbOfOneViewAndOfABatchAgree) {
  RgbRequest one = sky(RgbRequest{});
  one.view = {45, 90};
  const RgbResult single = client().rgb(one);
  EXPECT_EQ(single.method, "spectral");
  ASSERT_EQ(single.samples.size(), 1u);
  EXPECT_GT(single.samples[0].luminance_cd_m2, 0);
  EXPECT_GT(single.samples[0].rgb[2], 0);

  RgbBatchRequest batch = sky(RgbBatchRequest{});
  batch.views = {{45, 90}, {10, 0}};
  batch.method = "spectral";
  const RgbResult answered = client().rgb(batch);
  ASSERT_EQ(answered.samples.size(), 2u);
  for (int c = 0; c < 3; ++c)
    EXPECT_DOUBLE_EQ(answered.samples[0].rgb[c], single.samples[0].rgb[c]);
}

TEST_F(SkyClient, SkydomeStreamsAnOpenExrImage) {
  SkydomeRequest request = sky(SkydomeRequest{});
  request.projection = "latlong";
  request.size_px = 64;
  std::ostringstream image;
  const SkydomeDownload download = client().skydome(request, image);
  EXPECT_EQ(download.content_type, "image/x-exr");
  ASSERT_EQ(download.bytes, image.str().size());
  // The OpenEXR magic number 20000630, little-endian (OpenEXR file layout).
  ASSERT_GT(image.str().size(), 4u);
  EXPECT_EQ(image.str().substr(0, 4), std::string("\x76\x2f\x31\x01", 4));

  const auto file = server_->directory() / "sky.exr";
  const SkydomeDownload saved = client().skydome_to_file(request, file);
  EXPECT_EQ(saved.bytes, download.bytes);
  EXPECT_EQ(std::filesystem::file_size(file), download.bytes);
  EXPECT_FALSE(std::filesystem::exists(server_->directory() / "sky.exr.part"));
}

TEST_F(SkyClient, ARefusedSkydomeLeavesNoFile) {
  SkydomeRequest request = sky(SkydomeRequest{});
  request.size_px = 7;
  const auto file = server_->directory() / "refused.exr";
  try {
    client().skydome_to_file(request, file);
    FAIL() << "size 7 was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 400) << e.what();
    EXPECT_EQ(e.parameter(), "size") << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_FALSE(std::filesystem::exists(server_->directory() / "refused.exr.part"));
}

// docs/quality-levels.md: the optional quality of a request is sent and the answer's stated
// level read back; Preetham has no cost option, so its levels are one setting.
TEST_F(SkyClient, QualityIsSentAndStated) {
  RadianceRequest one = sky(RadianceRequest{});
  one.view = {60, 10};
  const RadianceResult plain = client().radiance(one);
  EXPECT_EQ(plain.quality, "standard");
  one.quality = "draft";
  const RadianceResult draft = client().radiance(one);
  EXPECT_EQ(draft.quality, "draft");
  EXPECT_EQ(draft.served_quality, "draft");
  EXPECT_EQ(draft.samples[0].radiance_w_m2_sr_nm, plain.samples[0].radiance_w_m2_sr_nm);
  RgbBatchRequest batch = sky(RgbBatchRequest{});
  batch.views = {{30, 200}};
  batch.quality = "reference";
  EXPECT_EQ(client().rgb(batch).quality, "reference");
  IrradianceRequest plane = sky(IrradianceRequest{});
  plane.quality = "draft";
  EXPECT_EQ(client().irradiance(plane).served_quality, "draft");
  one.quality = "best";
  try {
    client().radiance(one);
    ADD_FAILURE() << "quality=best was answered";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "quality");
  }
}

TEST_F(SkyClient, RefusalsAreErrorsNamingTheParameter) {
  RadianceRequest request = sky(RadianceRequest{});
  request.view = {60, 10};
  request.parameters["colour"] = std::string("blue");
  try {
    client().radiance(request);
    FAIL() << "an unknown parameter was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.code(), "unknown_parameter");
    EXPECT_EQ(e.parameter(), "colour");
    EXPECT_FALSE(e.message().empty());
  }

  RadianceBatchRequest batch = sky(RadianceBatchRequest{});
  batch.views = {{10, 10}, {200, 5}};
  try {
    client().radiance(batch);
    FAIL() << "a view at zenith 200 was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "views[1]");
  }

  RgbRequest unknown = sky(RgbRequest{});
  unknown.model = "nope";
  try {
    client().rgb(unknown);
    FAIL() << "an unknown model was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 404);
    EXPECT_EQ(e.code(), "unknown_model");
    EXPECT_EQ(e.parameter(), "model");
  }
}

TEST_F(SkyClient, NoServerIsAConnectionError) {
  ClientOptions options;
  // A port nothing listens on: the server's, once it is closed, is not knowable here, so a
  // privileged port that tests never serve.
  options.base_url = "http://127.0.0.1:9";
  options.connect_timeout_s = 5;
  try {
    Client(options).models();
    FAIL() << "port 9 answered";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 0);
    EXPECT_EQ(e.code(), "connection");
  }
}

// GET /v1/skypatches: Tregenza's 145 patches and the ground in Radiance's order, the separate
// sun, and the luminance output one number per patch; a bad scheme is an Error naming it.
TEST_F(SkyClient, SkyPatchesInRadiancesOrder) {
  SkyPatchesRequest request;
  request.model = "preetham";
  request.sun = SunAngles{30, 135};
  request.output = "luminance";
  const SkyPatchesResult vector = client().sky_patches(request);
  EXPECT_EQ(vector.scheme, "tregenza");
  EXPECT_EQ(vector.output, "luminance");
  ASSERT_EQ(vector.patches.size(), 146u);
  double solid_angle_sr = 0;
  for (std::size_t k = 0; k < vector.patches.size(); ++k) {
    EXPECT_EQ(vector.patches[k].patch, static_cast<int>(k));
    ASSERT_EQ(vector.patches[k].value.size(), 1u);
    EXPECT_GE(vector.patches[k].value[0], 0.0);
    if (k > 0) solid_angle_sr += vector.patches[k].solid_angle_sr;
  }
  EXPECT_NEAR(solid_angle_sr, 2.0 * 3.14159265358979, 1e-9);  // the sky hemisphere
  ASSERT_TRUE(vector.sun_source.has_value());
  EXPECT_NEAR(vector.sun_source->altitude_deg, 60.0, 1e-9);
  EXPECT_GT(vector.sun_source->value[0], vector.patches[1].value[0]);

  request.output = "spectral";
  request.scheme = "reinhart";
  request.mf = 2;
  request.wavelengths_nm = {450, 550};
  const SkyPatchesResult spectral = client().sky_patches(request);
  EXPECT_EQ(spectral.mf, 2);
  EXPECT_EQ(spectral.patches.size(), 578u);
  EXPECT_EQ(spectral.wavelengths_nm, (std::vector<double>{450, 550}));
  EXPECT_EQ(spectral.patches[10].value.size(), 2u);

  request.scheme = "klems";
  try {
    client().sky_patches(request);
    FAIL() << "an unknown scheme was answered";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "scheme");
  }
}

// GET /v1/skypatches with start: one column per hourly step, night columns zero, the values
// patch-major with their components; the step's sun as its own source by day.
TEST_F(SkyClient, SkyMatrixHasOneColumnPerStep) {
  SkyMatrixRequest request;
  request.model = "preetham";
  request.latitude = "42.444";
  request.longitude = "-76.5";
  request.start = "2013-05-27T03:00:00-04:00";
  request.end = "2013-05-27T12:00:00-04:00";
  request.output = "rgb";
  const SkyMatrixResult matrix = client().sky_matrix(request);
  EXPECT_EQ(matrix.model, "preetham");
  EXPECT_EQ(matrix.output, "rgb");
  ASSERT_EQ(matrix.components, 3u);
  ASSERT_EQ(matrix.patches.size(), 146u);
  ASSERT_EQ(matrix.steps.size(), 10u);  // 03:00 to 12:00 hourly
  ASSERT_EQ(matrix.values.size(), 146u * 10u * 3u);
  EXPECT_FALSE(matrix.fit.has_value());
  EXPECT_TRUE(matrix.steps.front().night);  // 03:00 EDT in May: the sun is down
  EXPECT_FALSE(matrix.steps.back().night);
  EXPECT_EQ(matrix.steps.back().time_utc, "2013-05-27T16:00:00Z");
  EXPECT_TRUE(matrix.steps.back().sun_value.has_value());
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(matrix.value(10, 0, c), 0.0);  // night: a column of zeros
    EXPECT_GT(matrix.value(10, 9, c), 0.0);  // noon: the sky is lit
  }
  // The noon column is the sky vector of that instant.
  SkyPatchesRequest noon;
  noon.model = "preetham";
  noon.place_time.emplace();
  noon.place_time->latitude = "42.444";
  noon.place_time->longitude = "-76.5";
  noon.place_time->time = "2013-05-27T12:00:00-04:00";
  noon.output = "rgb";
  const SkyPatchesResult vector = client().sky_patches(noon);
  ASSERT_EQ(vector.patches.size(), 146u);
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_NEAR(matrix.value(10, 9, c), vector.patches[10].value[c],
                1e-6 * vector.patches[10].value[c]);

  request.step = "PT0S";
  try {
    client().sky_matrix(request);
    FAIL() << "a zero step was answered";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "step");
  }
}

}  // namespace
}  // namespace clearsky::client
