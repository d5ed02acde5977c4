// float to OpenEXR's half for the skydome's pixels: what Imath's half(float) gives (round to
// nearest even, overflow to infinity), 8 values per instruction with the processor's F16C
// conversion where it has one. Imath uses that instruction itself when built for F16C
// (Imath/half.h, imath_float_to_half), so the bits are the same for every value other than a
// NaN, which no pixel holds (the service sends no NaN).
// Pure; thread-safe.
#pragma once

#include <Imath/half.h>

#include <cstddef>

namespace clearsky::api {

// out[i] = half(in[i]) for i in [0, n).
void floats_to_halves(const float* in, half* out, std::size_t n);

}  // namespace clearsky::api
