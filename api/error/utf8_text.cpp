// UTF-8 checks by nlohmann's serializer, the one that writes every answer: what it accepts is
// what can be sent.
#include "api/error/utf8_text.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace clearsky::api {

namespace {

bool is_ascii(std::string_view text) {
  return std::ranges::all_of(text, [](char c) { return static_cast<unsigned char>(c) < 0x80; });
}

}  // namespace

bool is_valid_utf8(std::string_view text) {
  return is_ascii(text) || replace_invalid_utf8(text) == text;
}

std::string replace_invalid_utf8(std::string_view text) {
  if (is_ascii(text)) return std::string(text);
  // The serializer replaces each invalid byte by U+FFFD (error_handler_t::replace); reading the
  // JSON string back gives the repaired text.
  const std::string quoted = nlohmann::json(std::string(text))
                                 .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return nlohmann::json::parse(quoted).get<std::string>();
}

std::string quoted_client_text(std::string_view text, std::size_t max_bytes) {
  if (text.size() <= max_bytes) return replace_invalid_utf8(text);
  return replace_invalid_utf8(text.substr(0, max_bytes)) + "...";
}

}  // namespace clearsky::api
