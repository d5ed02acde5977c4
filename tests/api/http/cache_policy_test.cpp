// Cache headers (api/http/cache_policy.h): the policy's Cache-Control, a strong tag that is a
// hash of the body, 304 for a GET naming it (weak or strong, in a list, or *), never for a
// POST; errors and handler-set Cache-Control are left alone; streamed bodies get no tag.
#include "api/http/cache_policy.h"

#include <gtest/gtest.h>
#include <xxhash.h>

#include <cstdio>
#include <string>
#include <vector>

namespace clearsky::api {
namespace {

ApiResponse answer(const std::string& body, int status = 200) {
  ApiResponse r;
  r.status = status;
  r.body = body;
  return r;
}

ApiRequest get(std::string if_none_match = "") {
  ApiRequest r;
  r.method = "GET";
  r.path = "/v1/models";
  if (!if_none_match.empty()) r.headers.emplace_back("if-none-match", if_none_match);
  return r;
}

TEST(CachePolicy, StrongTagIsAHashOfTheBody) {
  EXPECT_EQ(strong_etag("abc"), strong_etag("abc"));
  EXPECT_NE(strong_etag("abc"), strong_etag("abd"));
  EXPECT_EQ(strong_etag("").size(), 34u);  // 32 hex digits in quotes
  EXPECT_EQ(strong_etag("abc").front(), '"');
}

// The tag is XXH3-128 of the body, high then low 64 bits as 32 lowercase hex digits: the same
// body keeps its tag across server versions, so clients' cached tags stay valid.
TEST(CachePolicy, StrongTagIsTheHexOfXxh3_128) {
  for (const std::string& body : std::vector<std::string>{"", "abc", std::string(1325, 'x')}) {
    const XXH128_hash_t hash = XXH3_128bits(body.data(), body.size());
    char expected[40];
    std::snprintf(expected, sizeof expected, "\"%016llx%016llx\"",
                  static_cast<unsigned long long>(hash.high64),
                  static_cast<unsigned long long>(hash.low64));
    EXPECT_EQ(strong_etag(body), expected) << body.size();
  }
}

TEST(CachePolicy, IfNoneMatchUsesTheWeakComparison) {
  const std::string tag = strong_etag("x");
  EXPECT_TRUE(if_none_match(tag, tag));
  EXPECT_TRUE(if_none_match("W/" + tag, tag));
  EXPECT_TRUE(if_none_match("\"a\", " + tag + " ,\"b\"", tag));
  EXPECT_TRUE(if_none_match("*", tag));
  EXPECT_FALSE(if_none_match("\"a\", \"b\"", tag));
  EXPECT_FALSE(if_none_match("", tag));
}

TEST(CachePolicy, PoliciesSetCacheControlAndTags) {
  ApiResponse stored = answer("{}");
  apply_caching(Caching::deterministic, get(), stored);
  EXPECT_EQ(stored.header("Cache-Control"), "public, max-age=86400");
  EXPECT_EQ(stored.header("ETag"), strong_etag("{}"));

  ApiResponse revalidated = answer("{}");
  apply_caching(Caching::revalidate, get(), revalidated);
  EXPECT_EQ(revalidated.header("Cache-Control"), "no-cache");
  EXPECT_TRUE(revalidated.header("ETag"));

  ApiResponse data = answer("[]");
  apply_caching(Caching::no_store, get(), data);
  EXPECT_EQ(data.header("Cache-Control"), "no-store");
  EXPECT_FALSE(data.header("ETag"));

  ApiResponse error = answer("{\"error\":{}}", 503);
  apply_caching(Caching::deterministic, get(), error);
  EXPECT_EQ(error.header("Cache-Control"), "no-store");
  EXPECT_FALSE(error.header("ETag"));

  ApiResponse chosen = answer("{}");
  chosen.headers.emplace_back("Cache-Control", "no-store");
  apply_caching(Caching::deterministic, get(), chosen);
  EXPECT_FALSE(chosen.header("ETag"));

  ApiResponse streamed = answer("");
  streamed.stream = [](const ByteSink&) { return true; };
  apply_caching(Caching::deterministic, get(), streamed);
  EXPECT_EQ(streamed.header("Cache-Control"), "public, max-age=86400");
  EXPECT_FALSE(streamed.header("ETag"));
}

TEST(CachePolicy, NotModifiedForAGetNamingTheTag) {
  ApiResponse same = answer("{\"a\":1}");
  apply_caching(Caching::revalidate, get(strong_etag("{\"a\":1}")), same);
  EXPECT_EQ(same.status, 304);
  EXPECT_TRUE(same.body.empty());
  EXPECT_EQ(same.header("ETag"), strong_etag("{\"a\":1}"));
  EXPECT_EQ(same.header("Cache-Control"), "no-cache");

  ApiResponse changed = answer("{\"a\":2}");
  apply_caching(Caching::revalidate, get(strong_etag("{\"a\":1}")), changed);
  EXPECT_EQ(changed.status, 200);
  EXPECT_EQ(changed.body, "{\"a\":2}");

  ApiRequest post = get(strong_etag("{}"));
  post.method = "POST";
  ApiResponse posted = answer("{}");
  apply_caching(Caching::revalidate, post, posted);
  EXPECT_EQ(posted.status, 200);
}

}  // namespace
}  // namespace clearsky::api
