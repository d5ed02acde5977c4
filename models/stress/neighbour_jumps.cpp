// Largest relative neighbour jump of a sweep (neighbour_jumps.h).
#include "models/stress/neighbour_jumps.h"

#include <algorithm>
#include <cmath>

namespace clearsky::stress {

namespace {

const DocumentedJump* documented_between(std::span<const DocumentedJump> documented,
                                         const std::string& chain, double a, double b) {
  const double low = std::min(a, b), high = std::max(a, b);
  for (const DocumentedJump& d : documented)
    if ((d.chain.empty() || d.chain == chain) && d.coordinate >= low && d.coordinate <= high)
      return &d;
  return nullptr;
}

// Whether an outside_fit_domain refusal lies within kFitDomainEdgePoints of points i and i + 1.
bool near_fit_domain_edge(const Chain& chain, std::size_t i) {
  const std::size_t from = i >= kFitDomainEdgePoints ? i - kFitDomainEdgePoints : 0;
  const std::size_t to = std::min(chain.points.size(), i + 2 + kFitDomainEdgePoints);
  for (std::size_t k = from; k < to; ++k)
    if (chain.points[k].status == SampleStatus::outside_fit_domain) return true;
  return false;
}

void note_excluded(SweepSummary& summary, const std::string& name, double jump, double from,
                   double to) {
  auto it = std::find_if(summary.excluded.begin(), summary.excluded.end(),
                         [&](const ExcludedJump& e) { return e.name == name; });
  if (it == summary.excluded.end()) {
    summary.excluded.push_back({name, jump, from, to});
  } else if (jump > it->relative_jump) {
    *it = {name, jump, from, to};
  }
}

}  // namespace

void summarize_jumps(std::span<const Chain> chains, std::span<const double> wavelengths_nm,
                     std::span<const DocumentedJump> documented, SweepSummary& summary) {
  summary.chains = chains.size();
  for (const Chain& chain : chains) {
    summary.points = std::max(summary.points, chain.points.size());
    std::vector<double> peak(wavelengths_nm.size(), 0.0);
    for (const ChainPoint& p : chain.points) {
      if (!p.answered) continue;
      for (std::size_t w = 0; w < peak.size() && w < p.values.size(); ++w)
        peak[w] = std::max(peak[w], std::abs(p.values[w]));
    }
    for (std::size_t i = 0; i + 1 < chain.points.size(); ++i) {
      const ChainPoint& a = chain.points[i];
      const ChainPoint& b = chain.points[i + 1];
      if (!a.answered || !b.answered) continue;
      double worst = 0.0;
      std::size_t worst_w = 0;
      for (std::size_t w = 0; w < peak.size() && w < a.values.size() && w < b.values.size(); ++w) {
        if (!(peak[w] > 0.0)) continue;
        const double scale =
            std::max({std::abs(a.values[w]), std::abs(b.values[w]), kJumpFloorOfPeak * peak[w]});
        const double jump = std::abs(a.values[w] - b.values[w]) / scale;
        if (jump > worst) {
          worst = jump;
          worst_w = w;
        }
      }
      if (const DocumentedJump* d =
              documented_between(documented, chain.name, a.coordinate, b.coordinate)) {
        note_excluded(summary, d->name, worst, a.coordinate, b.coordinate);
        continue;
      }
      if (near_fit_domain_edge(chain, i)) {
        note_excluded(summary, "fit_domain_edge", worst, a.coordinate, b.coordinate);
        continue;
      }
      if (worst > summary.worst_relative_jump) {
        summary.worst_relative_jump = worst;
        summary.worst_from = a.coordinate;
        summary.worst_to = b.coordinate;
        summary.worst_wavelength_nm = wavelengths_nm[worst_w];
        summary.worst_chain = chain.name;
      }
    }
  }
}

}  // namespace clearsky::stress
