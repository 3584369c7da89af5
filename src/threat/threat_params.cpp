// The threat-area command's parameter tables (include/evade/threat/threat_params.hpp). Paper
// 001 (Yu, Wang, Sun 2017): sec. 4.1 (the target's orbit), sec. 2.1–2.2 (ΔV_max, ΔT, N
// impulses of eq. 1–3, the 5 s search step of eq. 6), sec. 3.1–3.2 (V_E and the direction
// angles α, θ of eq. 4; the GA's population 60 × 20 generations) and sec. 4.2 (the smallest
// eliminating V_E). The ranges are those the command has always accepted.
#include "evade/threat/threat_params.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace evade::threat {
namespace {

using G = ThreatGeometryParams;
using T = ThreatOptionParams;
using E = EvasionParams;

const Param<G> kGeometryRows[] = {
    EVADE_PARAM_REAL(G, target.altitude_m, "m", 1e5, 1e8, false,
                     "altitude of the target's circular orbit above earth.re_m (required)"),
    EVADE_PARAM_REAL(G, target.inclination_deg, "deg", 0.0, 180.0, false,
                     "target's inclination, for the record (HCW does not use it)"),
};

const Param<T> kOptionRows[] = {
    EVADE_PARAM_REAL(T, chaser.dv_max_mps, "m/s", 1e-6, 1e5, false,
                     "chaser's delta-v capacity DeltaV_max (required)"),
    with_flag(EVADE_PARAM_REAL(T, transfer.dt_s, "s", 1e-3, 1e6, false,
                               "chaser's fixed transfer time DeltaT (required)"),
              "--dt-transfer-s", "--dt-transfer"),
    with_flag(EVADE_PARAM_INT(T, transfer.impulses, "-", 2, 4, "chaser's impulses N (required)"),
              "--impulses"),
    EVADE_PARAM_REAL(T, sweep.step_s, "s", 1e-3, 1e5, false,
                     "step of the departure-time sweep over one chaser period"),
    EVADE_PARAM_REAL(T, sweep.edge_tol_s, "s", 0.0, 1e4, false,
                     "bisection tolerance of interval edges (0: grid only)"),
    EVADE_PARAM_INT(T, sweep.threads, "-", 1, 64, "threads of the sweep"),
};

const Param<E> kEvasionRows[] = {
    with_flag(EVADE_PARAM_REAL(E, evasion.dv_mps, "m/s", 0.0, 1e5, false,
                               "target's evasion burn V_E of the single optimization"),
              "--dv-mps", "--dv"),
    EVADE_PARAM_BOOL(E, evasion.use_isres,
                     "search the direction with ISRES (the paper's GA) instead of the sweep"),
    EVADE_PARAM_INT(E, evasion.population, "-", 2, 100000, "ISRES population"),
    EVADE_PARAM_INT(E, evasion.max_evaluations, "-", 1, 100000000,
                    "cap of threat-area evaluations of one direction search"),
    EVADE_PARAM_SEED(E, evasion.seed,
                     "ISRES random seed; the sweep's sample position inside each cell"),
    EVADE_PARAM_REAL(E, evasion.alpha_min_deg, "deg", -90.0, 90.0, false,
                     "lower bound of the pitch alpha (elevation, + toward the zenith)"),
    EVADE_PARAM_REAL(E, evasion.alpha_max_deg, "deg", -90.0, 90.0, false,
                     "upper bound of the pitch alpha"),
    EVADE_PARAM_REAL(E, evasion.theta_min_deg, "deg", -180.0, 180.0, false,
                     "lower bound of the yaw theta (azimuth from the velocity toward VVLH +y)"),
    EVADE_PARAM_REAL(E, evasion.theta_max_deg, "deg", -180.0, 180.0, false,
                     "upper bound of the yaw theta"),
    EVADE_PARAM_INT(E, evasion.sweep_alpha_cells, "-", 1, 1000,
                    "sweep cells in sin(alpha) (equal-area cells)"),
    EVADE_PARAM_INT(E, evasion.sweep_theta_cells, "-", 4, 1000, "sweep cells in theta"),
    EVADE_PARAM_REAL(E, evasion.sweep_edge_tol_s, "s", 0.0, 1e4, false,
                     "edge tolerance of the sweep's ranking evaluations (coarser is cheaper)"),
    EVADE_PARAM_INT(E, evasion.local_starts, "-", 0, 100,
                    "BOBYQA refinements from the best separated sweep cells"),
    EVADE_PARAM_REAL(E, evasion.local_xtol_rad, "rad", 0.0, 1.0, true,
                     "BOBYQA stop: step in sin(alpha) and theta"),
    EVADE_PARAM_INT(E, evasion.certify_max_cells, "-", 0, 100000000,
                    "lower-bound computations of the certificate (0: no certificate)"),
    EVADE_PARAM_REAL(E, evasion.certify_rel_tol, "-", 0.0, 0.5, true,
                     "certified when no direction's arc can be below (1 - tol) x best"),
    EVADE_PARAM_REAL(E, elimination.tol_mps, "m/s", 1e-6, 1e3, false,
                     "bisection tolerance of the eliminating V_E"),
};

template <class Cfg>
void throw_if_invalid(const ParamTable<Cfg>& table, const Cfg& cfg) {
  const std::string error = validate_params(table, cfg, "");
  if (!error.empty()) throw std::invalid_argument(error);
}

}  // namespace

