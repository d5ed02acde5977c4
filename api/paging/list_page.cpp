// Pagination of the list endpoints (list_page.h).
#include "api/paging/list_page.h"

#include <charconv>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

constexpr char kHex[] = "0123456789abcdef";

// The cursor is the key prefixed by its kind ('i' id, 'n' name), in hexadecimal: opaque, and
// safe in a URL as it is.
std::string encode(char kind, const std::string& key) {
  std::string text = std::string(1, kind) + key;
  std::string out;
  out.reserve(2 * text.size());
  for (unsigned char c : text) {
    out += kHex[c >> 4];
    out += kHex[c & 15];
  }
  return out;
}

std::string decode(char kind, const std::string& cursor) {
  const auto invalid = [] {
    return invalid_parameter("cursor",
                             "not a cursor this list returned (take it from the Link "
                             "header of the previous page)");
  };
  if (cursor.empty() || cursor.size() % 2 != 0) throw invalid();
  std::string text;
  for (std::size_t i = 0; i < cursor.size(); i += 2) {
    unsigned value = 0;
    const auto [end, error] = std::from_chars(cursor.data() + i, cursor.data() + i + 2, value, 16);
    if (error != std::errc() || end != cursor.data() + i + 2) throw invalid();
    text += static_cast<char>(value);
  }
  if (text.empty() || text[0] != kind) throw invalid();
  return text.substr(1);
}

// RFC 3986 percent-encoding of a query component (unreserved characters kept).
std::string percent_encoded(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
        c == '.' || c == '_' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += "0123456789ABCDEF"[c >> 4];
      out += "0123456789ABCDEF"[c & 15];
    }
  }
  return out;
}

}  // namespace

PageRequest parse_page_request(Parameters& query) {
  PageRequest page;
  page.limit = query.integer("limit", 1, kMaxPageLimit).value_or(kDefaultPageLimit);
  page.cursor = query.text("cursor");
  if (page.cursor && page.cursor->empty())
    throw invalid_parameter("cursor", "empty (omit it for the first page)");
  return page;
}

std::string id_cursor(std::int64_t id) { return encode('i', std::to_string(id)); }

std::int64_t id_from_cursor(const std::string& cursor) {
  const std::string text = decode('i', cursor);
  std::int64_t id = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || id <= 0)
    throw invalid_parameter("cursor", "not a cursor this list returned");
  return id;
}

std::string name_cursor(const std::string& name) { return encode('n', name); }

std::string name_from_cursor(const std::string& cursor) { return decode('n', cursor); }

std::string next_page_link(const std::string& path, const QueryParameters& query,
                           std::int64_t limit, const std::string& cursor) {
  std::string target = path + "?";
  for (const auto& [name, value] : query) {
    if (name == "limit" || name == "cursor") continue;
    target += percent_encoded(name) + "=" + percent_encoded(value) + "&";
  }
  target += "limit=" + std::to_string(limit) + "&cursor=" + cursor;
  return "<" + target + ">; rel=\"next\"";
}

ApiResponse list_page_response(const ApiRequest& request, const ListPage& page) {
  ApiResponse response = ordered_json_response(page.items);
  if (page.next_cursor)
    response.headers.emplace_back(
        "Link", next_page_link(request.path, request.query, page.limit, *page.next_cursor));
  return response;
}

}  // namespace clearsky::api
