// The tabulated sky irradiance of tilted planes (api/irradiance/plane_sky_irradiance_table.h)
// against the model's own sky_irradiance at suns between the nodes, for the fitted models
// (cheap to build): the interpolation error the series' "table" mode adds.
#include "api/irradiance/plane_sky_irradiance_table.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/core/numeric.h"
#include "models/registry.h"

namespace clearsky::api {
namespace {

std::shared_ptr<const SkyModel> build(const std::string& id) {
  for (const ModelFactory& factory : registered_models()) {
    if (factory.descriptor->id == id) {
      ModelConfig config;
      config.wavelengths = WavelengthGrid::points({450.0, 550.0, 650.0});
      if (id == "preetham" || id == "hosek") config.options["clamp_negative_fit"] = 1;
      return factory.create(config, {});
    }
  }
  ADD_FAILURE() << "no model " << id;
  return nullptr;
}

// The largest relative difference (to the plane's irradiance at 550 nm) over suns between the
// nodes, for the sun up to 85 degrees from the zenith.
double worst_relative_error(const SkyModel& model, const PlaneOrientation& plane) {
  const PlaneSkyIrradianceTable table(model, Viewpoint{}, plane);
  double worst = 0;
  for (double zenith_deg = 1.0; zenith_deg <= 85.0; zenith_deg += 7.0) {
    for (double azimuth_deg = 3.0; azimuth_deg < 360.0; azimuth_deg += 29.0) {
      const SunPosition sun{degrees_to_radians(zenith_deg), degrees_to_radians(azimuth_deg)};
      const auto state = model.prepare_sun(sun);
      const SpectralSample exact = model.sky_irradiance(*state, Viewpoint{}, plane);
      const auto tabulated = table.at(sun);
      EXPECT_TRUE(tabulated.has_value()) << zenith_deg << " " << azimuth_deg;
      if (!tabulated || exact.status != SampleStatus::ok) continue;
      worst = std::max(worst, std::abs((*tabulated)[1] - exact.value[1]) / exact.value[1]);
    }
  }
  return worst;
}

TEST(PlaneSkyIrradianceTable, InterpolatesTheModelsOwnValues) {
  for (const char* id : {"preetham", "hosek"}) {
    const auto model = build(id);
    ASSERT_TRUE(model);
    for (const auto& [tilt, azimuth] : {std::pair{30.0, 180.0}, {90.0, 180.0}, {90.0, 90.0}}) {
      const double error =
          worst_relative_error(*model, {degrees_to_radians(tilt), degrees_to_radians(azimuth)});
      RecordProperty(std::string(id) + "_" + std::to_string(static_cast<int>(tilt)) + "_" +
                         std::to_string(static_cast<int>(azimuth)),
                     std::to_string(error));
      std::printf("%s tilt %g azimuth %g: worst relative error %.4f\n", id, tilt, azimuth, error);
      EXPECT_LT(error, 0.02) << id << " " << tilt << " " << azimuth;
    }
  }
}

TEST(PlaneSkyIrradianceTable, ANodeIsTheModelsValue) {
  const auto model = build("preetham");
  ASSERT_TRUE(model);
  const PlaneOrientation plane{degrees_to_radians(60.0), degrees_to_radians(200.0)};
  const PlaneSkyIrradianceTable table(*model, Viewpoint{}, plane);
  const SunPosition sun{degrees_to_radians(40.0), degrees_to_radians(200.0 - 30.0)};
  const auto state = model->prepare_sun(sun);
  const SpectralSample exact = model->sky_irradiance(*state, Viewpoint{}, plane);
  const auto tabulated = table.at(sun);
  ASSERT_TRUE(tabulated.has_value());
  for (std::size_t w = 0; w < 3; ++w)
    EXPECT_NEAR((*tabulated)[w], exact.value[w], 1e-9 * exact.value[w]);
}

}  // namespace
}  // namespace clearsky::api
