// The brute-force reference the robust screener is tested against (robust_screen.hpp,
// screen_brute_force; robust_population_test.cpp): every pair at every sample, O(N^2 T), on
// the robust screener's Ephemeris (the same force model and integrator); a - to + sign
// change of the range rate f = rho.rho' between two samples is refined by Brent's method
// (events.hpp) and the closest approach kept when its miss is <= D_ij = max(D, N R_c), R_c of
// eq. 1 of Wang Xiaoyu, "Space entity collision prediction algorithm and self-adaptive
// simulation step design", J. Air Force Eng. Univ. 7(6), 2006 (paper 002). It shares none
// of the robust screener's bounds; reference_screen.hpp is the same method made affordable
// for long spans.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "evade/conjunction/ephemeris.hpp"
#include "evade/conjunction/internal/narrow_phase.hpp"
#include "evade/conjunction/internal/screen_support.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/dynamics/events.hpp"

namespace evade::conjunction {

ScreenResult screen_brute_force(const std::vector<SpaceObject>& objects, double span_s,
                                double sample_step_s, const ScreenOptions& opt) {
  opt.validate();
  if (!(sample_step_s > 0.0) || !std::isfinite(sample_step_s)) {
    throw std::invalid_argument("sample_step_s outside (0, inf)");
  }
  validate_objects(objects, opt.earth);
  ScreenResult res;
  const std::size_t n = objects.size();
  if (n < 2) return res;
  internal::check_motion_and_primary(objects, opt);
  Ephemeris eph(objects, opt.gravity, opt.earth, opt.integ, opt.motion);
  const long nsteps = static_cast<long>(std::ceil(span_s / sample_step_s - 1e-12));
  std::vector<StateEci> prev, cur;
  std::vector<double> f_prev(n * n, 0.0);
  double t_prev = 0.0;
  eph.states_at(0.0, prev);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) f_prev[i * n + j] = internal::range_rate_product(prev[i], prev[j]);
  for (long k = 1; k <= nsteps; ++k) {
    const double t = (k == nsteps) ? span_s : static_cast<double>(k) * sample_step_s;
    eph.states_at(t, cur);
    ++res.stats.steps;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        if (!opt.screens_pair(i, j)) continue;
        ++res.stats.pairs_checked;
        const double fc = internal::range_rate_product(cur[i], cur[j]);
        double& fp = f_prev[i * n + j];
        if (fp < 0.0 && fc >= 0.0) {
          ++res.stats.root_solves;
          const StateEci &gi = prev[i], &gj = prev[j];
          auto f = [&](double tt) {
            return internal::range_rate_product(eph.state_near(i, tt, gi, t_prev),
                                                eph.state_near(j, tt, gj, t_prev));
          };
          const double tca = brent_root(f, t_prev, t, fp, fc, opt.tca_tol_s, 200);
          const StateEci si = eph.state_near(i, tca, gi, t_prev);
          const StateEci sj = eph.state_near(j, tca, gj, t_prev);
          const double miss = (sj.r_eci_m - si.r_eci_m).norm();
          const double d_ij = pair_threshold_m(opt, collision_radius_m(objects[i], objects[j]));
          if (miss <= d_ij) {
            const double rc = collision_radius_m(objects[i], objects[j]);
            res.events.push_back(Conjunction{i, j, tca, miss, (sj.v_eci_mps - si.v_eci_mps).norm(),
                                             miss <= rc, miss <= opt.warning_multiple * rc});
          }
        }
        fp = fc;
      }
    }
    std::swap(prev, cur);
    t_prev = t;
  }
  internal::sort_events(res.events);
  return res;
}

}  // namespace evade::conjunction
