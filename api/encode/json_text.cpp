// JSON text laid out as nlohmann::json's dump() writes it (json_text.h).
#include "api/encode/json_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace clearsky::api {

void append_json_number(std::string& out, double value) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  // At most a sign, 17 digits, "0." and 3 zeros, or a point and "e-308": 24 bytes.
  std::array<char, 32> buffer;
  char* p = buffer.data();
  if (std::signbit(value)) {
    *p++ = '-';
    value = -value;
  }
  if (value == 0.0) {
    out.append(buffer.data(), p);
    out += "0.0";
    return;
  }
  // value = significand * 10^exponent, the significand's decimal digits the shortest that
  // round-trip (Dragonbox; fmt's public formatting lays them out unlike dump(), so its digit
  // generator is called directly: Debian's libfmt 9 exports it).
  const auto decimal = fmt::detail::dragonbox::to_decimal(value);
  // Two digits a step (fmt::format_int: about a quarter fewer instructions than std::to_chars).
  const fmt::format_int significand(decimal.significand);
  const char* const digits = significand.data();
  const char* const digits_end = digits + significand.size();
  const int k = static_cast<int>(significand.size());
  // The decimal point's position after the first digit: value = 0.d1d2...dk * 10^n.
  const int n = k + decimal.exponent;
  // dump()'s layout (nlohmann's dtoa_impl::format_buffer, min_exp -4, max_exp 15).
  constexpr int min_exp = -4;
  constexpr int max_exp = 15;
  if (k <= n && n <= max_exp) {  // digits[000].0
    p = std::copy(digits, digits_end, p);
    p = std::fill_n(p, n - k, '0');
    *p++ = '.';
    *p++ = '0';
  } else if (0 < n && n <= max_exp) {  // dig.its
    p = std::copy(digits, digits + n, p);
    *p++ = '.';
    p = std::copy(digits + n, digits_end, p);
  } else if (min_exp < n && n <= 0) {  // 0.[000]digits
    *p++ = '0';
    *p++ = '.';
    p = std::fill_n(p, -n, '0');
    p = std::copy(digits, digits_end, p);
  } else {  // d[.igits]e+XX, the exponent with at least two digits
    *p++ = digits[0];
    if (k > 1) {
      *p++ = '.';
      p = std::copy(digits + 1, digits_end, p);
    }
    *p++ = 'e';
    int e = n - 1;
    *p++ = e < 0 ? '-' : '+';
    if (e < 0) e = -e;
    if (e < 10) *p++ = '0';
    p = std::to_chars(p, buffer.data() + buffer.size(), e).ptr;
  }
  out.append(buffer.data(), p);
}

void append_finite_json_number(std::string& out, double value) {
  if (!std::isfinite(value)) throw std::logic_error("a non-finite number was about to be sent");
  append_json_number(out, value);
}

void append_json_number_array(std::string& out, const std::vector<double>& values) {
  out += '[';
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ',';
    append_json_number(out, values[i]);
  }
  out += ']';
}

void append_json_string(std::string& out, std::string_view text) {
  const bool plain = std::all_of(text.begin(), text.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u < 0x7F && c != '"' && c != '\\';
  });
  if (!plain) {
    // Escapes and UTF-8 (checked, as dump() does) stay nlohmann's.
    out += nlohmann::json(std::string(text)).dump();
    return;
  }
  out += '"';
  out += text;
  out += '"';
}

void JsonObjectText::append_to(std::string& out) {
  std::sort(members_.begin(), members_.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t size = 2;
  for (const auto& [key, value] : members_) size += key.size() + value.size() + 4;
  out.reserve(out.size() + size);
  out += '{';
  bool first = true;
  for (const auto& [key, value] : members_) {
    if (!first) out += ',';
    first = false;
    append_json_string(out, key);
    out += ':';
    out += value;
  }
  out += '}';
}

}  // namespace clearsky::api
