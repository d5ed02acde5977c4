// CORS (api/http/cors.h): nothing without configured origins; an allowed origin gets
// Access-Control-Allow-Origin and the exposed headers, another gets none; every answer varies
// by Origin; a preflight from an allowed origin gets the path's methods, the request headers
// and the max-age; "*" allows any origin.
#include "api/http/cors.h"

#include <gtest/gtest.h>

namespace clearsky::api {
namespace {

ApiRequest preflight(const std::string& origin) {
  ApiRequest r;
  r.method = "OPTIONS";
  r.path = "/v1/jobs";
  r.headers = {{"Origin", origin}, {"Access-Control-Request-Method", "POST"}};
  return r;
}

TEST(Cors, NoOriginsNoHeaders) {
  const CorsPolicy none;
  ApiResponse r;
  none.add_headers("https://a.example", r);
  EXPECT_TRUE(r.headers.empty());
  const ApiResponse options = none.options(preflight("https://a.example"), "GET, POST, OPTIONS");
  EXPECT_EQ(options.status, 204);
  EXPECT_EQ(options.header("Allow"), "GET, POST, OPTIONS");
  EXPECT_FALSE(options.header("Access-Control-Allow-Origin"));
  EXPECT_FALSE(options.header("Access-Control-Allow-Methods"));
}

TEST(Cors, AllowedOriginsOnly) {
  const CorsPolicy cors({"https://a.example"});
  ApiResponse allowed;
  cors.add_headers("https://a.example", allowed);
  EXPECT_EQ(allowed.header("Access-Control-Allow-Origin"), "https://a.example");
  EXPECT_EQ(allowed.header("Vary"), "Origin");
  EXPECT_NE(allowed.header("Access-Control-Expose-Headers")->find("ETag"), std::string::npos);
  // The stored fit an answer used (docs/fits.md "Using a fit"), readable by a page.
  EXPECT_NE(allowed.header("Access-Control-Expose-Headers")->find("Clearsky-Fit"),
            std::string::npos);

  ApiResponse other;
  cors.add_headers("https://b.example", other);
  EXPECT_FALSE(other.header("Access-Control-Allow-Origin"));
  EXPECT_EQ(other.header("Vary"), "Origin");

  const ApiResponse ok = cors.options(preflight("https://a.example"), "GET, POST, OPTIONS");
  EXPECT_EQ(ok.status, 204);
  EXPECT_EQ(ok.header("Access-Control-Allow-Origin"), "https://a.example");
  EXPECT_EQ(ok.header("Access-Control-Allow-Methods"), "GET, POST, OPTIONS");
  EXPECT_EQ(ok.header("Access-Control-Allow-Headers"), "Authorization, Content-Type");
  EXPECT_EQ(ok.header("Access-Control-Max-Age"), std::to_string(CorsPolicy::kMaxAgeS));

  // Added once, however often asked.
  ApiResponse twice = ok;
  cors.add_headers("https://a.example", twice);
  EXPECT_EQ(twice.headers.size(), ok.headers.size());

  const ApiResponse refused = cors.options(preflight("https://b.example"), "GET, OPTIONS");
  EXPECT_EQ(refused.status, 204);
  EXPECT_FALSE(refused.header("Access-Control-Allow-Origin"));
  EXPECT_FALSE(refused.header("Access-Control-Allow-Methods"));
}

TEST(Cors, AnyOrigin) {
  const CorsPolicy any({"*"});
  ApiResponse r;
  any.add_headers("https://whoever.example", r);
  EXPECT_EQ(r.header("Access-Control-Allow-Origin"), "*");
  EXPECT_FALSE(r.header("Vary"));
}

}  // namespace
}  // namespace clearsky::api
