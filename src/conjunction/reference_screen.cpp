// Fine-sampling reference screening with pair skipping (issue 13; see reference_screen.hpp
// for the method and its speed bound; DOP853 dense output: Hairer, Norsett & Wanner,
// Solving ODEs I, sec. II.6; Brent's method: events.hpp).
#include "evade/conjunction/reference_screen.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "evade/dynamics/events.hpp"
#include "evade/dynamics/kepler_propagator.hpp"
#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::conjunction {
namespace {

constexpr double kFloorMarginM = 20e3;

// States of all objects at non-decreasing sample times.
class SampleEphemeris {
 public:
  SampleEphemeris(const std::vector<SpaceObject>& objects, const ScreenOptions& opt)
      : opt_(opt), n_(objects.size()) {
    if (opt.motion) return;  // states from the motion source
    for (const auto& o : objects) {
      if (opt.gravity == GravityModel::kTwoBody) {
        kepler_.emplace_back(o.state, opt.earth.mu_m3ps2);
        continue;
      }
      const EarthModel e = opt.earth;
      auto rhs = [e](double, const Vec6& x) { return orbit_derivative(x, GravityModel::kTwoBodyJ2, e); };
      numeric_.push_back(std::make_unique<Dop853<Vec6>>(rhs, opt.integ));
      numeric_.back()->reset(0.0, o.state.stacked());
    }
  }

  void states_at(double t, double span_s, std::vector<StateEci>& out) {
    const std::size_t n = n_;
    out.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (opt_.motion) {
        out[i] = opt_.motion->state_at(i, t);
        continue;
      }
      if (!kepler_.empty()) {
        out[i] = kepler_[i].state_at(t);
        continue;
      }
      Dop853<Vec6>& in = *numeric_[i];
      while (in.t_s() < t) {
        if (!in.step(span_s)) throw std::runtime_error("reference: " + in.failure_reason());
      }
      out[i] = t == in.t_s() ? StateEci::from_stacked(in.x()) : StateEci::from_stacked(in.dense(t));
    }
  }

  // Sample k (time t) of every object: computed here for the force models; for a motion
  // source each object's state is computed when first asked for (sample()), so objects
  // whose pairs are all skipped cost nothing.
  void advance(long k, double t, double span_s) {
    std::vector<StateEci>& slot = slot_[k & 1];
    if (!opt_.motion) {
      states_at(t, span_s, slot);
      for (const auto& st : slot) check(st);
      return;
    }
    slot.resize(n_);
    stamp_[k & 1].assign(n_, -1);
  }

  const StateEci& sample(std::size_t i, long k, double t) {
    StateEci& st = slot_[k & 1][i];
    if (opt_.motion && stamp_[k & 1][i] != k) {
      st = opt_.motion->state_at(i, t);
      stamp_[k & 1][i] = k;
      check(st);
    }
    return st;
  }

  StateEci near(std::size_t i, double t, const StateEci& s, double t_s) const {
    if (opt_.motion) return opt_.motion->state_at(i, t);
    if (!kepler_.empty()) return kepler_[i].state_at(t);
    return propagate_orbit(s, t - t_s, opt_.gravity, opt_.earth, opt_.integ);
  }

 private:
  void check(const StateEci& s) const {
    if (s.r_eci_m.norm() < opt_.earth.re_m + kFloorMarginM)
      throw std::runtime_error("reference: an object fell below Re + 20 km");
    if (opt_.motion && s.v_eci_mps.norm() > std::sqrt(2.0 * opt_.earth.mu_m3ps2 / (opt_.earth.re_m + kFloorMarginM)))
      throw std::runtime_error("reference: an object exceeds the bound-orbit speed");
  }

  ScreenOptions opt_;
  std::size_t n_ = 0;
  std::vector<StateEci> slot_[2];  // samples k with k & 1 == 0 and == 1
  std::vector<long> stamp_[2];     // motion sources: sample index held, -1 none
  std::vector<KeplerOrbit> kepler_;
  std::vector<std::unique_ptr<Dop853<Vec6>>> numeric_;
};

// Motion sources: a bound orbit at radius >= Re + 20 km has v^2 < 2 mu / (Re + 20 km) =
// v_cap^2; every sample's speed is checked against v_cap, and between samples the speed
// grows by at most 10 m/s^2 x the sample step (|r''| < 10 m/s^2 above Re).
double motion_speed_cap_mps(const ScreenOptions& opt) {
  return std::sqrt(2.0 * opt.earth.mu_m3ps2 / (opt.earth.re_m + kFloorMarginM));
}

// V: bound on every pair's relative speed over the span (see the header).
double relative_speed_bound_mps(const std::vector<SpaceObject>& objects, const ScreenOptions& opt,
                                double sample_step_s) {
  if (opt.motion) return 2.0 * (motion_speed_cap_mps(opt) + 10.0 * sample_step_s);
  const double mu = opt.earth.mu_m3ps2, re = opt.earth.re_m;
  const double j2 = opt.gravity == GravityModel::kTwoBodyJ2 ? opt.earth.j2 : 0.0;
  double v2_max = 0.0;
  for (const auto& o : objects) {
    const double r = o.state.r_eci_m.norm();
    const double s = o.state.r_eci_m.z() / r;
    const double pot = -mu / r + mu * j2 * re * re / (r * r * r) * 0.5 * (3.0 * s * s - 1.0);
    const double energy = 0.5 * o.state.v_eci_mps.squaredNorm() + pot;
    v2_max = std::max(v2_max, 2.0 * energy + 2.0 * mu / re + mu * j2 / re);
  }
  return 2.0 * 1.01 * std::sqrt(v2_max);
}


