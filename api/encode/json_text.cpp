// JSON text laid out as nlohmann::json's dump() writes it (json_text.h).
#include "api/encode/json_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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
  const std::uint64_t significand = decimal.significand;
  const int k = fmt::detail::count_digits(significand);
  // The decimal point's position after the first digit: value = 0.d1d2...dk * 10^n.
  const int n = k + decimal.exponent;
  // The digits are written two at a time straight to their place in the buffer (no copy of
  // them afterwards): these numbers are most of a radiance answer's bytes.
  const auto write_digits = [&](char* at) {
    fmt::detail::format_decimal<char>(at, significand, k);
  };
  // dump()'s layout (nlohmann's dtoa_impl::format_buffer, min_exp -4, max_exp 15).
  constexpr int min_exp = -4;
  constexpr int max_exp = 15;
  if (k <= n && n <= max_exp) {  // digits[000].0
    write_digits(p);
    p += k;
    for (int i = k; i < n; ++i) *p++ = '0';
    *p++ = '.';
    *p++ = '0';
  } else if (0 < n && n <= max_exp) {  // dig.its: the first n digits move left for the point
    write_digits(p + 1);
    for (int i = 0; i < n; ++i) p[i] = p[i + 1];
    p[n] = '.';
    p += k + 1;
  } else if (min_exp < n && n <= 0) {  // 0.[000]digits
    *p++ = '0';
    *p++ = '.';
    for (int i = 0; i < -n; ++i) *p++ = '0';
    write_digits(p);
    p += k;
  } else {  // d[.igits]e+XX, the exponent with at least two digits
    write_digits(p + 1);
    p[0] = p[1];
    if (k > 1) {
      p[1] = '.';
      p += k + 1;
    } else {
      p += 1;
    }
    *p++ = 'e';
    int e = n - 1;
    *p++ = e < 0 ? '-' : '+';
    if (e < 0) e = -e;
    if (e >= 100) {
      *p++ = static_cast<char>('0' + e / 100);
      e %= 100;
    }
    *p++ = static_cast<char>('0' + e / 10);
    *p++ = static_cast<char>('0' + e % 10);
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
