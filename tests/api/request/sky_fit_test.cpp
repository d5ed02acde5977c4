// The fit parameter of the sky endpoints (api/request/sky_fit.h, docs/fits.md "Using a fit")
// without a database: a lookup that answers fixed fits stands for the fits table
// (tests/api/fits/stored_fit_values_test.cpp has the real one). The fit's values reach the
// configuration exactly as the same values given explicitly, a parameter given too is refused
// naming it, a value out of the descriptor's range is refused naming it and the fit, a parameter
// the model does not list is a 409 naming fit, and the answer's member and headers say which fit.
#include <gtest/gtest.h>

#include <limits>

#include "api/request/sky_request.h"
#include "models/registry.h"

namespace clearsky::api {
namespace {

const ModelDescriptor& preetham() { return *find_model("preetham")->descriptor; }

// A lookup answering the fit with these values for any reference, and counting its calls.
struct FixedFits {
  AppliedFit fit;
  int calls = 0;
  FitLookup lookup() {
    return [this](const std::string& reference, const ModelDescriptor& descriptor) {
      ++calls;
      EXPECT_EQ(descriptor.id, "preetham");
      AppliedFit out = fit;
      out.latest = reference == "latest";
      return out;
    };
  }
};

AppliedFit turbidity_fit(double turbidity) {
  return AppliedFit{7, "preetham", "1", "kider2014", false, {{"turbidity", turbidity}}};
}

Parameters parameters(std::vector<std::pair<std::string, std::string>> pairs) {
  Parameters p("GET /v1/radiance");
  for (auto& [name, value] : pairs) p.add(name, value);
  return p;
}

int status_of(const std::function<void()>& f, std::string* parameter = nullptr,
              std::string* message = nullptr) {
  try {
    f();
  } catch (const ApiError& e) {
    if (parameter) *parameter = e.parameter();
    if (message) *message = e.what();
    return e.status();
  }
  return 0;
}

TEST(SkyFit, TheFitsValuesConfigureTheModelAsTheSameValuesGivenExplicitly) {
  // A value with a long binary expansion: the text written must parse back to the same double.
  const double turbidity = 2.3480000000000003;
  FixedFits fits{turbidity_fit(turbidity)};
  Parameters by_fit = parameters({{"fit", "7"}});
  const SkyConfig fitted = parse_sky_config(by_fit, preetham(), fits.lookup());
  by_fit.reject_unused();
  Parameters explicit_values = parameters({{"turbidity", round_trip_text(turbidity)}});
  const SkyConfig given = parse_sky_config(explicit_values, preetham(), fits.lookup());
  EXPECT_EQ(fitted.config.atmosphere.turbidity, turbidity);
  EXPECT_EQ(fitted.config.canonical_string(), given.config.canonical_string());
  ASSERT_TRUE(fitted.fit.has_value());
  EXPECT_EQ(fitted.fit->id, 7);
  EXPECT_FALSE(given.fit.has_value());
  EXPECT_EQ(fits.calls, 1);  // only the request that names a fit looks one up
}

TEST(SkyFit, RoundTripTextParsesBackToTheSameDouble) {
  for (const double x : {0.0, 1.0, 2.3480000000000003, 0.1, 1.0 / 3.0, 6.02214076e23,
                         std::numeric_limits<double>::denorm_min()})
    EXPECT_EQ(number_value("x", round_trip_text(x)), x) << round_trip_text(x);
  EXPECT_EQ(round_trip_text(2.5), "2.5");
}

TEST(SkyFit, AParameterGivenTogetherWithTheFitThatSetsItIsRefusedNamingIt) {
  FixedFits fits{turbidity_fit(3.0)};
  Parameters p = parameters({{"fit", "7"}, {"turbidity", "3"}});
  std::string parameter, message;
  EXPECT_EQ(
      status_of([&] { parse_sky_config(p, preetham(), fits.lookup()); }, &parameter, &message),
      400);
  EXPECT_EQ(parameter, "turbidity");
  EXPECT_NE(message.find("fit 7 sets it"), std::string::npos) << message;
}

TEST(SkyFit, ParametersTheFitDoesNotSetAreGivenAsUsual) {
  AppliedFit fit = turbidity_fit(3.0);
  FixedFits fits{fit};
  Parameters p = parameters({{"fit", "7"}, {"clamp_negative_fit", "1"}});
  const SkyConfig sky = parse_sky_config(p, preetham(), fits.lookup());
  p.reject_unused();
  EXPECT_EQ(sky.config.atmosphere.turbidity, 3.0);
  EXPECT_EQ(sky.config.options.at("clamp_negative_fit"), 1.0);
}

TEST(SkyFit, AValueOutsideTheDescriptorsRangeIsRefusedNamingItAndTheFit) {
  // Preetham's turbidity starts at 2 (its descriptor); a fit stored with 1.5 (by a model
  // version whose range was wider) is refused as the same value given would be.
  FixedFits fits{turbidity_fit(1.5)};
  Parameters p = parameters({{"fit", "7"}});
  std::string parameter, message;
  EXPECT_EQ(
      status_of([&] { parse_sky_config(p, preetham(), fits.lookup()); }, &parameter, &message),
      400);
  EXPECT_EQ(parameter, "turbidity");
  EXPECT_NE(message.find("(the value of fit 7)"), std::string::npos) << message;
}

TEST(SkyFit, AFitOfAParameterTheModelDoesNotListIsAConflictNamingFit) {
  FixedFits fits{AppliedFit{8, "preetham", "0", "d", false, {{"alpha", 1.2}}}};
  Parameters p = parameters({{"fit", "8"}});
  std::string parameter;
  EXPECT_EQ(status_of([&] { parse_sky_config(p, preetham(), fits.lookup()); }, &parameter), 409);
  EXPECT_EQ(parameter, "fit");
}

TEST(SkyFit, TheLookupsRefusalReachesTheClientAsItIs) {
  const FitLookup refusing = [](const std::string&, const ModelDescriptor&) -> AppliedFit {
    throw ApiError::about(404, "unknown_fit", "fit", "no fit 9");
  };
  Parameters p = parameters({{"fit", "9"}});
  std::string parameter;
  EXPECT_EQ(status_of([&] { parse_sky_config(p, preetham(), refusing); }, &parameter), 404);
  EXPECT_EQ(parameter, "fit");
}

TEST(SkyFit, TheAnswerSaysWhichFitAndValuesItUsed) {
  const AppliedFit fit{12, "hosek", "2", "kider2014", false, {{"turbidity", 2.875}, {"albedo", 0}}};
  nlohmann::json body = nlohmann::json::object();
  add_fit_member(body, fit);
  EXPECT_EQ(body["fit"], nlohmann::json({{"id", 12},
                                         {"model", "hosek"},
                                         {"model_version", "2"},
                                         {"dataset", "kider2014"},
                                         {"parameters", {{"turbidity", 2.875}, {"albedo", 0.0}}}}));
  std::vector<std::pair<std::string, std::string>> headers;
  add_fit_headers(headers, fit);
  ASSERT_EQ(headers.size(), 1u);
  EXPECT_EQ(headers[0], std::make_pair(std::string("Clearsky-Fit"),
                                       std::string("12; turbidity=2.875; albedo=0")));

  // Without a fit nothing is added: answers without fit= are as before.
  nlohmann::json plain = nlohmann::json::object();
  add_fit_member(plain, std::nullopt);
  EXPECT_TRUE(plain.empty());
  std::vector<std::pair<std::string, std::string>> none;
  add_fit_headers(none, std::nullopt);
  EXPECT_TRUE(none.empty());
}

TEST(SkyFit, LatestIsNeverCachedAndKeepsOneCacheControl) {
  AppliedFit latest = turbidity_fit(3.0);
  latest.latest = true;
  std::vector<std::pair<std::string, std::string>> headers;
  add_fit_headers(headers, latest);
  EXPECT_EQ(headers.back(), std::make_pair(std::string("Cache-Control"), std::string("no-store")));
  // An answer already uncacheable (a draft served for standard) keeps its one header.
  std::vector<std::pair<std::string, std::string>> draft = {{"Cache-Control", "no-store"}};
  add_fit_headers(draft, latest);
  EXPECT_EQ(draft.size(), 2u);
}

}  // namespace
}  // namespace clearsky::api