double range_rate(const StateEci& a, const StateEci& b) {
  return (b.r_eci_m - a.r_eci_m).dot(b.v_eci_mps - a.v_eci_mps);
}

void check_motion_and_primary(const ScreenOptions& opt, std::size_t n) {
  if (opt.motion && opt.motion->size() != n) throw std::invalid_argument("reference: motion size != objects");
  if (opt.primary >= static_cast<long>(n)) throw std::invalid_argument("reference: primary outside the objects");
}

struct PairIndex {
  std::uint32_t i, j;
};

// Calendar of pending sign tests: bucket k % kRing holds the pairs due at sample k; every
// screened pair is first due at sample 1.
constexpr std::size_t kRing = 4096;

std::vector<std::vector<PairIndex>> initial_calendar(std::size_t n, const ScreenOptions& opt) {
  std::vector<std::vector<PairIndex>> due(kRing);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      if (opt.screens_pair(i, j)) due[1].push_back({i, j});
  return due;
}

// The range rate of pair p turned from < 0 at t_prev (states gi, gj) to >= 0 at t: Brent's
// root is the TCA; an event when its miss is within the pair's distance limit d_ij.
void solve_tca(const std::vector<SpaceObject>& objects, const ScreenOptions& opt,
               SampleEphemeris& eph, const PairIndex& p, double t_prev, double t,
               const StateEci& gi, const StateEci& gj, double fp, double fc, double d_ij,
               ScreenResult& res) {
  ++res.stats.root_solves;
  auto f = [&](double tt) { return range_rate(eph.near(p.i, tt, gi, t_prev), eph.near(p.j, tt, gj, t_prev)); };
  const double tca = brent_root(f, t_prev, t, fp, fc, opt.tca_tol_s, 200);
  const StateEci si = eph.near(p.i, tca, gi, t_prev), sj = eph.near(p.j, tca, gj, t_prev);
  const double miss = (sj.r_eci_m - si.r_eci_m).norm();
  if (miss <= d_ij) {
    const double rc = collision_radius_m(objects[p.i], objects[p.j]);
    res.events.push_back(Conjunction{p.i, p.j, tca, miss, (sj.v_eci_mps - si.v_eci_mps).norm(),
                                     miss <= rc, miss <= opt.warning_multiple * rc});
  }
}

}  // namespace

ScreenResult screen_reference(const std::vector<SpaceObject>& objects, double span_s,
                              double sample_step_s, const ScreenOptions& opt) {
  opt.validate();
  if (!(sample_step_s > 0.0) || !(span_s > 0.0)) throw std::invalid_argument("reference: bad steps");
  validate_objects(objects, opt.earth);
  ScreenResult res;
  const std::size_t n = objects.size();
  if (n < 2) return res;
  SampleEphemeris eph(objects, opt);
  const double v_rel = relative_speed_bound_mps(objects, opt, sample_step_s);
  const long nsteps = static_cast<long>(std::ceil(span_s / sample_step_s - 1e-12));
  auto time_of = [&](long k) { return k >= nsteps ? span_s : static_cast<double>(k) * sample_step_s; };
  check_motion_and_primary(opt, n);
  std::vector<std::vector<PairIndex>> due = initial_calendar(n, opt);
  eph.advance(0, 0.0, span_s);
  std::vector<PairIndex> now;
  for (long k = 1; k <= nsteps; ++k) {
    const double t = time_of(k), t_prev = time_of(k - 1);
    eph.advance(k, t, span_s);
    ++res.stats.steps;
    now.swap(due[static_cast<std::size_t>(k) % kRing]);
    for (const PairIndex& p : now) {
      ++res.stats.pairs_checked;
      const double d_ij = pair_threshold_m(opt, collision_radius_m(objects[p.i], objects[p.j]));
      const StateEci gi = eph.sample(p.i, k - 1, t_prev), gj = eph.sample(p.j, k - 1, t_prev);
      const StateEci& ci = eph.sample(p.i, k, t);
      const StateEci& cj = eph.sample(p.j, k, t);
      const double fp = range_rate(gi, gj);
      const double fc = range_rate(ci, cj);
      if (fp < 0.0 && fc >= 0.0) solve_tca(objects, opt, eph, p, t_prev, t, gi, gj, fp, fc, d_ij, res);
      // Intervals (t_k, t_k+m] with t_k+m < t_k + (d - D) / V cannot hold a miss <= D.
      const double d = (cj.r_eci_m - ci.r_eci_m).norm();
      const double free_steps = (d - d_ij) / (v_rel * sample_step_s);
      long m = free_steps > 0.0 ? static_cast<long>(std::ceil(free_steps)) - 1 : 0;
      m = std::clamp(m, 0L, static_cast<long>(kRing) - 2);
      if (k + m + 1 <= nsteps) due[static_cast<std::size_t>(k + m + 1) % kRing].push_back(p);
    }
    now.clear();
  }
  std::sort(res.events.begin(), res.events.end(), [](const Conjunction& a, const Conjunction& b) {
    if (a.tca_s != b.tca_s) return a.tca_s < b.tca_s;
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  return res;
}

}  // namespace evade::conjunction
