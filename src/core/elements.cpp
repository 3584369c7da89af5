// Classical orbital elements <-> Cartesian state (Vallado 4th ed. alg. 9 RV2COE and
// alg. 10 COE2RV), with every angle computed as atan2 of a sine and a cosine measured about
// the angular-momentum direction, so there is no acos precision loss and no NaN at the
// circular/equatorial singularities (conventions in the header).
#include "evade/core/elements.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "evade/core/constants.hpp"

namespace evade {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

Mat3 rot1(double a) {
  Mat3 m;
  const double c = std::cos(a), s = std::sin(a);
  m << 1, 0, 0, 0, c, s, 0, -s, c;
  return m;
}
Mat3 rot3(double a) {
  Mat3 m;
  const double c = std::cos(a), s = std::sin(a);
  m << c, s, 0, -s, c, 0, 0, 0, 1;
  return m;
}

// Signed angle from unit vector a to unit vector b measured about unit axis h, in [0, 2pi).
double angle_about(const Vec3& a, const Vec3& b, const Vec3& h) {
  return wrap_two_pi(std::atan2(a.cross(b).dot(h), a.dot(b)));
}

}  // namespace

double wrap_two_pi(double angle_rad) {
  double y = std::fmod(angle_rad, kTwoPi);
  if (y < 0.0) y += kTwoPi;
  if (y >= kTwoPi) y = 0.0;  // fmod rounding at exactly 2pi
  return y;
}

double wrap_pi(double angle_rad) {
  double y = wrap_two_pi(angle_rad + kPi) - kPi;
  return y;
}

double eccentric_from_mean_anomaly(double mean_anomaly_rad, double e) {
  require(std::isfinite(mean_anomaly_rad) && std::isfinite(e) && e >= 0.0 && e < 1.0,
          "eccentric_from_mean_anomaly: need finite M and 0 <= e < 1, got e = " + std::to_string(e));
  const double m = wrap_pi(mean_anomaly_rad);  // [-pi, pi)
  const double base = mean_anomaly_rad - m;   // multiple of 2pi restored at the end
  // Starting value: E = M + e sin M for moderate e; pi*sign(M) for high e (Danby), from which
  // Newton converges monotonically on [-pi, pi].
  double ecc = (e < 0.8) ? m + e * std::sin(m) : (m >= 0.0 ? kPi : -kPi);
  for (int k = 0; k < 50; ++k) {  // bounded: Halley converges cubically, ~3-5 iterations
    const double s = e * std::sin(ecc), c = e * std::cos(ecc);
    const double f = ecc - s - m, fp = 1.0 - c, fpp = s;
    const double newton = f / fp;
    const double step = f / (fp - 0.5 * newton * fpp);
    ecc -= step;
    if (std::fabs(step) <= 4e-16 * std::max(1.0, std::fabs(ecc))) break;
  }
  return ecc + base;
}

double true_from_eccentric_anomaly(double ecc, double e) {
  const double half = 0.5 * ecc;
  const double nu = 2.0 * std::atan2(std::sqrt(1.0 + e) * std::sin(half),
                                     std::sqrt(1.0 - e) * std::cos(half));
  // Keep the revolution count of the input.
  return nu + kTwoPi * std::round((ecc - nu) / kTwoPi);
}

double eccentric_from_true_anomaly(double true_anomaly_rad, double e) {
  const double half = 0.5 * true_anomaly_rad;
  const double ecc = 2.0 * std::atan2(std::sqrt(1.0 - e) * std::sin(half),
                                      std::sqrt(1.0 + e) * std::cos(half));
  return ecc + kTwoPi * std::round((true_anomaly_rad - ecc) / kTwoPi);
}

double mean_from_true_anomaly(double true_anomaly_rad, double e) {
  const double ecc = eccentric_from_true_anomaly(true_anomaly_rad, e);
  return ecc - e * std::sin(ecc);
}

double true_from_mean_anomaly(double m, double e) {
  return true_from_eccentric_anomaly(eccentric_from_mean_anomaly(m, e), e);
}

