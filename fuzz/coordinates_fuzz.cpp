// Latitudes and longitudes of requests in every notation they take (api/parse/coordinates.h):
// decimal degrees, degrees-minutes-seconds with d/'/" or colons or the Unicode signs, with or
// without a hemisphere letter. The input is one coordinate, read both as a latitude and as a
// longitude.
//
// Invariants (docs/fuzzing.md): a refusal is an ApiError 400 naming the parameter, nothing
// else escapes; an accepted latitude is finite in [-90, 90], a longitude in [-180, 180]; the
// decimal text of an accepted value reads back to the same value.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "api/error/api_error.h"
#include "api/parse/coordinates.h"
#include "fuzz/support/fuzz_check.h"

namespace {

template <typename Parse>
void check_coordinate(const std::string& input, const std::string& parameter, double limit,
                      Parse parse) {
  using namespace clearsky;
  using namespace clearsky::fuzz;
  double value = 0;
  try {
    value = parse(input, parameter);
  } catch (const api::ApiError& e) {
    check(e.status() == 400, "refusal with status " + std::to_string(e.status()), input);
    check(e.parameter() == parameter, "refusal naming '" + e.parameter() + "'", input);
    return;
  } catch (const std::exception& e) {
    fail(parameter + ": not an ApiError: " + e.what(), input);
  }
  check(std::isfinite(value) && std::abs(value) <= limit,
        parameter + " out of range: " + std::to_string(value), input);
  char decimal[64];
  std::snprintf(decimal, sizeof decimal, "%.17g", value);
  try {
    check(parse(decimal, parameter) == value, parameter + ": " + decimal + " reads back another",
          input);
  } catch (const std::exception& e) {
    fail(parameter + ": " + decimal + " does not read back: " + e.what(), input);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  check_coordinate(input, "lat", 90.0, [](std::string_view text, const std::string& parameter) {
    return clearsky::api::parse_latitude(text, parameter);
  });
  check_coordinate(input, "lon", 180.0, [](std::string_view text, const std::string& parameter) {
    return clearsky::api::parse_longitude(text, parameter);
  });
  return 0;
}
