// 3D-Nc collision probability (D. T. Hall, "Expected collision rates for tracked satellites",
// J. Spacecraft and Rockets 58(3), 2021, "H21"; the notation follows NASA CARA's Pc3D_Hall,
// whose published results the tests reproduce).
//   1. Each object's TCA state and covariance become equinoctial elements E and covariance
//      Q = K P K^T, K = (dX/dE)^-1 (equinoctial.hpp), where the PDF is far more Gaussian than in
//      Cartesian space. E = (n, af, ag, chi, psi, lambda_M) is singular at i = 180 deg, so when
//      either orbit is within 1e-6 of retrograde (1 + h_z/|h| < 1e-6; the Alfano 2009 cases)
//      both states and covariances are first rotated to the axes (y, z, x) (or (z, x, y) if
//      that is retrograde too); the Pc does not depend on the axes.
//   2. Two-body motion moves only lambda_M = lambda_M0 + n t, so the mean states X(t) and the
//      Jacobians J(t) = dX(t)/dE(0) follow in closed form: curved, not straight, motion.
//   3. At each time t the expansion centres are iterated to the peak overlap position (POP)
//      of the two position PDFs (CARA's PeakOverlapPos): with the offset states
//      x_u = x_s + J_s (E_mean - E_s), P_s = J_s Q J_s^T, A = P_s(r,r) (eigenvalues clipped at
//      (1e-4 HBR)^2), mu_p = (A1^-1 + A2^-1)^-1 (A1^-1 r_u1 + A2^-1 r_u2), v_up = v_u + B A^-1
//      (mu_p - r_u) and x_s <- (mu_p, v_up), until the step's Mahalanobis length in
//      (Sigma_p + HBR^2 I) is <= 1e-6 (averaging after 35, relaxed tolerance after 25, a two-
//      cycle test after 15 iterations, at most 100; an unbound centre stops the iteration).
//   4. The relative state about the POP is Gaussian: mean (r_u, v_u), covariance blocks
//      A, B, C of P_s1 + P_s2. The collision rate is the inward flux through the hard-body
//      sphere of radius R, dNc/dt = R^2 \oint N3(R rhat; r_u, A) nu(rhat) d Omega, with the
//      velocity conditional on the position, mean v_u + B A^-1 (R rhat - r_u) (H21 eq. 50)
//      and variance sigma^2 = rhat^T (C - B A^-1 B^T) rhat, and the expected inward speed
//      nu = sigma/sqrt(2 pi) [exp(-x^2) - sqrt(pi) x erfc(x)], x = nu0/(sqrt(2) sigma),
//      nu0 = rhat . (conditional mean) (Coppola 2012a, AAS 12-247, eqs. 31, 36, 37; nu =
//      max(0, -nu0) as sigma -> 0, eq. 39). The small-HBR limit is pi R^2 N3(0) |v_u|. When
//      the surface's effective Mahalanobis distance^2 M - 2R|A^-1 r_u| exceeds 1491 the rate
//      underflows and is 0. The sphere integral uses a Gauss-Legendre x trapezoid product rule
//      (sphere_quadrature.hpp) with its pole towards r_u (or the stiffest axis of A when r_u
//      is inside the sphere), doubled until two rules agree to sphere_rel_tol.
//   5. Nc = \int dNc/dt dt over the window by globally adaptive Gauss-Kronrod (7, 15)
//      quadrature (Piessens et al. 1983, QUADPACK QAG and its error estimate) to rel_tol, from
//      panels that resolve Coppola's window and cover the rest uniformly. The window is
//      [-window_s, window_s], or (window_s = 0) Coppola's bounds (AAS 12-248 eqs. 12-16) for
//      gamma, clipped to half the shorter period and widened while the rate at an end exceeds
//      2.5e-6 of the peak (CARA's refinement cut, gamma = 1e-6). For one isolated conjunction
//      Nc is the Pc (H21); pc is clipped to 1 as CARA does for quadrature error.
// Not implemented: CARA's covariance cross-correlation correction (H21 eq. 57, DCP inputs).
// Step 5's time integral is nc_time_integral.cpp, Coppola's window coppola_window.cpp.
#include "evade/assessment/pc_3d_nc.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "evade/assessment/equinoctial.hpp"
#include "evade/core/elements.hpp"
#include "nc_time_integral.hpp"

