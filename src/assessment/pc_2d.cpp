// 2D Pc by adaptive quadrature, Chan's series and Alfano's maximum Pc
// (include/evade/assessment/pc_2d.hpp gives the sources and equations).
#include "evade/assessment/pc_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>

#include "evade/core/constants.hpp"
#include "evade/core/gauss_kronrod.hpp"

namespace evade::assessment {
namespace {

Pc2dStatus input_status(const PrincipalEncounter& e, double hbr_m) noexcept {
  const bool finite = std::isfinite(e.miss_x_m) && std::isfinite(e.miss_y_m) &&
                      std::isfinite(e.sigma_x_m) && std::isfinite(e.sigma_y_m) &&
                      std::isfinite(hbr_m);
  if (!finite) return Pc2dStatus::kNotFinite;
  if (!(e.sigma_x_m > 0.0) || !(e.sigma_y_m > 0.0)) return Pc2dStatus::kBadSigma;
  if (!(hbr_m > 0.0)) return Pc2dStatus::kBadHbr;
  return Pc2dStatus::kOk;
}

// The ground's text of each refusal.
void check_input(const PrincipalEncounter& e, double hbr_m) {
  switch (input_status(e, hbr_m)) {
    case Pc2dStatus::kNotFinite:
      throw std::invalid_argument("Pc: non-finite miss, sigma or hard-body radius");
    case Pc2dStatus::kBadSigma:
      throw std::invalid_argument("Pc: encounter-plane sigmas must be > 0 m (got " +
                                  std::to_string(e.sigma_x_m) + ", " +
                                  std::to_string(e.sigma_y_m) + ")");
    case Pc2dStatus::kBadHbr:
      throw std::invalid_argument("Pc: hard-body radius must be > 0 m (got " +
                                  std::to_string(hbr_m) + ")");
    case Pc2dStatus::kOk:
    case Pc2dStatus::kBadTolerance: break;
  }
}

// P(a <= Y <= b) for Y ~ N(0, s^2), without cancellation in either tail.
double normal_interval(double a, double b, double s) noexcept {
  const double k = 1.0 / (std::sqrt(2.0) * s);
  if (a >= 0.0) return 0.5 * (std::erfc(a * k) - std::erfc(b * k));
  if (b <= 0.0) return 0.5 * (std::erfc(-b * k) - std::erfc(-a * k));
  return 1.0 - 0.5 * (std::erfc(-a * k) + std::erfc(b * k));
}

struct Integrand {
  PrincipalEncounter e;
  double r = 0.0;
  double operator()(double t) const noexcept {
    const double x = e.miss_x_m + r * std::sin(t);
    const double h = r * std::cos(t);
    const double gx = std::exp(-0.5 * x * x / (e.sigma_x_m * e.sigma_x_m)) /
                      (std::sqrt(2.0 * kPi) * e.sigma_x_m);
    return gx * normal_interval(e.miss_y_m - h, e.miss_y_m + h, e.sigma_y_m) * h;
  }
};

using Panel = Pc2dPanel;

// Gauss-Kronrod (7, 15) on [a, b] (core/gauss_kronrod.hpp).
Panel gauss_kronrod(const Integrand& f, double a, double b) noexcept {
  const double* const xk = kGk15Nodes;
  const double* const wk = kGk15Weights;
  const double* const wg = kG7Weights;
  const double c = 0.5 * (a + b);
  const double h = 0.5 * (b - a);
  const double fc = f(c);
  double k = wk[7] * fc;
  double g = wg[3] * fc;
  for (int i = 0; i < 7; ++i) {
    const double s = f(c - h * xk[i]) + f(c + h * xk[i]);
    k += wk[i] * s;
    if (i % 2 == 1) g += wg[i / 2] * s;
  }
  return {a, b, k * h, std::abs((k - g) * h)};
}

// Break points in t where the integrand turns: x = 0 +- k sx and R cos t = |ym| +- k sy; the
// ends, up to 21 turning points and 7 eighths: at most 30, sorted and without repeats.
struct BreakPoints {
  std::array<double, 30> t{};
  std::size_t n = 0;
  void add(double v) noexcept { t[n++] = v; }
};

BreakPoints break_points(const PrincipalEncounter& e, double r) noexcept {
  BreakPoints b;
  b.add(-0.5 * kPi);
  b.add(0.5 * kPi);
  for (double k : {0.0, -1.0, 1.0, -3.0, 3.0, -6.0, 6.0}) {
    const double sx = (k * e.sigma_x_m - e.miss_x_m) / r;
    if (std::abs(sx) < 1.0) b.add(std::asin(sx));
    const double cy = (std::abs(e.miss_y_m) + k * e.sigma_y_m) / r;
    if (cy > 0.0 && cy < 1.0) {
      b.add(std::acos(cy));
      b.add(-std::acos(cy));
    }
  }
  for (int i = 1; i < 8; ++i) b.add(-0.5 * kPi + i * kPi / 8.0);
  // Insertion sort: at most 30 values (435 comparisons), no recursion (std::sort's introsort
  // recurses, which the flight stack bound cannot allow: scripts/stack_check); the same order.
  for (std::size_t i = 1; i < b.n; ++i) {
    const double v = b.t[i];
    std::size_t j = i;
    for (; j > 0 && b.t[j - 1] > v; --j) b.t[j] = b.t[j - 1];
    b.t[j] = v;
  }
  b.n = static_cast<std::size_t>(
      std::unique(b.t.begin(), b.t.begin() + static_cast<std::ptrdiff_t>(b.n)) - b.t.begin());
  return b;
}

// The workspace's panels as a max-heap by error (what std::priority_queue does with
// std::push_heap and std::pop_heap on its container).
struct PanelHeap {
  Pc2dPanel* p;
  int n = 0;
  void push(const Pc2dPanel& x) noexcept {
    p[n++] = x;
    std::push_heap(p, p + n);
  }
  Pc2dPanel pop() noexcept {
    std::pop_heap(p, p + n);
    return p[--n];
  }
};

}  // namespace

const char* pc_2d_status_name(Pc2dStatus s) noexcept {
  switch (s) {
    case Pc2dStatus::kOk: return "ok";
    case Pc2dStatus::kNotFinite: return "not_finite";
    case Pc2dStatus::kBadSigma: return "bad_sigma";
    case Pc2dStatus::kBadHbr: return "bad_hbr";
    case Pc2dStatus::kBadTolerance: return "bad_tolerance";
  }
  return "?";
}

// Globally adaptive: the panel of the largest error is halved until the summed error is within
// rel_tol of the value or the workspace is full (bounded: at most kMaxPanels - 30 halvings).
Pc2dStatus pc_2d(const PrincipalEncounter& e, double hbr_m, double rel_tol, Pc2dWorkspace* ws,
                 Pc2dResult* out) noexcept {
  *out = Pc2dResult{};
  const Pc2dStatus st = input_status(e, hbr_m);
  if (st != Pc2dStatus::kOk) return st;
  if (!(rel_tol > 0.0)) return Pc2dStatus::kBadTolerance;
  const Integrand f{e, hbr_m};
  PanelHeap panels{ws->panels.data()};
  const BreakPoints t = break_points(e, hbr_m);
  double value = 0.0, error = 0.0;
  for (std::size_t i = 0; i + 1 < t.n; ++i) {
    const Panel p = gauss_kronrod(f, t.t[i], t.t[i + 1]);
    value += p.value;
    error += p.error;
    panels.push(p);
  }
  while (error > rel_tol * std::abs(value) && error > 1e-300 &&
         panels.n + 1 < Pc2dWorkspace::kMaxPanels) {
    const Panel worst = panels.pop();
    const double m = 0.5 * (worst.a + worst.b);
    const Panel l = gauss_kronrod(f, worst.a, m);
    const Panel r = gauss_kronrod(f, m, worst.b);
    value += l.value + r.value - worst.value;
    error += l.error + r.error - worst.error;
    panels.push(l);
    panels.push(r);
  }
  *out = {std::min(1.0, std::max(0.0, value)), error, panels.n};
  return Pc2dStatus::kOk;
}

Pc2dResult pc_2d(const PrincipalEncounter& e, double hbr_m, double rel_tol) {
  check_input(e, hbr_m);
  if (!(rel_tol > 0.0)) throw std::invalid_argument("pc_2d: rel_tol must be > 0");
  const auto ws = std::make_unique<Pc2dWorkspace>();
  Pc2dResult r;
  (void)pc_2d(e, hbr_m, rel_tol, ws.get(), &r);  // the input was checked: kOk
  return r;
}

double pc_chan(const PrincipalEncounter& e, double hbr_m) {
  check_input(e, hbr_m);
  const double u2 = 0.5 * hbr_m * hbr_m / (e.sigma_x_m * e.sigma_y_m);
  const double v2 = 0.5 * (e.miss_x_m * e.miss_x_m / (e.sigma_x_m * e.sigma_x_m) +
                           e.miss_y_m * e.miss_y_m / (e.sigma_y_m * e.sigma_y_m));
  // A miss beyond ~1.3e154 sigma squares to infinity: every Poisson weight e^-v v^m / m! is 0
  // (the series would otherwise form inf - inf = NaN, which std::min turned into 1.0).
  if (std::isinf(v2)) return 0.0;
  // A hard-body radius beyond ~1.3e154 sigma: the disc holds the whole density.
  if (std::isinf(u2)) return 1.0;
  // Poisson upper tail P(K > m), K ~ Poisson(u/2), summed term by term (no cancellation).
  auto upper_tail = [u2](int m) {
    double term = std::exp(-u2 + (m + 1) * std::log(u2) - std::lgamma(m + 2.0));
    double sum = 0.0;
    for (int k = m + 1; k < m + 2000 && term > 1e-300; ++k) {
      sum += term;
      if (term < 1e-17 * sum) break;
      term *= u2 / (k + 1);
    }
    return sum;
  };
  double sum = 0.0;
  for (int m = 0; m < 100000; ++m) {
    const double a = std::exp(-v2 + (m > 0 ? m * std::log(v2) : 0.0) - std::lgamma(m + 1.0));
    const double term = a * upper_tail(m);
    sum += term;
    if (m > v2 && term < 1e-17 * sum) break;
    if (v2 == 0.0) break;
  }
  if (!std::isfinite(sum)) throw std::domain_error("pc_chan: the series did not converge");
  return std::min(1.0, sum);
}

PcMaxResult pc_max_alfano(const PrincipalEncounter& e, double hbr_m) {
  check_input(e, hbr_m);
  auto pc_at = [&](double log_k) {
    const double k = std::exp(log_k);
    PrincipalEncounter s = e;
    s.sigma_x_m *= k;
    s.sigma_y_m *= k;
    return pc_2d(s, hbr_m, 1e-10).pc;
  };
  // Coarse scan for the bracket, then golden section on log k (Pc(k) is unimodal in k).
  double best = std::log(1e-4);
  double best_pc = -1.0;
  const double step = std::log(1e8) / 160.0;
  for (int i = 0; i <= 160; ++i) {
    const double lk = std::log(1e-4) + i * step;
    const double p = pc_at(lk);
    if (p > best_pc) { best_pc = p; best = lk; }
  }
  double a = best - step, b = best + step;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = pc_at(c), fd = pc_at(d);
  for (int it = 0; it < 80 && (b - a) > 1e-10; ++it) {
    if (fc > fd) { b = d; d = c; fd = fc; c = b - g * (b - a); fc = pc_at(c); }
    else { a = c; c = d; fc = fd; d = a + g * (b - a); fd = pc_at(d); }
  }
  const double lk = 0.5 * (a + b);
  const double p = pc_at(lk);
  if (p >= best_pc) return {p, std::exp(lk)};
  return {best_pc, std::exp(best)};
}

}  // namespace evade::assessment
