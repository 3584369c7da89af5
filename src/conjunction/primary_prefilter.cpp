// The perigee/apogee filter of one satellite against a catalog
// (include/evade/conjunction/primary_prefilter.hpp gives the argument).
#include "evade/conjunction/primary_prefilter.hpp"

#include "evade/sgp4/sgp4.hpp"

namespace evade::conjunction {
namespace {

sgp4::RadiusBounds bounds_over(const sgp4::MeanElements& m, double start_j2000_s, double span_s) {
  const double t0_s = start_j2000_s - sgp4::epoch_seconds_since_j2000(m) - kPrefilterPadS;
  const double t1_s = t0_s + span_s + 2.0 * kPrefilterPadS;
  return sgp4::Sgp4Propagator(m, sgp4::OperationMode::kImproved)
      .radius_bounds(t0_s / 60.0, t1_s / 60.0);
}

}  // namespace

std::vector<sgp4::MeanElements> prefilter_primary(const std::vector<sgp4::MeanElements>& all,
                                                  long primary_norad, double start_j2000_s,
                                                  double span_s, double threshold_m,
                                                  PrimaryPrefilterCounts* counts) {
  PrimaryPrefilterCounts c;
  c.objects = static_cast<long>(all.size());
  long primary = -1;
  for (std::size_t k = 0; k < all.size() && primary < 0; ++k)
    if (all[k].norad_id == primary_norad) primary = static_cast<long>(k);
  sgp4::RadiusBounds p;
  if (primary >= 0) p = bounds_over(all[static_cast<std::size_t>(primary)], start_j2000_s, span_s);
  c.primary_bounded = p.bounded;
  std::vector<sgp4::MeanElements> kept;
  for (std::size_t k = 0; k < all.size(); ++k) {
    bool keep = !p.bounded || static_cast<long>(k) == primary;
    if (!keep) {
      const sgp4::RadiusBounds b = bounds_over(all[k], start_j2000_s, span_s);
      if (!b.bounded) ++c.unbounded;
      keep = !b.bounded || (b.min_m <= p.max_m + threshold_m && b.max_m >= p.min_m - threshold_m);
      if (!keep) ++c.removed_radius;
    }
    if (keep) kept.push_back(all[k]);
  }
  c.kept = static_cast<long>(kept.size());
  if (counts) *counts = c;
  return kept;
}

}  // namespace evade::conjunction
