// A number in a CSV answer: nine significant digits (%.9g, enough for a float and for the
// measured inputs), never NaN or infinity (api/http/api_types.h finite()).
#pragma once

#include <string>

namespace clearsky::api {

std::string csv_number(double x);

}  // namespace clearsky::api
