// SDP4 deep-space terms (orbital period >= 225 min): lunar-solar periodics, lunar-solar
// secular rates, and the 12 h / 24 h geopotential resonances integrated with the theory's
// fixed 720 min Euler-Maclaurin step. Vallado, Crawford, Hujsak & Kelso (2006), "Revisiting
// Spacetrack Report #3", AIAA 2006-6753, sections on dscom, dpper, dsinit and dspace
// (Hoots & Roehrich 1980, STR#3, eq. for the deep-space model). Units: Earth radii, minutes,
// radians. Written from the paper's description and its published equations.
#pragma once

#include <vector>

namespace evade::sgp4 {

enum class OperationMode : char;

/// How far from the epoch the resonance checkpoints reach (60 days; later times resume from
/// the last one) [min].
constexpr double kResonanceCheckpointHorizonMin = 86400.0;

/// Coefficients of the lunar-solar periodic terms (dscom outputs kept for dpper).
struct LunarSolarPeriodics {
  double e3 = 0, ee2 = 0, se2 = 0, se3 = 0;
  double sgh2 = 0, sgh3 = 0, sgh4 = 0, sh2 = 0, sh3 = 0;
  double si2 = 0, si3 = 0, sl2 = 0, sl3 = 0, sl4 = 0;
  double xgh2 = 0, xgh3 = 0, xgh4 = 0, xh2 = 0, xh3 = 0;
  double xi2 = 0, xi3 = 0, xl2 = 0, xl3 = 0, xl4 = 0;
  double zmol = 0, zmos = 0;  ///< lunar and solar mean anomalies at epoch (rad)
};

/// Resonance state at epoch (dsinit): irez 0 none, 1 synchronous (24 h), 2 half-day (12 h).
struct Resonance {
  int irez = 0;
  double d2201 = 0, d2211 = 0, d3210 = 0, d3222 = 0, d4410 = 0;
  double d4422 = 0, d5220 = 0, d5232 = 0, d5421 = 0, d5433 = 0;
  double del1 = 0, del2 = 0, del3 = 0;
  double xfact = 0, xlamo = 0;
};

/// The resonance integrator's state after a whole number of 720 min steps from the epoch,
/// and (in DeepSpaceTerms::checkpoints) the loop's rates there, as it computes them.
struct ResonanceCheckpoint {
  double atime = 0;  ///< min from epoch
  double xli = 0;
  double xni = 0;
  double xndt = 0, xldot = 0, xnddt = 0;  ///< the resonance rates at this state
};

struct DeepSpaceTerms {
  LunarSolarPeriodics periodics;
  Resonance resonance;
  /// Resonant orbits: the integrator's state after k = 0, 1, ... steps toward t > 0, over
  /// the first kResonanceCheckpointHorizonMin (dspace's own loop, run once at initialisation
  /// so that a call at t resumes from the last whole step before it; empty otherwise).
  std::vector<ResonanceCheckpoint> checkpoints;
  double dedt = 0, didt = 0, dmdt = 0, dnodt = 0, domdt = 0;  ///< lunar-solar secular rates
};

/// Epoch elements and near-Earth secular rates the deep-space initialisation needs.
struct DeepSpaceEpoch {
  double epoch_days_1950 = 0;  ///< days since 1950 Jan 0.0 UTC
  double ecco = 0, inclo = 0, nodeo = 0, argpo = 0, mo = 0;
  double no_unkozai = 0;        ///< rad/min
  double mdot = 0, nodedot = 0, argpdot = 0;
  double gsto = 0;              ///< Greenwich sidereal angle at epoch (rad)
  double xke = 0;
};

/// dscom + dsinit: every deep-space coefficient at epoch.
DeepSpaceTerms deep_space_init(const DeepSpaceEpoch& ep);

/// Mean elements being advanced by dspace (in: secular near-Earth values; out: with the
/// lunar-solar secular rates and the resonance integration applied).
struct DeepSpaceMean {
  double em = 0, argpm = 0, inclm = 0, mm = 0, nodem = 0, nm = 0;
};

/// dspace: lunar-solar secular terms and resonance integration from epoch to t (min).
/// Stateless: integrates from epoch on the reference's 720 min grid (its stored integrator
/// state restarts on the same grid), resuming from ds.checkpoints, which hold that same
/// loop's states, so the numbers are the reference's bit for bit.
void deep_space_secular(const DeepSpaceTerms& ds, const DeepSpaceEpoch& ep, double t_min,
                        DeepSpaceMean& m);

/// Elements after the lunar-solar periodics (dpper, init = 'n').
struct PerturbedElements {
  double ep = 0, inclp = 0, nodep = 0, argpp = 0, mp = 0;
};

/// dpper: adds the lunar-solar periodics at t (min); the Lyddane modification below 0.2 rad
/// inclination, with the node handling of the chosen operation mode.
void deep_space_periodics(const LunarSolarPeriodics& p, double t_min, OperationMode mode,
                          PerturbedElements& e);

}  // namespace evade::sgp4