double mean_motion_radps(double a_m, double mu_m3ps2) {
  require(a_m > 0.0 && mu_m3ps2 > 0.0, "mean_motion_radps: need a > 0 and mu > 0");
  return std::sqrt(mu_m3ps2 / (a_m * a_m * a_m));
}

double orbital_period_s(double a_m, double mu_m3ps2) {
  return kTwoPi / mean_motion_radps(a_m, mu_m3ps2);
}

double orbital_period_s(const StateEci& s, double mu_m3ps2) {
  const double a = 1.0 / (2.0 / s.r_eci_m.norm() - s.v_eci_mps.squaredNorm() / mu_m3ps2);
  return a > 0.0 ? kTwoPi * std::sqrt(a * a * a / mu_m3ps2)
                 : std::numeric_limits<double>::infinity();
}

StateEci state_from_elements(const OrbitalElements& oe, double mu) {
  require(std::isfinite(oe.a_m) && oe.a_m > 0.0,
          "state_from_elements: a_m = " + std::to_string(oe.a_m) + " (need a finite value > 0)");
  require(std::isfinite(oe.e) && oe.e >= 0.0 && oe.e < 1.0,
          "state_from_elements: e = " + std::to_string(oe.e) + " (need 0 <= e < 1)");
  require(std::isfinite(oe.i_rad) && std::isfinite(oe.raan_rad) && std::isfinite(oe.argp_rad) &&
              std::isfinite(oe.true_anomaly_rad),
          "state_from_elements: non-finite angle");
  require(mu > 0.0, "state_from_elements: mu must be > 0");
  const double p = oe.a_m * (1.0 - oe.e * oe.e);
  const double cnu = std::cos(oe.true_anomaly_rad), snu = std::sin(oe.true_anomaly_rad);
  const double r = p / (1.0 + oe.e * cnu);
  const double vs = std::sqrt(mu / p);
  const Vec3 r_pqw(r * cnu, r * snu, 0.0);
  const Vec3 v_pqw(-vs * snu, vs * (oe.e + cnu), 0.0);
  const Mat3 q = rot3(-oe.raan_rad) * rot1(-oe.i_rad) * rot3(-oe.argp_rad);
  return {q * r_pqw, q * v_pqw};
}

OrbitalElements elements_from_state(const StateEci& s, double mu) {
  const Vec3& r = s.r_eci_m;
  const Vec3& v = s.v_eci_mps;
  require(r.allFinite() && v.allFinite(), "elements_from_state: non-finite state");
  const double rn = r.norm();
  require(rn > 0.0, "elements_from_state: zero position");
  const Vec3 h = r.cross(v);
  const double hn = h.norm();
  require(hn > 0.0, "elements_from_state: rectilinear orbit (r x v = 0)");
  const Vec3 h_hat = h / hn;
  const Vec3 e_vec = ((v.squaredNorm() - mu / rn) * r - r.dot(v) * v) / mu;
  const double e = e_vec.norm();
  require(e < 1.0, "elements_from_state: unbound orbit, e = " + std::to_string(e));
  const double energy = 0.5 * v.squaredNorm() - mu / rn;

  OrbitalElements oe;
  oe.a_m = -mu / (2.0 * energy);
  oe.e = e;
  const Vec3 node(-h.y(), h.x(), 0.0);  // k x h
  const double node_n = node.norm();
  oe.i_rad = std::atan2(node_n, h.z());
  const bool equatorial = node_n / hn < kEquatorialTolerance;
  const bool circular = e < kCircularTolerance;
  const Vec3 n_hat = equatorial ? Vec3::UnitX() : Vec3(node / node_n);
  // Node line direction; for equatorial orbits the x axis (angles then measured about h).
  oe.raan_rad = equatorial ? 0.0 : wrap_two_pi(std::atan2(node.y(), node.x()));
  const Vec3 r_hat = r / rn;
  if (circular) {
    oe.e = 0.0;
    oe.argp_rad = 0.0;
    oe.true_anomaly_rad = angle_about(n_hat, r_hat, h_hat);
  } else {
    const Vec3 e_hat = e_vec / e;
    oe.argp_rad = angle_about(n_hat, e_hat, h_hat);
    oe.true_anomaly_rad = angle_about(e_hat, r_hat, h_hat);
  }
  return oe;
}

}  // namespace evade
