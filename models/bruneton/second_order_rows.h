// The rows of the single-scattering tables that the second order reads (Bruneton and Neyret
// 2008, Algorithm 4.1: the density J of order 2, Eq. 7, and the sky irradiance of order 1,
// Eq. 15, read single scattering; nothing else does until the end).
//
// Both read the 4D tables only at fixed zeniths: J at each layer's radius and the sphere's
// sphere_samples zeniths, the irradiance at each irradiance radius and its irradiance_samples / 2
// zeniths of the upper hemisphere; their lookups touch two layers and two mu rows at most. The
// precomputation releases the single-scattering tables after the second order and builds them
// in full again at the end (docs/tables-and-memory.md "The precomputation's peak"), so the
// first pass needs only these rows: 749 of the 4,096 at the paper's resolution. Each row is
// computed alone (its own view ray and half-precision scale), so the rows it computes are the
// same bit for bit, and the later orders the same as with every row computed
// (docs/performance.md "Bruneton's precomputation").
#pragma once

#include <vector>

#include "models/bruneton/bruneton_functions.h"

namespace clearsky::bruneton {

// cos((i + 0.5) pi / n) for i < count: the zeniths of J's sphere (count = n = sphere_samples)
// and of the irradiance's hemisphere (count = n / 2, n = irradiance_samples), as the 2008 code's
// inscatterS and irradianceN place them.
std::vector<double> zenith_cosines(int count, int n);

// Per (r, mu) row of the 4D tables (index layer * res.mu + mu): 1 where a lookup of J's or the
// irradiance's profiles can read it (both texels of its r and mu axes, whatever their weights),
// 0 elsewhere.
std::vector<char> rows_read_by_second_order(const Resolution& res, const ShellGeometry& g);

}  // namespace clearsky::bruneton
