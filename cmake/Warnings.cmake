# clearsky_warnings: the warning flags of every clearsky target, as an INTERFACE library that
# each library, executable and test program links PRIVATE (so flags do not leak to consumers
# and third-party code configured in the same tree is not affected). CLEARSKY_WERROR (default
# ON) makes any warning fail the build; turn it off to try a new compiler.
add_library(clearsky_warnings INTERFACE)
target_compile_options(clearsky_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow)
if(CLEARSKY_WERROR)
  target_compile_options(clearsky_warnings INTERFACE -Werror)
endif()
# GCC 12 reports -Wrestrict inside libstdc++ when a std::string member is assigned a string
# literal after inlining (GCC bug 105329, fixed in GCC 13): a false positive, silenced for
# GCC 12 only.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12
   AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(clearsky_warnings INTERFACE -Wno-restrict)
endif()