ParamTable<ThreatGeometryParams> threat_geometry_params() noexcept {
  return make_param_table(kGeometryRows);
}
ParamTable<ThreatOptionParams> threat_option_params() noexcept {
  return make_param_table(kOptionRows);
}
ParamTable<EvasionParams> evasion_params() noexcept { return make_param_table(kEvasionRows); }

void ThreatGeometryParams::validate() const { throw_if_invalid(threat_geometry_params(), *this); }
void ThreatOptionParams::validate() const { throw_if_invalid(threat_option_params(), *this); }
void EvasionParams::validate() const { throw_if_invalid(evasion_params(), *this); }

ThreatGeometry ThreatGeometryParams::geometry(const EarthModel& earth,
                                              const Vec6& chaser0_rsw) const {
  ThreatGeometry g;
  const double a_m = earth.re_m + target.altitude_m;
  g.n_radps = std::sqrt(earth.mu_m3ps2 / (a_m * a_m * a_m));
  g.chaser0_rsw = chaser0_rsw;
  return g;
}

ThreatOptions ThreatOptionParams::options() const {
  ThreatOptions o;
  o.dv_max_mps = chaser.dv_max_mps;
  o.transfer_s = transfer.dt_s;
  o.impulses = transfer.impulses;
  o.step_s = sweep.step_s;
  o.edge_tol_s = sweep.edge_tol_s;
  o.threads = sweep.threads;
  return o;
}

EvasionOptions EvasionParams::options() const {
  EvasionOptions o;
  o.use_isres = evasion.use_isres;
  o.population = evasion.population;
  o.max_evaluations = evasion.max_evaluations;
  o.seed = evasion.seed;
  o.alpha_min_rad = evasion.alpha_min_deg * kDegToRad;
  o.alpha_max_rad = evasion.alpha_max_deg * kDegToRad;
  o.theta_min_rad = evasion.theta_min_deg * kDegToRad;
  o.theta_max_rad = evasion.theta_max_deg * kDegToRad;
  o.sweep_alpha_cells = evasion.sweep_alpha_cells;
  o.sweep_theta_cells = evasion.sweep_theta_cells;
  o.sweep_edge_tol_s = evasion.sweep_edge_tol_s;
  o.local_starts = evasion.local_starts;
  o.local_xtol_rad = evasion.local_xtol_rad;
  o.certify_max_cells = evasion.certify_max_cells;
  o.certify_rel_tol = evasion.certify_rel_tol;
  return o;
}

}  // namespace evade::threat
