// The largest relative jump between neighbouring samples of a sweep (docs/stability.md): a
// chain is one quantity (a view's radiance, an irradiance) followed along the swept coordinate;
// a refused sample breaks it. Jumps whose interval contains a documented discontinuity of the
// model are reported apart, by its name, not as the chain's worst.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "models/stress/stress_report.h"

namespace clearsky::stress {

struct ChainPoint {
  double coordinate = 0;
  bool answered = false;
  std::vector<double> values{};  // one per wavelength (empty when not answered)
  SampleStatus status = SampleStatus::ok;
};

struct Chain {
  std::string name;
  std::vector<ChainPoint> points;  // in sweep order
};

// A coordinate at which the model documents a jump (docs/stability.md "Documented jumps").
struct DocumentedJump {
  std::string name{};
  double coordinate = 0;
  std::string chain{};  // the chain it concerns; empty: every chain of the sweep
};

// A fitted model's spectrum crosses zero linearly where it leaves its fit domain
// (models/core/fit_domain.h), so the relative change between neighbours grows without bound
// there: jumps within this many points of an outside_fit_domain refusal are reported apart, as
// the documented jump "fit_domain_edge".
inline constexpr std::size_t kFitDomainEdgePoints = 5;

// The floor of the relative jump, as a fraction of the chain's peak at each wavelength.
inline constexpr double kJumpFloorOfPeak = 1e-2;

// Fills summary.worst_* and summary.excluded from the chains of one sweep (summary.name and
// coordinate are the caller's). wavelengths_nm names the wavelength of each value.
void summarize_jumps(std::span<const Chain> chains, std::span<const double> wavelengths_nm,
                     std::span<const DocumentedJump> documented, SweepSummary& summary);

}  // namespace clearsky::stress
