// check_aerosols_option (api/request/aerosols_option.h) and its two callers: a sky request and an
// evaluation's parameters naming an inversion the installed source does not know are a 404
// unknown_aerosols naming aerosols; a known id and 0 pass.
#include "api/request/aerosols_option.h"

#include <gtest/gtest.h>

#include "api/error/api_error.h"
#include "api/evaluation/evaluations_api.h"
#include "api/request/sky_request.h"
#include "models/measured_aerosols/aerosol_inversion_source.h"
#include "models/measured_aerosols/measured_aerosols.h"

namespace clearsky::api {
namespace {

struct KnowsSeven {
  KnowsSeven() {
    install_aerosol_inversion_source([](std::int64_t id) -> std::optional<std::string> {
      if (id == 7) return std::string("stored");
      return std::nullopt;
    });
  }
  ~KnowsSeven() { install_aerosol_inversion_source({}); }
};

void expect_unknown(const std::function<void()>& f) {
  try {
    f();
    ADD_FAILURE() << "accepted";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 404) << e.what();
    EXPECT_EQ(e.code(), "unknown_aerosols") << e.what();
    EXPECT_EQ(e.parameter(), "aerosols") << e.what();
  }
}

TEST(AerosolsOption, AnIdTheSourceDoesNotKnowIsA404NamingAerosols) {
  const KnowsSeven source;
  EXPECT_NO_THROW(check_aerosols_option("aerosols", 0));
  EXPECT_NO_THROW(check_aerosols_option("aerosols", 7));
  EXPECT_NO_THROW(check_aerosols_option("aod_scale", 8));
  expect_unknown([] { check_aerosols_option("aerosols", 8); });
}

TEST(AerosolsOption, WithoutASourceEveryIdButZeroIsUnknown) {
  EXPECT_NO_THROW(check_aerosols_option("aerosols", 0));
  expect_unknown([] { check_aerosols_option("aerosols", 7); });
}

TEST(AerosolsOption, EvaluationParametersAreChecked) {
  const KnowsSeven source;
  const ModelFactory factory = measured_aerosols_factory();
  const ModelFactory* const models[] = {&factory};
  EXPECT_NO_THROW(parse_evaluation_parameters(nlohmann::json{{"aerosols", 7}}, models));
  expect_unknown([&] { parse_evaluation_parameters(nlohmann::json{{"aerosols", 9}}, models); });
}

TEST(AerosolsOption, SkyRequestsAreChecked) {
  const KnowsSeven source;
  const ModelDescriptor& d = measured_aerosols_descriptor();
  const FitLookup no_fits;
  Parameters known("GET /v1/radiance");
  known.add("aerosols", "7");
  EXPECT_EQ(parse_sky_config(known, d, no_fits).config.options.at("aerosols"), 7.0);
  expect_unknown([&] {
    Parameters unknown("GET /v1/radiance");
    unknown.add("aerosols", "9");
    parse_sky_config(unknown, d, no_fits);
  });
}

}  // namespace
}  // namespace clearsky::api
