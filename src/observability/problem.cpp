// Paper 004 geometry: frames, burn parametrization (§2.1), the angles-only measurement (eq. 3)
// and the HCW sampling of eq. 1–2 (Φ_P X_P0 and B_r u_E). See problem.hpp for the frames.
#include "evade/observability/problem.hpp"

#include <cmath>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>

#include "evade/core/constants.hpp"
#include "evade/dynamics/hcw.hpp"

namespace evade::observability {
namespace {

[[noreturn]] void bad(const std::string& field, double value, const std::string& allowed) {
  std::ostringstream os;
  os.precision(17);
  os << "observability problem: " << field << " = " << value << " is invalid; allowed: " << allowed;
  throw std::invalid_argument(os.str());
}

// One check of validate(): when !ok, bad(field, value, allowed).
struct Check {
  bool ok;
  const char* field;
  double value;
  std::string allowed;
};

// Throws for the first failed check, in order.
void require_all(std::initializer_list<Check> checks) {
  for (const Check& c : checks) {
    if (!c.ok) bad(c.field, c.value, c.allowed);
  }
}

// v finite and in (lo, hi].
bool finite_in_open_closed(double v, double lo, double hi) {
  return std::isfinite(v) && v > lo && v <= hi;
}

void validate_state(const Vec6& x) {
  for (int i = 0; i < 6; ++i)
    if (!std::isfinite(x(i)))
      bad("x_chaser_p0[" + std::to_string(i) + "]", x(i), "finite [m, m/s]");
  if (x.head<3>().norm() <= 0.0)
    bad("|x_chaser_p0 position|", 0.0, "> 0 m (the angles are undefined at zero range)");
}

void validate_bounds(const ObservabilityProblem& p) {
  const double lo = p.theta_min_rad;
  const double hi = p.theta_max_rad;
  const double eps = p.eps_max_rad;
  require_all({
      {std::isfinite(lo) && std::isfinite(hi), "theta bounds", std::isfinite(lo) ? hi : lo,
       "finite"},
      {lo < hi, "theta_min_rad", lo,
       "< theta_max_rad = " + std::to_string(hi) + " (inverted or empty bounds)"},
      {!(hi - lo > kTwoPi + 1e-12), "theta_max_rad - theta_min_rad", hi - lo, "<= 2π"},
      {std::isfinite(eps) && eps >= 0.0 && eps <= 0.5 * kPi, "eps_max_rad", eps,
       "finite, in [0, π/2]"},
  });
}

}  // namespace

Mat3 rotation_rsw_to_paper() { return Vec3(-1.0, -1.0, 1.0).asDiagonal(); }

void validate(const ObservabilityProblem& p) {
  require_all({{finite_in_open_closed(p.n_radps, 0.0, 1e-2), "n_radps", p.n_radps,
                "finite, in (0, 0.01] rad/s"}});
  validate_state(p.x_chaser_p0);
  require_all({
      {finite_in_open_closed(p.dv_mps, 0.0, 1e4), "dv_mps", p.dv_mps,
       "finite, in (0, 1e4] m/s (a zero burn has no direction)"},
      {std::isfinite(p.dt_obs_s) && p.dt_obs_s > 0.0, "dt_obs_s", p.dt_obs_s, "finite, > 0 s"},
      {std::isfinite(p.t_obs_s) && p.t_obs_s >= p.dt_obs_s, "t_obs_s", p.t_obs_s,
       "finite, >= dt_obs_s (at least one sample after t0)"},
      {!(p.t_obs_s / p.dt_obs_s > 1e6), "t_obs_s / dt_obs_s", p.t_obs_s / p.dt_obs_s,
       "<= 1e6 samples"},
  });
  validate_bounds(p);
}

std::vector<double> sample_times(const ObservabilityProblem& p) {
  const long n = static_cast<long>(std::floor(p.t_obs_s / p.dt_obs_s + 1e-9));
  std::vector<double> t(static_cast<std::size_t>(n + 1));
  for (long k = 0; k <= n; ++k) t[static_cast<std::size_t>(k)] = static_cast<double>(k) * p.dt_obs_s;
  return t;
}

Vec3 dv_paper_from_angles(double eps_rad, double theta_rad, double dv_mps) {
  const double ce = std::cos(eps_rad);
  return dv_mps * Vec3(ce * std::cos(theta_rad), ce * std::sin(theta_rad), std::sin(eps_rad));
}

Vec3 dv_rsw_from_angles(double eps_rad, double theta_rad, double dv_mps) {
  return rotation_rsw_to_paper() * dv_paper_from_angles(eps_rad, theta_rad, dv_mps);
}

std::pair<double, double> los_angles(const Vec3& r) {
  // Eq. 3, principal values as printed. x = 0 gives ±π/2 (std::atan of ±Inf); the zero
  // vector gives NaN, which callers never produce (range > 0 is validated).
  const double pitch = std::atan(r.z() / r.x());
  const double azimuth = std::atan(r.y() / std::hypot(r.x(), r.z()));
  return {pitch, azimuth};
}

double pitch_difference(double a_rad, double b_rad) {
  double d = std::fmod(a_rad - b_rad, kPi);  // in (−π, π)
  if (d > 0.5 * kPi) d -= kPi;
  if (d <= -0.5 * kPi) d += kPi;
  return d;
}

Vec3 chaser_position_p(const ObservabilityProblem& p, double t_s) {
  const Mat3 c = rotation_rsw_to_paper();
  Vec6 x_rsw;
  x_rsw << c * p.x_chaser_p0.head<3>(), c * p.x_chaser_p0.tail<3>();
  return c * hcw_propagate(p.n_radps, t_s, x_rsw).head<3>();
}

Vec3 burn_displacement_p(const ObservabilityProblem& p, double t_s, const Vec3& dv_p_mps) {
  const Mat3 c = rotation_rsw_to_paper();
  return c * hcw_impulse_response(p.n_radps, t_s, c * dv_p_mps).head<3>();
}

SampledProblem sample(const ObservabilityProblem& p) {
  validate(p);
  SampledProblem s;
  s.problem = p;
  s.t_s = sample_times(p);
  const Mat3 c = rotation_rsw_to_paper();
  s.r_chaser_p.reserve(s.t_s.size());
  s.b_r_p.reserve(s.t_s.size());
  for (double t : s.t_s) {
    s.r_chaser_p.push_back(chaser_position_p(p, t));
    s.b_r_p.push_back(c * hcw_stm_blocks(p.n_radps, t).rv * c);  // Φ_rv expressed in P
  }
  return s;
}

}  // namespace evade::observability
