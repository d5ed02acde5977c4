// Tests of bearer-token authorisation of writes (server/auth/write_auth.h).
#include "server/auth/write_auth.h"

#include <gtest/gtest.h>

#include "api/error/api_error.h"

namespace clearsky::server {
namespace {

int status_of(const WriteAuthorizer& auth, std::string_view header) {
  try {
    auth.authorize("POST", "/v1/jobs", header, "127.0.0.1");
  } catch (const api::ApiError& e) {
    return e.status();
  }
  return 200;
}

TEST(WriteAuth, ConstantTimeEqual) {
  EXPECT_TRUE(constant_time_equal("secret", "secret"));
  EXPECT_FALSE(constant_time_equal("secret", "secreT"));
  EXPECT_FALSE(constant_time_equal("secret", "secret2"));
  EXPECT_FALSE(constant_time_equal("secret", "secre"));
  EXPECT_FALSE(constant_time_equal("secret", ""));
  // A candidate that repeats the expected text's prefix is still unequal.
  EXPECT_FALSE(constant_time_equal("abab", "ab"));
  EXPECT_TRUE(constant_time_equal("", ""));
}

TEST(WriteAuth, NoTokenDisablesWrites) {
  const WriteAuthorizer none(std::nullopt);
  EXPECT_FALSE(none.writes_enabled());
  EXPECT_EQ(status_of(none, "Bearer anything"), 403);
  EXPECT_EQ(status_of(WriteAuthorizer(std::string()), "Bearer "), 403);
}

TEST(WriteAuth, BearerTokenIsRequiredAndCompared) {
  const WriteAuthorizer auth(std::string("s3cret-token"));
  EXPECT_TRUE(auth.writes_enabled());
  EXPECT_EQ(status_of(auth, "Bearer s3cret-token"), 200);
  EXPECT_EQ(status_of(auth, ""), 401);
  EXPECT_EQ(status_of(auth, "Bearer "), 401);
  EXPECT_EQ(status_of(auth, "Basic s3cret-token"), 401);
  EXPECT_EQ(status_of(auth, "bearer s3cret-token"), 401);
  EXPECT_EQ(status_of(auth, "Bearer s3cret-toke"), 401);
  EXPECT_EQ(status_of(auth, "Bearer s3cret-token "), 401);
}

// A refusal names the header to give, as every error names its parameter.
TEST(WriteAuth, RefusalsNameTheAuthorizationHeader) {
  for (const WriteAuthorizer& auth :
       {WriteAuthorizer(std::string("s3cret-token")), WriteAuthorizer(std::nullopt)}) {
    try {
      auth.authorize("POST", "/v1/jobs", "Bearer wrong", "127.0.0.1");
      ADD_FAILURE() << "authorised";
    } catch (const api::ApiError& e) {
      EXPECT_EQ(e.parameter(), "Authorization") << e.status();
    }
  }
}

TEST(WriteAuth, OptionWinsOverEnvironment) {
  EXPECT_EQ(status_of(WriteAuthorizer::from_option_or_environment("a", "b"), "Bearer a"), 200);
  EXPECT_EQ(status_of(WriteAuthorizer::from_option_or_environment("", "b"), "Bearer b"), 200);
  EXPECT_FALSE(WriteAuthorizer::from_option_or_environment("", nullptr).writes_enabled());
  EXPECT_FALSE(WriteAuthorizer::from_option_or_environment("", "").writes_enabled());
}

}  // namespace
}  // namespace clearsky::server
