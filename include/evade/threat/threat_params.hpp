// The threat-area command's parameters (paper 001, Yu, Wang, Sun 2017): the one declaration
// of each scenario key's unit, range and meaning (evade/core/param.hpp).
//
// The scenario groups the inputs by object (target., chaser., transfer., sweep., evasion.,
// elimination.) while the solvers take ThreatGeometry, ThreatOptions and EvasionOptions. Each
// table below is therefore over a struct laid out like the scenario, so that a field's path
// is its key (`transfer.dt_s`), and converts to the solver's struct: the geometry's scalars
// (sec. 4.1: circular target orbit), the sweep options (sec. 2.1–2.2: ΔV_max, ΔT, N, the
// 5 s step) and the evasion search (sec. 3.2 and 4.2: V_E, the optimizer's budget and the
// direction bounds in degrees). Read with prefix "" (the keys carry their section) by
// read_threat_scenario (threat_scenario.hpp). The two RSW vectors of the chaser are lists
// and are read beside the tables.
#pragma once

#include <cstdint>

#include "evade/core/constants.hpp"
#include "evade/core/param.hpp"
#include "evade/core/state.hpp"
#include "evade/threat/evasion.hpp"
#include "evade/threat/threat_area.hpp"

namespace evade::threat {

/// The geometry's scalar keys. Defaults: paper 001's target (sec. 4.1).
struct ThreatGeometryParams {
  struct Target {
    double altitude_m = 370000.0;  ///< circular orbit altitude above earth.re_m (required key)
    double inclination_deg = 0.0;  ///< for the record: HCW does not use it
  } target;

  /// Throws std::invalid_argument naming the first bad key (param_error text).
  void validate() const;
  /// Mean motion n = √(μ / (Re + h)³) of the target's circular orbit and the chaser's RSW
  /// state relative to the target at t0; the target starts at the origin.
  ThreatGeometry geometry(const EarthModel& earth, const Vec6& chaser0_rsw) const;
};

/// The sweep's keys (→ ThreatOptions). Defaults: ThreatOptions's.
struct ThreatOptionParams {
  struct Chaser {
    double dv_max_mps = 324.0;  ///< ΔV_max (required key)
  } chaser;
  struct Transfer {
    double dt_s = 2200.0;  ///< ΔT (required key)
    int impulses = 3;      ///< N (required key)
  } transfer;
  struct Sweep {
    double step_s = 5.0;
    double edge_tol_s = 0.05;
    int threads = 2;
  } sweep;

  /// Throws std::invalid_argument naming the first bad key (param_error text).
  void validate() const;
  /// The solver's options (span one chaser period, default SQP settings).
  ThreatOptions options() const;
};

/// The evasion search's keys (→ EvasionOptions, V_E, the elimination tolerance).
struct EvasionParams {
  struct Evasion {
    double dv_mps = 20.0;  ///< V_E of the single optimization (the paper's timing case)
    bool use_isres = false;
    int population = 60;
    int max_evaluations = 1200;
    std::uint64_t seed = 1;
    double alpha_min_deg = -90.0;
    double alpha_max_deg = 90.0;
    double theta_min_deg = -180.0;
    double theta_max_deg = 180.0;
    int sweep_alpha_cells = 8;
    int sweep_theta_cells = 16;
    double sweep_edge_tol_s = 2.0;
    int local_starts = 3;
    double local_xtol_rad = 1e-4;
    int certify_max_cells = 3000;
    double certify_rel_tol = 1e-3;
  } evasion;
  struct Elimination {
    double tol_mps = 0.05;
  } elimination;

  /// Throws std::invalid_argument naming the first bad key (param_error text).
  void validate() const;
  /// The optimizer's options (angles in radians).
  EvasionOptions options() const;
};

/// target.altitude_m, target.inclination_deg.
ParamTable<ThreatGeometryParams> threat_geometry_params() noexcept;
/// chaser.dv_max_mps, transfer.dt_s, transfer.impulses, sweep.step_s, sweep.edge_tol_s,
/// sweep.threads.
ParamTable<ThreatOptionParams> threat_option_params() noexcept;
/// evasion.dv_mps, evasion.use_isres, evasion.population, evasion.max_evaluations,
/// evasion.seed, evasion.{alpha,theta}_{min,max}_deg, the sweep search's evasion.sweep_*,
/// evasion.local_*, evasion.certify_*, and elimination.tol_mps.
ParamTable<EvasionParams> evasion_params() noexcept;

}  // namespace evade::threat
