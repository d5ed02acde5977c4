// A number in a CSV answer (csv_number.h).
#include "api/encode/csv_number.h"

#include <cstdio>

#include "api/http/api_types.h"

namespace clearsky::api {

std::string csv_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(finite(x)));
  return buffer;
}

}  // namespace clearsky::api