namespace evade::assessment {
namespace {

using nc::NcPanel;
using nc::TimeIntegral;

constexpr double kRateCut = 2.5e-6;  // rate / peak below which a window end is negligible
// Accepted non-positive-definiteness: the smallest eigenvalue of the correlation matrix may be
// down to -1e-4 (Alfano case 06's primary has -1.8e-5). Such a covariance is used as given,
// as CARA does by default; the position blocks are clipped where they are inverted.
constexpr double kNpdTolerance = 1e-4;

std::string num(double x) {
  char buf[32];
  (void)std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

void check_state(const StateEci& s, const std::string& what, double mu) {
  if (!s.r_eci_m.allFinite() || !s.v_eci_mps.allFinite()) {
    throw std::invalid_argument("pc_3d_nc: " + what + " state has a non-finite component");
  }
  const double energy = 0.5 * s.v_eci_mps.squaredNorm() - mu / s.r_eci_m.norm();
  const Vec3 h = s.r_eci_m.cross(s.v_eci_mps);
  const Vec3 e = s.v_eci_mps.cross(h) / mu - s.r_eci_m.normalized();
  if (!(energy < 0.0) || !(e.norm() < 1.0)) {
    throw std::invalid_argument("pc_3d_nc: " + what + " orbit is unbound (e = " +
                                num(e.norm()) + " >= 1 or energy >= 0)");
  }
}

// Symmetric and positive semi-definite within kNpdTolerance: the correlation matrix's smallest
// eigenvalue (scale-free across the position and velocity blocks).
void check_covariance(const Mat6& c, const std::string& what) {
  if (!c.allFinite()) throw std::invalid_argument("pc_3d_nc: " + what + " covariance has a non-finite entry");
  Vec6 d;
  for (int i = 0; i < 6; ++i) {
    if (c(i, i) < 0.0) {
      throw std::invalid_argument("pc_3d_nc: " + what + " covariance has a negative variance (element " +
                                  std::to_string(i) + " = " + num(c(i, i)) + ")");
    }
    d(i) = c(i, i) > 0.0 ? 1.0 / std::sqrt(c(i, i)) : 0.0;
  }
  const Mat6 s = d.asDiagonal() * c * d.asDiagonal();
  if ((s - s.transpose()).cwiseAbs().maxCoeff() > 1e-8) {
    throw std::invalid_argument("pc_3d_nc: " + what + " covariance is not symmetric");
  }
  const double lmin = Eigen::SelfAdjointEigenSolver<Mat6>(0.5 * (s + s.transpose())).eigenvalues()(0);
  if (lmin < -kNpdTolerance) {
    throw std::invalid_argument("pc_3d_nc: " + what +
                                " covariance is not positive semi-definite (smallest eigenvalue of "
                                "its correlation matrix " + num(lmin) + ")");
  }
}

void check_inputs(const StateEci& o1, const Mat6& c1, const StateEci& o2, const Mat6& c2,
                  double hbr_m, double mu, const Nc3dOptions& opt) {
  if (!(mu > 0.0) || !std::isfinite(mu)) throw std::invalid_argument("pc_3d_nc: mu must be finite and > 0");
  if (!(hbr_m > 0.0) || !std::isfinite(hbr_m)) {
    throw std::invalid_argument("pc_3d_nc: hard-body radius must be finite and > 0 m (got " + num(hbr_m) + ")");
  }
  if (!(opt.window_s >= 0.0) || !std::isfinite(opt.window_s)) {
    throw std::invalid_argument("pc_3d_nc: window_s must be finite and >= 0 s");
  }
  if (!(opt.gamma > 0.0 && opt.gamma < 1.0)) throw std::invalid_argument("pc_3d_nc: gamma must be in (0, 1)");
  if (!(opt.rel_tol > 0.0) || !(opt.sphere_rel_tol > 0.0)) {
    throw std::invalid_argument("pc_3d_nc: rel_tol and sphere_rel_tol must be > 0");
  }
  check_state(o1, "object 1", mu);
  check_state(o2, "object 2", mu);
  check_covariance(c1, "object 1");
  check_covariance(c2, "object 2");
}

bool near_retrograde(const StateEci& s) {
  const Vec3 h = s.r_eci_m.cross(s.v_eci_mps);
  return 1.0 + h.z() / h.norm() < 1e-6;
}

struct Oriented {
  std::array<StateEci, 2> s;
  std::array<Mat6, 2> c;
};

Oriented rotate(const Oriented& in, const Mat3& m) {
  Mat6 m6 = Mat6::Zero();
  m6.block<3, 3>(0, 0) = m;
  m6.block<3, 3>(3, 3) = m;
  Oriented out;
  for (int i = 0; i < 2; ++i) {
    out.s[i] = {m * in.s[i].r_eci_m, m * in.s[i].v_eci_mps};
    out.c[i] = m6 * in.c[i] * m6.transpose();
  }
  return out;
}

// CARA's retrograde reorientation: new axes (y, z, x), else (z, x, y).
Oriented reorient(const Oriented& in) {
  if (!near_retrograde(in.s[0]) && !near_retrograde(in.s[1])) return in;
  Mat3 m;
  m << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  Oriented out = rotate(in, m);
  if (near_retrograde(out.s[0]) || near_retrograde(out.s[1])) out = rotate(in, m.transpose());
  return out;
}

bool element_pdf(const StateEci& s, const Mat6& c, double mu, nc::ElementPdf* p) {
  const Vec6 x = s.stacked();
  if (!cartesian_to_equinoctial(x, mu, &p->e0)) return false;
  const Mat6 k = jacobian_equinoctial_to_cartesian(p->e0, x, mu).inverse();
  const Mat6 q = k * c * k.transpose();
  p->q = 0.5 * (q + q.transpose());
  return p->q.allFinite();
}

// The span holding all but kSpanTail of Nc on each side: the cumulative Nc over the panels
// in time order, linear inside a panel (CARA's TaConj, TbConj, comparable to Coppola's
// duration at gamma = 1e-6: 5e-7 on each side).
constexpr double kSpanTail = 5e-7;

void conjunction_span(std::vector<NcPanel> panels, double nc, double* ta, double* tb) {
  std::sort(panels.begin(), panels.end(), [](const NcPanel& x, const NcPanel& y) { return x.a < y.a; });
  *ta = panels.empty() ? 0.0 : panels.front().a;
  *tb = panels.empty() ? 0.0 : panels.back().b;
  double cum = 0.0;
  bool found_a = false;
  for (const NcPanel& p : panels) {
    const double next = cum + std::max(0.0, p.nc);
    auto at = [&](double level) {
      return p.a + (p.b - p.a) * (next > cum ? (level - cum) / (next - cum) : 0.0);
    };
    if (!found_a && next >= kSpanTail * nc) {
      *ta = at(kSpanTail * nc);
      found_a = true;
    }
    if (next >= (1.0 - kSpanTail) * nc) {
      *tb = at((1.0 - kSpanTail) * nc);
      return;
    }
    cum = next;
  }
}

// Initial panels: Coppola's window (where a near-linear encounter's rate lives) in 4 panels,
// the rest of [a, b] in panels no wider than max(Coppola's width, (b - a) / 32).
void initial_panels(TimeIntegral* ti, double a, double b, const EncounterWindow& w) {
  const double lo = std::clamp(w.tau0_s, a, b);
  const double hi = std::clamp(w.tau1_s, a, b);
  if (!(hi > lo)) {
    ti->add_panels(a, b, 32);
    return;
  }
  const double width = std::max(hi - lo, (b - a) / 32.0);
  if (lo > a) ti->add_panels(a, lo, static_cast<int>(std::ceil((lo - a) / width)));
  ti->add_panels(lo, hi, 4);
  if (b > hi) ti->add_panels(hi, b, static_cast<int>(std::ceil((b - hi) / width)));
}

struct Window {
  double a = 0.0, b = 0.0;
};

// Default window: Coppola's bounds within half the shorter period, widened (by its own width,
// up to that limit) while the rate at an end is above kRateCut of the peak.
Window default_window(TimeIntegral* ti, const EncounterWindow& w, double half_period_s) {
  Window win{std::max(w.tau0_s, -half_period_s), std::min(w.tau1_s, half_period_s)};
  if (!(win.b > win.a)) win = {-half_period_s, half_period_s};
  initial_panels(ti, win.a, win.b, w);
  for (int pass = 0; pass < 16 && ti->budget_left(); ++pass) {
    ti->refine();
    const double cut = kRateCut * ti->peak_;
    const double width = win.b - win.a;
    bool widened = false;
    if (win.a > -half_period_s && ti->rate_at(win.a, nullptr) > cut) {
      const double a = std::max(win.a - width, -half_period_s);
      ti->add_panels(a, win.a, 4);
      win.a = a;
      widened = true;
    }
    if (win.b < half_period_s && ti->rate_at(win.b, nullptr) > cut) {
      const double b = std::min(win.b + width, half_period_s);
      ti->add_panels(win.b, b, 4);
      win.b = b;
      widened = true;
    }
    if (!widened) break;
  }
  return win;
}

std::string convergence_failure(const TimeIntegral& ti, const Nc3dOptions& opt, double nc) {
  const double cut = kRateCut * ti.peak_;
  if (!ti.budget_left()) {
    return "rate evaluation budget (" + std::to_string(opt.max_rate_evaluations) + ") exhausted";
  }
  if (ti.total(&NcPanel::err) > opt.rel_tol * std::abs(nc) + 1e-300) return "time integral did not reach rel_tol";
  if (ti.worst_pop_failure_ > cut) return "peak overlap position did not converge where the rate matters";
  // The finest sphere rule may miss sphere_rel_tol where the PDF is much narrower than the
  // sphere; that is acceptable while its error is below rel_tol of the peak rate.
  if (ti.worst_sphere_error_ > opt.rel_tol * ti.peak_) {
    return "unit-sphere integral did not converge where the rate matters";
  }
  return "";
}

}  // namespace

Nc3dResult pc_3d_nc(const StateEci& obj1, const Mat6& cov1_eci, const StateEci& obj2,
                    const Mat6& cov2_eci, double hbr_m, double mu_m3ps2,
                    const Nc3dOptions& opt) {
  check_inputs(obj1, cov1_eci, obj2, cov2_eci, hbr_m, mu_m3ps2, opt);
  Nc3dResult res;
  res.coppola = coppola_window(obj1, cov1_eci, obj2, cov2_eci, hbr_m, opt.gamma);
  res.period1_s = orbital_period_s(obj1, mu_m3ps2);
  res.period2_s = orbital_period_s(obj2, mu_m3ps2);
  const Oriented o = reorient(Oriented{{obj1, obj2}, {cov1_eci, cov2_eci}});
  nc::ElementPdf p1, p2;
  if (!element_pdf(o.s[0], o.c[0], mu_m3ps2, &p1) || !element_pdf(o.s[1], o.c[1], mu_m3ps2, &p2)) {
    res.pc = std::numeric_limits<double>::quiet_NaN();
    res.failure = "equinoctial elements undefined (retrograde equatorial orbit)";
    return res;
  }
  const nc::RateSettings rs{hbr_m, mu_m3ps2, opt.sphere_rel_tol};
  TimeIntegral ti(p1, p2, rs, opt);
  Window win{-opt.window_s, opt.window_s};
  if (opt.window_s > 0.0) {
    initial_panels(&ti, win.a, win.b, res.coppola);
    ti.refine();
  } else {
    win = default_window(&ti, res.coppola, 0.5 * std::min(res.period1_s, res.period2_s));
  }
  const double nc = ti.total(&NcPanel::nc);
  res.pc = std::min(1.0, nc);
  res.pc_small_hbr = ti.total(&NcPanel::nc_small);
  res.t_begin_s = win.a;
  res.t_end_s = win.b;
  res.t_peak_s = ti.t_peak_;
  conjunction_span(ti.panels_, nc, &res.conj_begin_s, &res.conj_end_s);
  res.rate_peak_per_s = ti.peak_;
  res.rate_evaluations = ti.evaluations_;
  res.failure = convergence_failure(ti, opt, nc);
  res.converged = res.failure.empty();
  return res;
}

}  // namespace evade::assessment
