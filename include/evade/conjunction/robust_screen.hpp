// Conjunction screening that cannot miss an approach below the threshold (issue 6), for one
// pair or a catalog, and a brute-force fine-step reference to test it against.
//
// The span is cut into grid steps [t_a, t_b] (step_s). For every object and step:
//   * the trajectory stays within g h^2/8 of the chord r(t_a) -> r(t_b) componentwise
//     (interpolation error of a function whose second derivative is bounded by g, the
//     largest gravity acceleration on the orbit, mu / r_perigee^2, with a J2 margin);
//   * so a pair can come within D during the step only if the boxes around the two chords,
//     padded by g h^2/8 + D/2, overlap. Boxes go into a uniform grid whose cells are as
//     large as the largest box (each box touches at most 8 cells; the (cell, object) entries
//     are sorted by a radix sort on the cell); pairs are formed per cell (the cell's boxes
//     copied together and tested branch-free) and kept once (in the cell that holds the low
//     corner of their box overlap).
// Before that, the apogee/perigee filter (Hoots, Crawford & Roehrich, Celest. Mech. 33,
// 1984) removes pairs whose radius ranges are more than D apart.
// Narrow phase, per candidate pair and step, branch and bound on [a, b]:
//   relative position rho(t), rho'' = g_j - g_i, |rho''| <= A = min(g_i + g_j, K R_max)
//   (K = 2 mu / r_min^3: the gravity gradient's largest eigenvalue, with a J2 margin);
//   lower bound of |rho| on [a, b] = distance of the chord rho(a) -> rho(b) from the
//   origin - A (b-a)^2 / 8. The interval is dropped when the bound exceeds D. Otherwise the
//   range rate f = rho.rho' is examined: f' = |rho'|^2 + rho.rho'' >= V_min^2 - R_max A,
//   V_min = (|rho'(a)| + |rho'(b)| - A (b-a)) / 2; when that is > 0, f is increasing, has
//   at most one root in [a, b], and a closest approach exists iff f(a) < 0 <= f(b); it is
//   located by Brent's method (events.hpp) on f and kept if its miss is <= D. If f cannot
//   be shown monotone (slow co-orbital pairs), [a, b] is halved down to leaf_s and the sign
//   test is applied on each leaf (counted as unproven_leaves; docs/VALIDATION.md).
// Under two-body + J2 the radius range, g, K, L and the speed bound of every object come per
// grid step from the arc lemma of arc_bounds.hpp (proved in docs/VALIDATION.md).
// With a MotionSource (ScreenOptions::motion, e.g. SGP4) the objects move by it; its bound
// eps_i on |r_i'' - a(r_i)| (a = two-body + J2) enters the arc lemma as G + eps_i, A as
// K R_max + eps_i + eps_j, and the f'' bound with the rates (docs/VALIDATION.md, "Robust
// mode with SGP4 motion"). ScreenOptions::primary limits the pairs to those of one object.
// Threads (std::thread) work on blocks of grid steps: first they advance every object
// through the block's grid times (objects split between them; under J2 each object's
// integrator steps through every grid time from t = 0), then they screen the block's steps
// (steps split between them). Processes split the steps by screen_robust_part (under J2 each
// first advances its objects through the earlier grid times); events are merged and
// sorted. Results do not depend on the split.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "evade/conjunction/motion_source.hpp"
#include "evade/conjunction/types.hpp"
#include "evade/core/param.hpp"
#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::conjunction {

struct ScreenOptions {
  double threshold_m = 5000.0;    ///< D: report every closest approach with miss <= D_ij
  bool include_warning_radius = true;  ///< D_ij = max(D, N R_c(i, j)) instead of D
  double warning_multiple = 5.0;  ///< N for the warning flag (and D_ij above)
  double step_s = 60.0;           ///< grid step h [s]; 0 = auto_step_s(N)
  double leaf_s = 0.5;            ///< smallest subdivision of the narrow phase [s]
  double tca_tol_s = 1e-9;        ///< Brent bracket tolerance on the TCA [s]
  int threads = 2;                ///< worker threads (>= 1)
  GravityModel gravity = GravityModel::kTwoBody;
  EarthModel earth = kEarthDefault;
  AdaptiveOptions integ = AdaptiveOptions::tight();  ///< J2 path only
  /// Objects move by this source instead of the force model (size = number of objects);
  /// then gravity must be kTwoBodyJ2 and earth the source's reference_earth().
  std::shared_ptr<const MotionSource> motion;
  /// Index of the one object whose pairs are screened (-1: all pairs).
  long primary = -1;
  /// True when the pair (i, j) is screened (every pair, or only those of the primary).
  bool screens_pair(std::size_t i, std::size_t j) const {
    return primary < 0 || static_cast<long>(i) == primary || static_cast<long>(j) == primary;
  }
  /// Called from the calling thread with the fraction done in [0, 1] (may be empty).
  std::function<void(double)> progress;
  /// Throws std::invalid_argument naming the option, value and allowed range (the table's
  /// rows as "robust.<key>", the Earth model with the Earth table).
  void validate() const;
};

