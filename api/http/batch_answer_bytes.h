// The memory a batch answer of POST/GET /v1/radiance or /v1/rgb holds while it is computed and
// sent (docs/threat-model.md "exhaust memory with answers or requests"): such an answer is built
// whole, not streamed, so its bytes are reserved out of the answer memory budget
// (answer_memory_reservation.h) before the sky is computed and released once it was sent.
//
// Per view: the computed spectrum (one double per wavelength of the model's grid, and a status),
// each answered number as a JSON value in its array (16 bytes, arrays grown by doubling: 32) and
// as text in the encoded body (at most 26 characters; a CSV row of radiance repeats the view's
// two angles and the wavelength beside each value, 4 numbers of up to 16 characters: 64 bytes
// counted per value covers both), and the sample's object with its member names (node, key and
// text: 640 bytes); plus the answer's fixed members. An estimate from the counts alone, made
// before anything is computed.
//
// Answers estimated below kUncountedAnswerBytes (every single-view answer at the default grids)
// are not reserved: they hold at most that much per worker, and the common request pays no
// shared counter.
#pragma once

#include <cstddef>

namespace clearsky::api {

inline constexpr std::size_t kUncountedAnswerBytes = std::size_t{64} << 10;

// views: samples in the answer; grid_wavelengths: the model's grid (what is computed per view);
// numbers_per_view: the numbers the answer gives per view (the wavelengths asked for, or an
// RGB sample's 5).
std::size_t batch_answer_bytes(std::size_t views, std::size_t grid_wavelengths,
                               std::size_t numbers_per_view);

}  // namespace clearsky::api
