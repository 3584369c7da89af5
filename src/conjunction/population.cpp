// Seeded synthetic LEO population (see population.hpp for the documented distribution).
#include "evade/conjunction/population.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "evade/dynamics/kepler_propagator.hpp"
#include "evade/core/elements.hpp"

namespace evade::conjunction {

void PopulationOptions::validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("population." + what); };
  if (count > 10'000'000) fail("count = " + std::to_string(count) + " outside [0, 1e7]");
  if (!(coorbital_fraction >= 0.0 && crossing_fraction >= 0.0 && tangent_fraction >= 0.0 &&
        coorbital_fraction + crossing_fraction + tangent_fraction <= 1.0)) {
    fail("coorbital_fraction + crossing_fraction + tangent_fraction outside [0, 1], each >= 0");
  }
  if (!(span_s >= 0.0) || !std::isfinite(span_s)) fail("span_s outside [0, inf)");
}

namespace {

// The draws of synthetic_population, in the order the documented distribution takes them
// (one std::mt19937_64 stream: a seed is a catalog).
class PopulationDraw {
 public:
  explicit PopulationDraw(const PopulationOptions& opt)
      : rng_(opt.seed), mu_(opt.earth.mu_m3ps2), re_(opt.earth.re_m), span_s_(opt.span_s) {}

  // Background object k ("bg<k>").
  SpaceObject background(std::size_t k) {
    SpaceObject o;
    o.name = "bg" + std::to_string(k);
    o.state = state_from_elements(background_elements(), mu_);
    size_error(o);
    return o;
  }

  // Slow co-orbital pair k ("co<k>a/b"): the second copies the first's elements, perturbed.
  void coorbital_pair(std::size_t k, std::vector<SpaceObject>& out) {
    OrbitalElements oe = background_elements();
    OrbitalElements oe2 = oe;
    oe2.a_m += uni(-300.0, 300.0);
    oe2.e = std::max(0.0, oe.e + uni(-2e-4, 2e-4));
    oe2.i_rad = std::clamp(oe.i_rad + uni(-0.01, 0.01) * kDegToRad, 0.0, kPi);
    oe2.raan_rad += uni(-0.01, 0.01) * kDegToRad;
    const double m1 = mean_from_true_anomaly(oe.true_anomaly_rad, oe.e);
    oe2.true_anomaly_rad = true_from_mean_anomaly(m1 + uni(-0.05, 0.05) * kDegToRad, oe2.e);
    SpaceObject a, b;
    a.name = "co" + std::to_string(k) + "a";
    b.name = "co" + std::to_string(k) + "b";
    a.state = state_from_elements(oe, mu_);
    b.state = state_from_elements(oe2, mu_);
    size_error(a);
    size_error(b);
    out.push_back(a);
    out.push_back(b);
  }

  // A pair meeting at a random point and time, velocity directions ang_lo..ang_hi apart.
  void crossing_pair(std::size_t k, const std::string& prefix, double ang_lo, double ang_hi,
                     std::vector<SpaceObject>& out) {
    const double r = re_ + uni(400e3, 1200e3);
    Vec3 p(normal(0, 1), normal(0, 1), normal(0, 1));
    p = p.normalized() * r;
    const double t_meet = uni(0.0, span_s_);
    // Two horizontal directions at an angle U(ang_lo, ang_hi) deg.
    Vec3 h1 = p.unitOrthogonal();
    const Vec3 h2 = p.normalized().cross(h1);
    const double psi = uni(0.0, kTwoPi);
    const double ang = uni(ang_lo, ang_hi) * kDegToRad;
    const Vec3 d1 = std::cos(psi) * h1 + std::sin(psi) * h2;
    const Vec3 d2 = std::cos(psi + ang) * h1 + std::sin(psi + ang) * h2;
    const double vc = std::sqrt(mu_ / r);
    Vec3 off(normal(0, 1), normal(0, 1), normal(0, 1));
    off = off.normalized() * uni(0.0, 3000.0);
    StateEci s1{p, vc * d1};
    StateEci s2{p + off, vc * d2};
    SpaceObject a, b;
    a.name = prefix + std::to_string(k) + "a";
    b.name = prefix + std::to_string(k) + "b";
    a.state = KeplerOrbit(s1, mu_).state_at(-t_meet);
    b.state = KeplerOrbit(s2, mu_).state_at(-t_meet);
    size_error(a);
    size_error(b);
    out.push_back(a);
    out.push_back(b);
  }

 private:
  double uni(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  double normal(double m, double s) { return std::normal_distribution<double>(m, s)(rng_); }

  void size_error(SpaceObject& o) {
    o.size_m = std::exp(uni(std::log(0.1), std::log(10.0)));
    o.pos_error_m = uni(10.0, 100.0);
  }

  // Perigee altitude: the shell mixture of population.hpp [m].
  double perigee_altitude_m() {
    const double u = uni(0.0, 1.0);
    double hp;
    if (u < 0.30) hp = normal(550e3, 30e3);
    else if (u < 0.55) hp = normal(780e3, 40e3);
    else if (u < 0.70) hp = normal(1000e3, 60e3);
    else hp = uni(300e3, 2000e3);
    return std::clamp(hp, 250e3, 2100e3);
  }

  // Inclination: the mixture of population.hpp [deg].
  double inclination_deg() {
    const double v = uni(0.0, 1.0);
    double inc;
    if (v < 0.25) inc = 53.0;
    else if (v < 0.35) inc = 86.4;
    else if (v < 0.65) inc = normal(97.5, 1.0);
    else if (v < 0.75) inc = 51.6;
    else inc = uni(0.0, 180.0);
    return inc;
  }

  OrbitalElements background_elements() {
    OrbitalElements oe;
    const double hp = perigee_altitude_m();
    oe.e = uni(0.0, 0.01);
    oe.a_m = (re_ + hp) / (1.0 - oe.e);
    const double inc = inclination_deg();
    oe.i_rad = std::clamp(inc, 0.0, 180.0) * kDegToRad;
    oe.raan_rad = uni(0.0, kTwoPi);
    oe.argp_rad = uni(0.0, kTwoPi);
    oe.true_anomaly_rad = true_from_mean_anomaly(uni(0.0, kTwoPi), oe.e);
    return oe;
  }

  std::mt19937_64 rng_;
  double mu_;
  double re_;
  double span_s_;
};

}  // namespace

std::vector<SpaceObject> synthetic_population(const PopulationOptions& opt) {
  opt.validate();
  PopulationDraw draw(opt);
  const auto n_total = static_cast<double>(opt.count);
  const auto n_co = static_cast<std::size_t>(std::floor(n_total * opt.coorbital_fraction / 2.0)) * 2;
  const auto n_cx = static_cast<std::size_t>(std::floor(n_total * opt.crossing_fraction / 2.0)) * 2;
  const auto n_tg = static_cast<std::size_t>(std::floor(n_total * opt.tangent_fraction / 2.0)) * 2;
  const std::size_t n_bg = opt.count - n_co - n_cx - n_tg;
  std::vector<SpaceObject> out;
  out.reserve(opt.count);
  for (std::size_t k = 0; k < n_bg; ++k) out.push_back(draw.background(k));
  for (std::size_t k = 0; k < n_co / 2; ++k) draw.coorbital_pair(k, out);
  for (std::size_t k = 0; k < n_cx / 2; ++k) draw.crossing_pair(k, "cx", 20.0, 160.0, out);
  for (std::size_t k = 0; k < n_tg / 2; ++k) draw.crossing_pair(k, "tg", 0.5, 5.0, out);
  return out;
}

}  // namespace evade::conjunction