/// D_ij, the distance within which a pair is reported: the threshold D, or with
/// include_warning_radius max(D, N R_c(i, j)), R_c the pair's collision radius (eq. 1:
/// collision_radius_m of types.hpp) [m]. The one definition every screener uses.
inline double pair_threshold_m(const ScreenOptions& opt, double collision_radius_m) noexcept {
  if (!opt.include_warning_radius) return opt.threshold_m;
  return std::max(opt.threshold_m, opt.warning_multiple * collision_radius_m);
}

/// The scenario's `robust.*` rows of ScreenOptions: threshold_m, step_s, leaf_s (the other
/// fields come from the command line, paper_step.n_warning and the Earth model).
ParamTable<ScreenOptions> screen_options_params() noexcept;

struct ScreenStats {
  long steps = 0;                 ///< grid steps
  long pairs_checked = 0;         ///< pairs sharing a grid cell (box tests done)
  long candidates = 0;            ///< pairs whose boxes overlap and that pass apogee/perigee
  long refined = 0;               ///< intervals examined by the narrow phase
  long root_solves = 0;           ///< Brent solves on the range rate
  long pairs_after_apogee_perigee = 0;  ///< pairs whose radius ranges overlap within max D_ij
  long unproven_leaves = 0;       ///< leaves where f could not be shown monotone
  long repeated_roots_merged = 0; ///< second roots of one closest approach, dropped (noise)
};

struct ScreenResult {
  std::vector<Conjunction> events;  ///< sorted by tca_s, then i, j
  ScreenStats stats;
};

/// Grid step balancing propagation (~N per step) against pair tests (~N^2 h^3 per step):
/// cost per span ~ N/h + N^2 h^2 is smallest for h ~ N^(-1/3), so
/// h = h_10k (10 000/N)^(1/3) s, clamped to [10, 120] s. h_10k, calibrated on this machine
/// (docs/PERFORMANCE.md): kAutoStepForceModels_s for two-body and J2 (60 s was best at
/// N = 10 000); kAutoStepGridStates_s for a motion source with grid states (SGP4: one
/// evaluation per object and step, and a candidate pair costs a position-only test before
/// any exact state; 60 s was best at N = 30 000, about 110 s at N = 5 000).
constexpr double kAutoStepForceModels_s = 60.0;
constexpr double kAutoStepGridStates_s = 86.5;
double auto_step_s(std::size_t n_objects, bool grid_states = false);

/// auto_step_s for the objects and motion of opt (grid states when opt.motion has them).
double auto_step_s(std::size_t n_objects, const ScreenOptions& opt);

/// Screens [0, span_s]. Objects are validated first (std::invalid_argument on bad input).
ScreenResult screen_robust(const std::vector<SpaceObject>& objects, double span_s,
                           const ScreenOptions& opt);

/// Number of grid steps of a screening of span_s (the unit that parts are made of).
long screen_grid_steps(double span_s, const ScreenOptions& opt, std::size_t n_objects);

/// Part `part` of `parts` (0 <= part < parts) of screen_robust: the grid steps
/// [K part / parts, K (part + 1) / parts) of the K steps. Merging every part's result
/// (merge_screen_results) gives exactly screen_robust's events and stats.
ScreenResult screen_robust_part(const std::vector<SpaceObject>& objects, double span_s,
                                const ScreenOptions& opt, int part, int parts);

/// Appends part's events (re-sorted) and adds its statistics.
void merge_screen_results(ScreenResult& into, const ScreenResult& part);

/// Reference: every pair sampled every sample_step_s; a sign change - to + of the range
/// rate between samples is refined by Brent's method; kept if miss <= D_ij. O(N^2 T).
ScreenResult screen_brute_force(const std::vector<SpaceObject>& objects, double span_s,
                                double sample_step_s, const ScreenOptions& opt);

}  // namespace evade::conjunction
