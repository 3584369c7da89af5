// Which Pc to trust: the usage checks of the 2D method and of 3D-Nc, and the escalation
// 2D -> 3D-Nc -> Monte Carlo.
//
// D. Hall, L. Baars, S. Casali, "A multistep probability of collision computational
// algorithm", AAS 23-398, 2023 (NASA CARA's multistep Pc), whose usage checks these are:
// 2D (rectilinear encounter; with A the combined position covariance, r, v the relative
// position and velocity at TCA): the time of the smallest Mahalanobis distance
// T = -r'A^-1 v / v'A^-1 v, its 1-sigma width s = (v'A^-1 v)^-1/2, the conjunction bounds
// Ta,b = T -+ s sqrt(2) erfcinv(gamma);
//   extended = min(1, (Tb - Ta) / P_min)    (the encounter lasts a sizeable part of an orbit)
//   offset   = min(1, max(|Ta|, |Tb|) / P_min)  (it reaches far from the 2D plane's TCA)
//   npd      = a covariance was repaired before the Pc (its smallest eigenvalue was <= 0)
// and the Chan/Alfano short-term check (assess.hpp) beside them. 3D-Nc (pc_3d_nc.hpp): with
// [TA, TB] the encounter segment (the relative-distance maxima of the mean two-body
// trajectories on either side of TCA) and [Ta, Tb] the conjunction span (the times holding all
// but 5e-7 of Nc on each side, CARA's TaConj, TbConj; within [TA, TB]):
//   extended = (Tb - Ta) / (TB - TA),  offset = max(Ta / TA, Tb / TB),  converged.
// The recommended Pc is the 2D value when no 2D check fails; else 3D-Nc (6x6 covariances
// needed) when it converged and no 3D-Nc check fails; else the Monte Carlo (monte_carlo_pc.hpp)
// over the 3D-Nc window, run to the target relative accuracy.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evade/assessment/assess.hpp"
#include "evade/assessment/pc_3d_nc.hpp"
#include "evade/assessment/pc_methods.hpp"

namespace evade::assessment {

/// The encounter segment and conjunction span of a 3D-Nc result [s about TCA].
struct Nc3dSpans {
  double segment_begin_s = 0.0, segment_end_s = 0.0;  ///< TA, TB
  double conj_begin_s = 0.0, conj_end_s = 0.0;        ///< Ta, Tb
};

struct PcChoice {
  double pc = 0.0;
  std::string method;  ///< the recommended row's name (pc_methods.hpp): "2d", "3d_nc" or "mc"
  std::vector<PcStep> steps;         ///< the escalation's steps as they ran, in table order
  std::optional<Nc3dResult> nc3d;    ///< when 3D-Nc ran
  std::optional<Nc3dSpans> spans;    ///< TA, TB, Ta, Tb of the 3D-Nc checks
  std::optional<MonteCarloResult> mc;  ///< when the escalation ran the Monte Carlo
  std::string why;                     ///< one line: why this method
  /// The step of m, or nullptr when it did not run.
  const PcStep* step(PcMethod m) const;
};

/// What an escalation step sees (pc_methods.hpp's PcMethodRow::escalate).
struct PcStepInput {
  const Assessment& a;
  double hbr_m;
  const AssessConfig& cfg;
  const EarthModel& earth;
  const McExecution& exec;
};

/// The escalation's steps (rows of pc_methods.hpp): the 2D value and its usage checks; 3D-Nc
/// and its checks (c->nc3d, c->spans); the Monte Carlo over the 3D-Nc window (c->mc; the
/// assessment's own Monte Carlo when the caller asked for one).
PcStep escalate_2d(const PcStepInput& in, PcChoice* c);
PcStep escalate_3d_nc(const PcStepInput& in, PcChoice* c);
PcStep escalate_mc(const PcStepInput& in, PcChoice* c);

/// A Monte Carlo's Pc as the outputs report it (its Wilson interval as the figures).
PcValue monte_carlo_value(const MonteCarloResult& mc);

/// The 2D usage checks of an assessment from states.
std::vector<UsageFlag> usage_2d(const Assessment& a, double hbr_m, const AssessConfig& cfg,
                                const EarthModel& earth);

/// TA, TB of the mean trajectories (two-body), at most one period of the shorter orbit from
/// TCA on each side; Ta, Tb as above.
Nc3dSpans nc3d_spans(const Assessment& a, const Nc3dResult& nc, const EarthModel& earth);

/// The 3D-Nc usage checks.
std::vector<UsageFlag> usage_3d_nc(const Nc3dResult& nc, const Nc3dSpans& s,
                                   const AssessConfig& cfg);

/// Runs the escalation on an assessment from states: the rows of pc_methods() with a step, in
/// order, those that need 6x6 covariances only with six_by_six; the first whose usage checks
/// hold is recommended. exec: how its Monte Carlo runs; a Monte Carlo already in the
/// assessment (asked for by the caller) is the escalation's, not rerun. every_method: the
/// steps marked every_method (3D-Nc) run even after an earlier recommendation.
PcChoice choose_pc(const Assessment& a, double hbr_m, const AssessConfig& cfg,
                   const EarthModel& earth, bool six_by_six, const McExecution& exec = {},
                   bool every_method = false);

}  // namespace evade::assessment
