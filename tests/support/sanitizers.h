// Whether this program is built with AddressSanitizer (deploy/test.sh runs the unit tests in a
// clang ASan + UBSan tree): tests that measure resident memory cannot bound it there, since
// freed blocks wait in the sanitizer's quarantine and allocations carry shadow memory.
#pragma once

#include <gtest/gtest.h>

namespace clearsky::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace clearsky::testing

// A numerical refinement test (a model at settings several times finer than the paper's,
// converging on its reference) skips itself in the sanitizer tree: there (-O1, instrumented
// loads) each took minutes of the 2-core run (Nishita93's 256 and 512 spheres and cylinders,
// O'Neal's 512 samples, a 16,200-view integration), reaching the code the model's tests at its
// paper setting reach there too. The Release pass of deploy/test.sh runs them.
#define CLEARSKY_SKIP_REFINEMENT_UNDER_SANITIZERS()                                       \
  do {                                                                                    \
    if (::clearsky::testing::kAddressSanitizer)                                           \
      GTEST_SKIP() << "a refinement test: run in the Release pass, not under sanitizers"; \
  } while (false)
