// Pagination of the list endpoints (GET /v1/datasets, /v1/imports, /v1/evaluations, /v1/jobs;
// docs/data-api.md "Pagination"): query `limit` (1..1000, default 100) and `cursor` (opaque,
// from the previous page). The body stays a bare JSON array; the next page is announced by
// the header Link: </v1/...?...&limit=N&cursor=C>; rel="next" (RFC 8288), absent on the last
// page. The lists are read by keyset pagination (storage/repositories/keyset_page.h): a cursor
// holds the last key of its page (an id or a name), so pages never shift when rows come or go.
// Thread-safety: pure functions.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/http/api_types.h"
#include "api/request/parameters.h"

namespace clearsky::api {

using QueryParameters = NameValues;

constexpr std::int64_t kDefaultPageLimit = 100;
constexpr std::int64_t kMaxPageLimit = 1000;

struct PageRequest {
  std::int64_t limit = kDefaultPageLimit;
  std::optional<std::string> cursor;
};

// One page of a list: the body's array and, when another page follows, its cursor (for pages
// of `limit`).
struct ListPage {
  nlohmann::ordered_json items = nlohmann::ordered_json::array();
  std::optional<std::string> next_cursor;
  std::int64_t limit = kDefaultPageLimit;
};

// limit and cursor from the query, marked read (400 naming them when invalid).
PageRequest parse_page_request(Parameters& query);

// Cursors of lists keyed by id or by name; reading one of another kind, or text no list
// returned, is a 400 naming "cursor".
std::string id_cursor(std::int64_t id);
std::int64_t id_from_cursor(const std::string& cursor);
std::string name_cursor(const std::string& name);
std::string name_from_cursor(const std::string& cursor);

// The Link header value announcing the next page: path?QUERY&limit=N&cursor=C; rel="next",
// QUERY being the request's other parameters (its filters), percent-encoded.
std::string next_page_link(const std::string& path, const QueryParameters& query,
                           std::int64_t limit, const std::string& cursor);

// The page as the answer to the request: the bare array, with the Link header when another
// page follows.
ApiResponse list_page_response(const ApiRequest& request, const ListPage& page);

}  // namespace clearsky::api
