// Whether this program is built with AddressSanitizer (deploy/test.sh runs the unit tests in a
// clang ASan + UBSan tree): tests that measure resident memory cannot bound it there, since
// freed blocks wait in the sanitizer's quarantine and allocations carry shadow memory.
#pragma once

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
