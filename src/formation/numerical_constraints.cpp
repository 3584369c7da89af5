// Numerically measured constraint deviations (see numerical_constraints.hpp).
#include "evade/formation/numerical_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/core/elements.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::formation {
namespace {

std::pair<std::size_t, int> key(const SatelliteId& id) {
  return {id.group, static_cast<int>(id.role)};
}

// Keeps a slowly varying angle continuous: the branch nearest `ref`.
double near(double angle, double ref) { return ref + wrap_pi(angle - ref); }

}  // namespace

void PropagationSettings::validate() const {
  integrator.validate();
  if (samples_per_rev < 8 || samples_per_rev > 512) {
    throw std::invalid_argument("PropagationSettings.samples_per_rev = " +
                                std::to_string(samples_per_rev) + " outside [8, 512]");
  }
}

FormationPropagator::FormationPropagator(const FormationSpec& spec, const SatelliteId& threatened,
                                         double t_eval_s, const PropagationSettings& settings)
    : spec_(spec), x_(threatened), settings_(settings) {
  settings_.validate();
  defs_ = constraints_for(spec_, x_);  // validates spec
  if (!std::isfinite(t_eval_s) || !(t_eval_s > 0.0) || t_eval_s > 120.0 * kSecondsPerDay) {
    throw std::invalid_argument("FormationPropagator: t_eval_s = " + std::to_string(t_eval_s) +
                                " outside (0, 120 days]");
  }
  t_eval_s_ = t_eval_s;
  const MeanElements& mx = spec_.sat(x_);
  const J2SecularRates rates = j2_secular_rates(mx.a_m, mx.e, mx.i_rad, spec_.earth);
  period_s_ = kTwoPi / rates.arg_latitude_dot_radps;
  n_per_rev_ = settings_.samples_per_rev;
  const double dt = period_s_ / n_per_rev_;
  const auto n_grid = static_cast<std::size_t>(std::ceil((t_eval_s_ + period_s_) / dt)) + 2;
  grid_s_.resize(n_grid);
  for (std::size_t k = 0; k < n_grid; ++k) grid_s_[k] = static_cast<double>(k) * dt;
  for (std::size_t k = 0; k + n_per_rev_ < n_grid; ++k) centres_s_.push_back(grid_s_[k] + 0.5 * period_s_);

  auto add = [&](const SatelliteId& id) {
    if (unmaneuvered_.count(key(id)) != 0) return;
    const StateEci s0 = state_from_mean_elements(spec_.sat(id), spec_.earth);
    const std::vector<StateEci> st =
        propagate_with_burns(s0, grid_s_, {}, spec_.earth, settings_.integrator);
    Angles a;
    a.osc.reserve(st.size());
    for (const StateEci& s : st) a.osc.push_back(osculating_angles(s, spec_.earth.mu_m3ps2));
    unmaneuvered_[key(id)] = std::move(a);
  };
  add(x_);
  for (const ConstraintDef& c : defs_) {
    add(c.first);
    add(c.second);
    q0_.push_back(deviation(c, spec_.sat(c.first), spec_.sat(c.second)));
  }
  for (const ConstraintDef& c : defs_) {
    dev_unmaneuvered_.push_back(averaged_deviation(c, angles_of(c.first), angles_of(c.second)));
  }
}

const FormationPropagator::Angles& FormationPropagator::angles_of(const SatelliteId& id) const {
  return unmaneuvered_.at(key(id));
}

std::vector<double> FormationPropagator::averaged_deviation(const ConstraintDef& c,
                                                            const Angles& first,
                                                            const Angles& second) const {
  const std::size_t n = grid_s_.size();
  // Relative elements per sample, kept continuous.
  std::vector<double> d_raan(n), d_u(n), d_i(n), a1(n), a2(n), i2(n);
  const double raan_ref = wrap_pi(first.osc[0].raan_rad - second.osc[0].raan_rad);
  const double u_ref = wrap_pi(first.osc[0].arg_lat_rad - second.osc[0].arg_lat_rad);
  for (std::size_t k = 0; k < n; ++k) {
    d_raan[k] = near(first.osc[k].raan_rad - second.osc[k].raan_rad, raan_ref);
    d_u[k] = near(first.osc[k].arg_lat_rad - second.osc[k].arg_lat_rad, u_ref);
    d_i[k] = first.osc[k].i_rad - second.osc[k].i_rad;
    a1[k] = first.osc[k].a_m;
    a2[k] = second.osc[k].a_m;
    i2[k] = second.osc[k].i_rad;
  }
  const auto w = static_cast<std::size_t>(n_per_rev_);
  auto avg = [&](const std::vector<double>& v, std::size_t k) {
    double s = 0.5 * (v[k] + v[k + w]);
    for (std::size_t j = 1; j < w; ++j) s += v[k + j];
    return s / static_cast<double>(w);
  };
  std::vector<double> out(centres_s_.size());
  for (std::size_t k = 0; k < centres_s_.size(); ++k) {
    MeanElements s2;
    s2.a_m = avg(a2, k);
    s2.i_rad = avg(i2, k);
    MeanElements f = s2;
    f.a_m = avg(a1, k);
    f.i_rad = s2.i_rad + avg(d_i, k);
    f.raan_rad = avg(d_raan, k);
    f.arg_lat_rad = avg(d_u, k);
    s2.raan_rad = 0.0;
    s2.arg_lat_rad = 0.0;
    out[k] = deviation(c, f, s2);
  }
  return out;
}

std::vector<DeviationSeries> FormationPropagator::series(const std::vector<TangentialBurn>& burns,
                                                         std::vector<AppliedBurn>* applied) const {
  const StateEci s0 = state_from_mean_elements(spec_.sat(x_), spec_.earth);
  const std::vector<StateEci> st =
      propagate_with_burns(s0, grid_s_, burns, spec_.earth, settings_.integrator, applied);
  Angles man;
  man.osc.reserve(st.size());
  for (const StateEci& s : st) man.osc.push_back(osculating_angles(s, spec_.earth.mu_m3ps2));
  std::vector<DeviationSeries> out;
  for (std::size_t r = 0; r < defs_.size(); ++r) {
    const ConstraintDef& c = defs_[r];
    const Angles& f = (c.first == x_) ? man : angles_of(c.first);
    const Angles& s = (c.second == x_) ? man : angles_of(c.second);
    const std::vector<double> dev = averaged_deviation(c, f, s);
    DeviationSeries ds;
    ds.t_s = centres_s_;
    ds.deviation.resize(dev.size());
    for (std::size_t k = 0; k < dev.size(); ++k) {
      double delta = dev[k] - dev_unmaneuvered_[r][k];
      if (c.kind == ConstraintKind::kInterGroupRaan || c.kind == ConstraintKind::kInterGroupPhase) {
        delta = wrap_pi(delta);
      }
      ds.deviation[k] = q0_[r] + delta;
    }
    out.push_back(std::move(ds));
  }
  return out;
}

double value_at(const DeviationSeries& s, double t) {
  if (s.t_s.empty()) throw std::invalid_argument("value_at: empty series");
  if (t <= s.t_s.front()) return s.deviation.front();
  if (t >= s.t_s.back()) return s.deviation.back();
  const auto it = std::upper_bound(s.t_s.begin(), s.t_s.end(), t);
  const std::size_t k = static_cast<std::size_t>(it - s.t_s.begin());
  const double w = (t - s.t_s[k - 1]) / (s.t_s[k] - s.t_s[k - 1]);
  return (1.0 - w) * s.deviation[k - 1] + w * s.deviation[k];
}

}  // namespace evade::formation
