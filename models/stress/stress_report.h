// What a stress run of one model found (docs/stability.md): how many spectra were computed, the
// refusals by status and whether the descriptor declares each, values that must never appear
// (non-finite, negative), the largest relative jump between neighbours of every sweep (jumps at
// the model's documented discontinuities reported apart, by name), and the physical checks:
// symmetry about the sun's vertical plane, energy bounds and the trends with aerosol. Plain data;
// thread-safety: a value, safe to share once written.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "models/core/sample_status.h"

namespace clearsky::stress {

// Refusals of one status: declared when the descriptor says the input is outside what the model
// answers (sun beyond max_sun_zenith_deg, altitude outside the range, a view below the horizon
// of a ground-only model, a fitted model outside its fit domain), undeclared otherwise.
struct RefusalTally {
  std::size_t declared = 0;
  std::size_t undeclared = 0;
  std::string first_undeclared_at{};  // where the first undeclared refusal happened
};

// A jump at a location the model documents as discontinuous, excluded from the sweep's worst.
struct ExcludedJump {
  std::string name{};  // the documented discontinuity, e.g. "ground_horizon"
  double relative_jump = 0;
  double from = 0, to = 0;  // the neighbours' coordinates
};

// One sweep: a coordinate varied through the domain with everything else fixed.
struct SweepSummary {
  std::string name{};        // e.g. "view_zenith_deg sun_zenith_deg=30 azimuth_offset_deg=90"
  std::string coordinate{};  // e.g. "view_zenith_deg"
  std::size_t points = 0;    // coordinate values
  std::size_t chains = 0;    // quantities followed along it (views, irradiances)
  // Largest |a - b| / max(|a|, |b|, floor) between answered neighbours over wavelengths and
  // chains, floor = 1e-2 of the chain's peak at that wavelength (so a value decaying to
  // nothing does not count as a jump); where it is, and in which chain.
  double worst_relative_jump = 0;
  double worst_from = 0, worst_to = 0;
  double worst_wavelength_nm = 0;
  std::string worst_chain{};
  std::vector<ExcludedJump> excluded{};  // the worst jump at each documented discontinuity
};

// A check over many samples: how many were checked, how many failed, the worst ratio to the
// bound (1 is the bound itself) and where.
struct BoundCheck {
  std::string name{};
  std::string bound{};  // what is checked, in words
  std::size_t checked = 0;
  std::size_t violations = 0;
  double worst = 0;
  std::string worst_at{};
  std::string first_violation_at{};  // in sweep order
  // A limit the model documents for this check (documented_limits.h), and the worst ratio it
  // allows; empty: none, every violation fails.
  std::string documented_limit{};
  double allowed_worst = 1.0;
};

struct ModelStressReport {
  std::string model{};
  std::string version{};
  std::vector<double> wavelengths_nm{};
  std::map<std::string, double> options{};  // the base configuration's options
  std::size_t samples = 0;                  // spectra asked for (views, irradiances)
  std::map<SampleStatus, RefusalTally> refusals{};
  // Values delivered by the checked queries that are non-finite or negative: the checks of
  // SkyModel turn them into numerical_failure, so these count what slipped through (must be 0).
  std::size_t non_finite_values = 0;
  std::size_t negative_values = 0;
  std::vector<SweepSummary> sweeps{};
  BoundCheck symmetry;
  BoundCheck energy;
  BoundCheck radiance_below_sun;
  std::vector<BoundCheck> trends{};
  std::size_t models_built = 0;
  double seconds = 0;

  std::size_t undeclared_refusals() const {
    std::size_t n = 0;
    for (const auto& [status, tally] : refusals) n += tally.undeclared;
    return n;
  }
};

}  // namespace clearsky::stress
