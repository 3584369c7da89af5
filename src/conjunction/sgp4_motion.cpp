// SGP4 motion of a catalog for the screeners (issue 12; see sgp4_motion.hpp). SGP4/SDP4:
// Vallado, Crawford, Hujsak & Kelso (2006), AIAA 2006-6753 (evade/sgp4). Central and second
// differences: e.g. Atkinson, An Introduction to Numerical Analysis, 2nd ed., sec. 5.7.
// The perturbation envelope and what it assumes: docs/VALIDATION.md, "Robust mode with SGP4
// motion".
// This file: the motion's states, lane groups and accelerations. The envelopes are
// sgp4_motion_envelope.cpp, the option checks sgp4_motion_options.cpp, the catalog's motion is
// built by sgp4_catalog_builder.cpp.
#include "evade/conjunction/sgp4_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>


#include "evade/conjunction/internal/sgp4_motion_support.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/sgp4/gravity_constants.hpp"

namespace evade::conjunction {
namespace {

using internal::fmt;
using internal::label;
using internal::sgp4_error_label;

// Position at t_s seconds from the element epoch, or the SGP4 error text.
struct Position {
  bool ok = false;
  Vec3 r;
  std::string error;
};

Position position(const sgp4::Sgp4Propagator& p, double t_s) {
  const sgp4::Sgp4State s = p.propagate_s(t_s);
  Position out;
  out.ok = s.error == sgp4::Sgp4Error::kNone;
  out.r = s.r_teme_m;
  if (!out.ok) {
    out.error = sgp4_error_label(s.error);
  }
  return out;
}

}  // namespace

std::string RejectedElementSet::message() const { return label(norad_id, name) + ": " + reason; }

EarthModel wgs72_earth() {
  const sgp4::GravityConstants k = sgp4::gravity_constants(sgp4::GravityModel::kWgs72);
  EarthModel e;
  e.mu_m3ps2 = k.mu_km3ps2 * 1e9;
  e.re_m = k.radius_km * 1e3;
  e.j2 = k.j2;
  return e;
}

EarthModel Sgp4Motion::reference_earth() const { return wgs72_earth(); }

StateEci Sgp4Motion::state_at(std::size_t i, double t_s) const {
  const double t = offset_s_[i] + t_s, tau = velocity_step_s_;
  const Position a = position(props_[i], t - tau), b = position(props_[i], t),
                 c = position(props_[i], t + tau);
  if (!a.ok || !b.ok || !c.ok) {
    throw std::runtime_error("SGP4 motion: " + label(norad_[i], names_[i]) + ": " +
                             (!b.ok ? b.error : !a.ok ? a.error : c.error) + " at t = " +
                             fmt(t_s) + " s from the start");
  }
  return StateEci{b.r, (c.r - a.r) / (2.0 * tau)};
}

StateEci Sgp4Motion::grid_state_at(std::size_t i, double t_s) const {
  const sgp4::Sgp4State s = props_[i].propagate_s(offset_s_[i] + t_s);
  if (s.error != sgp4::Sgp4Error::kNone) return state_at(i, t_s);  // throws naming the error
  return StateEci{s.r_teme_m, s.v_teme_mps};
}

void Sgp4Motion::grid_states_at(double t_s, std::size_t begin, std::size_t end,
                                StateEci* out) const {
  const std::size_t windows = window_first_group_.empty() ? 0 : window_first_group_.size() - 1;
  for (std::size_t i = begin; i < end;) {
    const std::size_t w = i / kLaneWindow, w0 = w * kLaneWindow;
    const std::size_t w1 = std::min(size(), w0 + kLaneWindow);
    if (i == w0 && w1 <= end && w < windows) {  // a whole window: its prepared groups
      window_states(w, t_s, out);
      i = w1;
    } else {
      const std::size_t j = std::min(end, w1);
      grouped_states(t_s, i, j, out);
      i = j;
    }
  }
}

void Sgp4Motion::window_states(std::size_t w, double t_s, StateEci* out) const {
  const std::size_t w0 = w * kLaneWindow, w1 = std::min(size(), w0 + kLaneWindow);
  scalar_states(t_s, w0, w1, out);
  for (std::size_t g = window_first_group_[w]; g < window_first_group_[w + 1]; ++g)
    group_states(groups_[g], group_lanes_[g], t_s, out);
}

void Sgp4Motion::grouped_states(double t_s, std::size_t begin, std::size_t end,
                                StateEci* out) const {
  scalar_states(t_s, begin, end, out);
  for (const LaneGroup& lg : lane_groups(begin, end)) group_states(lg, lanes_of(lg), t_s, out);
}

void Sgp4Motion::scalar_states(double t_s, std::size_t begin, std::size_t end, StateEci* out) const {
  for (std::size_t i = begin; i < end; ++i)
    if (!four_lane(i)) out[i] = grid_state_at(i, t_s);
}

void Sgp4Motion::group_states(const LaneGroup& lg, const sgp4::Sgp4X4Lanes& lanes, double t_s,
                              StateEci* out) const {
  const sgp4::Sgp4Propagator* p[4];
  double tsince_min[4], r[4][3], v[4][3];
  bool ok[4];
  for (std::size_t k = 0; k < 4; ++k) {
    p[k] = &props_[lg.obj[k]];
    tsince_min[k] = (offset_s_[lg.obj[k]] + t_s) / 60.0;  // as propagate_s
  }
  sgp4::propagate_x4(lanes, p, tsince_min, r, v, ok);
  for (std::size_t k = 0; k < lg.n; ++k) {
    const std::size_t i = lg.obj[k];
    out[i] = ok[k] ? StateEci{Vec3(r[k][0], r[k][1], r[k][2]), Vec3(v[k][0], v[k][1], v[k][2])}
                   : grid_state_at(i, t_s);  // an error: named by state_at
  }
}

sgp4::Sgp4X4Lanes Sgp4Motion::lanes_of(const LaneGroup& lg) const {
  const sgp4::Sgp4Propagator* p[4];
  for (std::size_t k = 0; k < 4; ++k) p[k] = &props_[lg.obj[k]];
  return sgp4::Sgp4X4Lanes(p);
}

std::vector<Sgp4Motion::LaneGroup> Sgp4Motion::lane_groups(std::size_t begin, std::size_t end) const {
  std::vector<LaneGroup> out;
  for (const char kind : {char{1}, char{2}}) {  // near-Earth, then deep-space groups
    LaneGroup lg{};
    for (std::size_t i = begin; i <= end; ++i) {
      if (i < end && four_lane_[i] != kind) continue;
      if (i < end) lg.obj[lg.n++] = static_cast<std::uint32_t>(i);
      if (lg.n == 4 || (i == end && lg.n > 0)) {
        for (std::size_t k = lg.n; k < 4; ++k) lg.obj[k] = lg.obj[lg.n - 1];  // repeats the last
        out.push_back(lg);
        lg = LaneGroup{};
      }
    }
  }
  return out;
}

void Sgp4Motion::build_lane_groups() {
  groups_.clear();
  group_lanes_.clear();
  window_first_group_.assign(1, 0);
  for (std::size_t w0 = 0; w0 < size(); w0 += kLaneWindow) {
    for (const LaneGroup& lg : lane_groups(w0, std::min(size(), w0 + kLaneWindow))) {
      groups_.push_back(lg);
      group_lanes_.push_back(lanes_of(lg));
    }
    window_first_group_.push_back(groups_.size());
  }
}

double Sgp4Motion::grid_velocity_error_mps(std::size_t i) const {
  static const double kErrorMps = [] {  // the same for every object: computed once
    const EarthModel e = wgs72_earth();
    return velocity_allowance_mps(std::sqrt(2.0 * e.mu_m3ps2 / e.re_m));
  }();
  return kErrorMps + (four_lane(i) ? 1e-6 : 0.0);
}

double Sgp4Motion::grid_position_error_m(std::size_t i) const { return grid_err_m_[i]; }

bool Sgp4Motion::acceleration_at(std::size_t i, double t_s, Vec3& a_mps2, double& error_mps2) const {
  const double h = accel_step_s_, t = offset_s_[i] + t_s;
  Position q[5];
  for (int m = 0; m < 5; ++m) {
    q[m] = position(props_[i], t + (m - 2) * h);
    if (!q[m].ok) return false;  // the caller falls back to the envelope
  }
  a_mps2 = (-q[0].r + 16.0 * q[1].r - 30.0 * q[2].r + 16.0 * q[3].r - q[4].r) / (12.0 * h * h);
  const double r = q[2].r.norm(), n2 = n_max_radps_[i] * n_max_radps_[i];
  const double truncation = 4.0 * n2 * n2 * n2 * r * h * h * h * h / 90.0;
  const double jumps = 34.0 / 12.0 * 4e-12 * r / (h * h);
  error_mps2 = truncation + jumps;
  return true;
}

}  // namespace evade::conjunction
