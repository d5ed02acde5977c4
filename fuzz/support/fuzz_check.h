// What the fuzz programs (docs/fuzzing.md) do with a broken invariant: print it with the
// input's description and abort, which libFuzzer reports as a crash and saves the input.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace clearsky::fuzz {

[[noreturn]] inline void fail(const std::string& what, const std::string& context = {}) {
  std::fprintf(stderr, "\nFUZZ INVARIANT BROKEN: %s\n", what.c_str());
  if (!context.empty()) std::fprintf(stderr, "input: %s\n", context.c_str());
  std::abort();
}

inline void check(bool condition, const std::string& what, const std::string& context = {}) {
  if (!condition) fail(what, context);
}

}  // namespace clearsky::fuzz
