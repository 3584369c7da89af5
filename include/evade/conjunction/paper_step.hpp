// Paper 002's self-adaptive simulation step (section 2, eq. 3-5 and the `Step` procedure),
// with our corrected reading of the printed pseudo-code.
//
// Reference: Wang Xiaoyu, J. Air Force Eng. Univ. 7(6), 2006 (paper 002).
//   dR = R_j - R_i, dV = V_j - V_i (eq. 3); radial speed V_R = dR.dV/|dR| (eq. 4);
//   time to encounter T = |dR| / |V_R| (eq. 5); warning period T_CA = M h_now.
//   Step rule for one pair, given the step h_now that led to the current sample:
//     not approaching (dR.dV >= 0)       -> h_next = min(h_sim, L_E h_now)
//     approaching, no collision, T > T_CA -> h_next = h_now
//     approaching, no collision, T <= T_CA-> h_next = h_now / L_D
//     collision (|dR| <= R_c, eq. 2)      -> h_next = h_sim
//   Several objects: the smallest h_next over all pairs (section 2, last paragraph).
// Two defects of the printed pseudo-code are corrected (docs/VALIDATION.md):
//  (1) it calls dR.dV > 0 "approaching"; with dR = R_j - R_i approaching is dR.dV < 0;
//  (2) its first line `h_now = h_sim` is the initialization of the run, not a reset at each
//      call (taken literally the step never shrinks below h_sim and nothing is flagged).
// This rule is a heuristic: it samples the encounter geometrically and flags a collision
// only if a sample happens to fall inside R_c (it does in the paper's head-on case). It can
// miss approaches (robust_screen.hpp is the mode that cannot).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "evade/conjunction/ephemeris.hpp"
#include "evade/conjunction/types.hpp"
#include "evade/core/param.hpp"

namespace evade::conjunction {

struct PaperStepParams {
  double h_sim_s = 60.0;         ///< nominal (initial) simulation step h_sim [s]
  double n_warning = 5.0;        ///< N: warning radius = N R_c, N > 1
  double m_warning_period = 3.0; ///< M: warning period T_CA = M h_now, M > 1
  double l_enlarge = 5.0;        ///< L_E > 1: step growth factor
  double l_reduce = 5.0;         ///< L_D > 1: step reduction factor
  double h_min_s = 1e-9;         ///< floor on the step (guards a stuck run) [s]
  /// Reproduce the printed pseudo-code's defects, to show what they do (default: off).
  bool literal_sign = false;   ///< defect 1: "approaching" when dR.dV > 0
  bool literal_reset = false;  ///< defect 2: h_now = h_sim at every call
  /// Throws std::invalid_argument naming the parameter, value and allowed range (the
  /// table's rows as "paper_step.<key>").
  void validate() const;
};

/// The scenario's `paper_step.*` rows: h_sim_s, n_warning, m_warning_period, l_enlarge,
/// l_reduce (h_min_s and the literal_* switches are not scenario keys).
ParamTable<PaperStepParams> paper_step_params() noexcept;

/// Geometry of one pair at one sample.
struct PairSample {
  double distance_m = 0.0;        ///< |dR|
  double radial_speed_mps = 0.0;  ///< dR.dV/|dR|: < 0 approaching (eq. 4)
  double rel_speed_mps = 0.0;     ///< |dV|
  bool collision = false;         ///< |dR| <= R_c (eq. 2)
  bool warning = false;           ///< |dR| <= N R_c
};

PairSample sample_pair(const StateEci& si, const StateEci& sj, double rc_m, double n_warning);

/// The corrected `Step` rule for one pair (see the file comment).
double paper_next_step_s(const PairSample& p, double h_now_s, const PaperStepParams& prm);

/// One simulation sample: t_s reached with step_s (the step used to get there; h_sim at
/// t = 0), as in the paper's Table 2; geometry of the pair that set the next step.
struct TraceRow {
  double t_s = 0.0;
  double step_s = 0.0;
  std::size_t i = 0;
  std::size_t j = 1;
  double distance_m = 0.0;
  double radial_speed_mps = 0.0;
  bool collision = false;
  bool warning = false;
};

struct PaperResult {
  /// Collisions flagged at samples (tca_s = sample time, miss_m = sampled distance), and
  /// for encounters that entered the warning radius without a collision sample, the
  /// closest warning sample of that encounter.
  std::vector<Conjunction> events;
  long steps = 0;               ///< number of samples after t = 0
  std::vector<TraceRow> trace;  ///< every sample (when requested)
};

/// Runs the adaptive simulation over [0, span_s] (samples while t <= span_s). `progress`
/// (may be empty) is called with the fraction of the span done, at most every 1 %.
PaperResult screen_paper(const std::vector<SpaceObject>& objects, double span_s,
                         const PaperStepParams& prm, Ephemeris& eph, bool record_trace,
                         const std::function<void(double)>& progress = {});

}  // namespace evade::conjunction
