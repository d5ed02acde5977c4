// Prints the OpenAPI document the server serves at /openapi.json, for the linter's CTest
// (tests/api/openapi/CMakeLists.txt, docs/openapi.md).
#include <iostream>

#include "api/openapi/openapi_document.h"

int main() {
  std::cout << clearsky::api::openapi_document().dump(2) << '\n';
  return std::cout ? 0 : 1;
}
