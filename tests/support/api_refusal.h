// The refusal a call throws, for tests that compare an api::ApiError's status, parameter and
// message (docs/conventions.md "Typed errors naming the parameter"): status 0 when the call
// throws nothing.
#pragma once

#include <string>

#include "api/error/api_error.h"

namespace clearsky::testing {

struct ApiRefusal {
  int status = 0;
  std::string parameter, message;
};

template <typename F>
ApiRefusal refusal_of(F&& call) {
  try {
    call();
  } catch (const api::ApiError& e) {
    return {e.status(), e.parameter(), e.what()};
  }
  return {};
}

}  // namespace clearsky::testing
