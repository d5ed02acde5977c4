// Wavelengths outside a model's declared spectral range (its descriptor's min_wavelength_nm ..
// max_wavelength_nm) are a 422 naming `wavelengths`, decided before any table is built: for
// every registered model, on the endpoints that take wavelengths (radiance, the spectral
// skydome). A build on such a grid used to fail inside the precomputation (500
// precomputation_failed).
#include <gtest/gtest.h>

#include <atomic>
#include <sstream>

#include "api/handlers/handlers.h"
#include "api/skydome/skydome_render.h"
#include "models/registry.h"
#include "tests/support/synchronous_provider.h"

namespace clearsky::api {
namespace {

ApiRequest get(const std::string& path, const NameValues& query) {
  ApiRequest r;
  r.method = "GET";
  r.path = path;
  r.query = query;
  return r;
}

// The real factories, counting the builds asked for (there must be none).
class CountingProvider final : public ModelProvider {
 public:
  std::span<const ModelFactory> factories() const override { return inner_.factories(); }
  using ModelProvider::model;
  std::shared_ptr<const SkyModel> model(const ModelFactory& factory, const ModelConfig& config,
                                        const ModelRequester&) const override {
    ++builds;
    return inner_.model(factory, config);
  }
  ModelState default_state(const ModelFactory& factory) const override {
    return inner_.default_state(factory);
  }
  mutable std::atomic<int> builds{0};

 private:
  clearsky::testing::SynchronousProvider inner_{
      {registered_models().begin(), registered_models().end()}};
};

std::string text(double nm) {
  std::ostringstream out;
  out.precision(17);
  out << nm;
  return out.str();
}

TEST(WavelengthRange, OutsideEveryModelsDeclaredRangeIs422BeforeAnyBuild) {
  CountingProvider provider;
  const ApiContext context{provider, Limits{}};
  for (const ModelFactory& factory : registered_models()) {
    const ModelDescriptor& d = *factory.descriptor;
    std::vector<std::string> outside = {"10", "100000", text(d.min_wavelength_nm - 0.5),
                                        text(d.max_wavelength_nm + 0.5), "400," + text(1e5)};
    if (d.min_wavelength_nm > 285.0) outside.push_back("285");
    if (d.max_wavelength_nm < 4000.0) outside.push_back("4000");
    for (const std::string& wavelengths : outside) {
      SCOPED_TRACE(d.id + " wavelengths=" + wavelengths);
      const NameValues sky = {{"model", d.id},
                              {"sun_zenith", "30"},
                              {"sun_azimuth", "0"},
                              {"wavelengths", wavelengths}};
      NameValues view = sky;
      view.insert(view.end(), {{"view_zenith", "10"}, {"view_azimuth", "0"}});
      NameValues image = sky;
      image.insert(image.end(), {{"channels", "spectral"}, {"size", "8"}});
      for (const auto& attempt :
           {std::function<void()>([&] { radiance(context, get("/v1/radiance", view)); }),
            std::function<void()>([&] { prepare_skydome(context, get("/v1/skydome", image)); })}) {
        try {
          attempt();
          ADD_FAILURE() << "answered";
        } catch (const ApiError& e) {
          EXPECT_EQ(e.status(), 422) << e.what();
          EXPECT_EQ(e.parameter(), "wavelengths") << e.what();
        }
      }
    }
  }
  EXPECT_EQ(provider.builds.load(), 0);
}

}  // namespace
}  // namespace clearsky::api
