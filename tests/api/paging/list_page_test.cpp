// Tests of the list pagination parameters, cursors and Link header (api/paging/list_page.h).
#include "api/paging/list_page.h"

#include <gtest/gtest.h>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

PageRequest page_of(const QueryParameters& pairs) {
  Parameters query("GET /test");
  for (const auto& [name, value] : pairs) query.add(name, value);
  const PageRequest page = parse_page_request(query);
  query.reject_unused();
  return page;
}

std::string refused_parameter(const std::function<void()>& call) {
  try {
    call();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    return e.parameter();
  }
  return "";
}

TEST(ListPage, LimitAndCursorAreChecked) {
  EXPECT_EQ(page_of({}).limit, 100);
  EXPECT_FALSE(page_of({}).cursor);
  EXPECT_EQ(page_of({{"limit", "1"}}).limit, 1);
  EXPECT_EQ(page_of({{"limit", "1000"}, {"cursor", "ab"}}).limit, 1000);
  EXPECT_EQ(page_of({{"cursor", "ab"}}).cursor, "ab");
  for (const char* bad : {"0", "1001", "-1", "ten", "5x", ""})
    EXPECT_EQ(refused_parameter([&] { page_of({{"limit", bad}}); }), "limit") << bad;
  EXPECT_EQ(refused_parameter([&] { page_of({{"cursor", ""}}); }), "cursor");
}

TEST(ListPage, CursorsRoundTripAndAreOfOneKind) {
  EXPECT_EQ(id_from_cursor(id_cursor(42)), 42);
  EXPECT_EQ(name_from_cursor(name_cursor("kider 2014/ä")), "kider 2014/ä");
  EXPECT_EQ(refused_parameter([] { id_from_cursor(name_cursor("a")); }), "cursor");
  EXPECT_EQ(refused_parameter([] { name_from_cursor(id_cursor(3)); }), "cursor");
  for (const char* bad : {"zz", "abc", "69"})  // not hex, odd, an empty id
    EXPECT_EQ(refused_parameter([&] { id_from_cursor(bad); }), "cursor") << bad;
  // Safe in a URL as it is.
  for (char c : name_cursor("a b&c=d"))
    EXPECT_TRUE((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')) << c;
}

TEST(ListPage, TheResponseIsTheArrayWithALinkWhenMoreFollow) {
  ApiRequest request;
  request.path = "/v1/jobs";
  request.query = {{"limit", "1"}};
  ListPage page;
  page.items.push_back(1);
  page.limit = 1;
  EXPECT_FALSE(list_page_response(request, page).header("Link"));
  EXPECT_EQ(list_page_response(request, page).body, "[1]");
  page.next_cursor = id_cursor(1);
  EXPECT_EQ(list_page_response(request, page).header("Link"),
            "</v1/jobs?limit=1&cursor=" + id_cursor(1) + ">; rel=\"next\"");
}

TEST(ListPage, NextLinkKeepsTheFiltersAndReplacesThePage) {
  EXPECT_EQ(next_page_link(
                "/v1/evaluations",
                {{"model", "preetham"}, {"cursor", "old"}, {"since", "2026-01-01T00:00+01:00"}}, 2,
                "6933"),
            "</v1/evaluations?model=preetham&since=2026-01-01T00%3A00%2B01%3A00&limit=2&cursor="
            "6933>; rel=\"next\"");
  EXPECT_EQ(next_page_link("/v1/jobs", {}, 100, "6e61"),
            "</v1/jobs?limit=100&cursor=6e61>; rel=\"next\"");
}

}  // namespace
}  // namespace clearsky::api
