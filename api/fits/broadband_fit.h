// An atmosphere fit to a broadband irradiance dataset (docs/fits.md "Fits to broadband
// irradiance"): the values of the free parameters (models/fitting/fit_space.h) that minimise the
// RMSE, W/m2, of the model's broadband irradiance against the components measured, all their
// samples pooled (pooled_rmse_w_m2 of api/evaluation/broadband_evaluation.h: the objective of
// a day of GHI is the RMSE of GHI).
//  1. Grid: every point of the free parameters' grid (FitSettings::parameters' grid_points).
//  2. Refinement: golden-section search (Kiefer 1953, "Sequential minimax search for a
//     maximum") along each free parameter in turn, within one grid step either side of the
//     best point, the others held, until it moves less than relative_tolerance of the bounds'
//     width or max_refine_evaluations are spent; twice over the parameters when there are
//     several.
//  3. Uncertainty: per parameter, the range of the values evaluated whose RMSE is within
//     uncertainty_fraction of the minimum (scan and sampled alike).
//  4. Confirmation: the optimum (and the start) at config's own setting on every sample.
// The search runs with search_options over config's (the cheap tables of fit_space.h for table
// models) and on at most kMaxBroadbandSearchSamples samples with the sun up, evenly spread over
// the series (every sample costs a hemisphere of sky irradiance and a broadband extension per
// point evaluated); the confirmation on all of them. The result is the capture fits' FitResult
// (models/fitting/atmosphere_fit.h) without captures, so that it is stored and shown as theirs.
// Thread-safety: may run on several threads at once for different fits.
#pragma once

#include <vector>

#include "models/fitting/atmosphere_fit.h"
#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::api {

inline constexpr std::size_t kMaxBroadbandSearchSamples = 240;

// Throws std::invalid_argument when no sample has the sun up or the model does not answer
// broadband (broadband_unavailable_reason, naming model), whatever the model's factory throws,
// and PrecomputeCancelled.
FitResult fit_broadband(const ModelFactory& factory,
                        const std::vector<storage::IrradianceSample>& samples,
                        const FitSettings& settings);

}  // namespace clearsky::api
