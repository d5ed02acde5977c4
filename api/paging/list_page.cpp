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

PageRequest parse_page_request(const QueryParameters& query) {
  PageRequest page;
  for (const auto& [name, value] : query) {
    if (name == "limit") {
      std::int64_t limit = 0;
      const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), limit);
      if (value.empty() || error != std::errc() || end != value.data() + value.size() ||
          limit < 1 || limit > kMaxPageLimit)
        throw invalid_parameter("limit", "\"" + value + "\" is not an integer in [1, " +
                                             std::to_string(kMaxPageLimit) + "]");
      page.limit = limit;
    } else if (name == "cursor") {
      if (value.empty()) throw invalid_parameter("cursor", "empty (omit it for the first page)");
      page.cursor = value;
    }
  }
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

}  // namespace clearsky::api
