// Event location on the dense output of Dop853: roots of a scalar g(t, x(t)).
//
// An event is a sign change of g between the two ends of an accepted step (t_prev, t]. It
// is located on the 7th-order continuous extension (HNW I, sec. II.6) with Brent's method
// (R. P. Brent, "Algorithms for Minimization without Derivatives", 1973, ch. 4, procedure
// zero): inverse quadratic interpolation / secant steps safeguarded by bisection, converging
// to a bracket no wider than time_tol_s + 4 eps |t|. A root that makes g touch zero
// without changing sign inside one step (an even number of roots) is not seen: keep steps
// shorter than the time between roots (AdaptiveOptions::h_max_s) when that matters.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "evade/dynamics/dop853.hpp"

namespace evade {

/// Which sign changes count, in increasing physical time whatever the integration direction:
/// kRising = g goes from < 0 to >= 0 (e.g. range rate at a closest approach), kFalling =
/// from > 0 to <= 0.
enum class EventDirection { kAny = 0, kRising = 1, kFalling = -1 };

struct EventOptions {
  double time_tol_s = 1e-9;  ///< Brent bracket tolerance [s]
  int max_iterations = 200;  ///< bound on Brent iterations per root
  EventDirection direction = EventDirection::kAny;
  bool terminal = false;     ///< stop the integration at the first event
  long max_events = 100000;  ///< stop after this many events
};

template <class Vector>
struct EventRecord {
  double t_s = 0.0;   ///< event time [s]
  Vector x;           ///< state at t_s (dense output)
  int direction = 0;  ///< +1: g rises through zero as time increases, -1: g falls
};

namespace detail {

/// One step choice of Brent's zero: interpolation (secant when a == c, else inverse
/// quadratic) where it is acceptable, else bisection. Updates the step d and the step before
/// it, e.
inline void brent_step(double a, double b, double c, double ga, double gb, double gc, double m,
                       double tol1, double* d, double* e) {
  if (!(std::abs(*e) >= tol1 && std::abs(ga) > std::abs(gb))) {
    *d = m;
    *e = m;
    return;
  }
  double p;
  double q;
  const double s = gb / ga;
  if (a == c) {
    p = 2.0 * m * s;
    q = 1.0 - s;
  } else {
    const double qa = ga / gc;
    const double r = gb / gc;
    p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
    q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
  }
  if (p > 0.0) q = -q; else p = -p;
  if (2.0 * p < std::min(3.0 * m * q - std::abs(tol1 * q), std::abs(*e * q))) {
    *e = *d;
    *d = p / q;
  } else {
    *d = m;
    *e = m;
  }
}

}  // namespace detail

/// Root of a scalar function on [a, b] with g(a) g(b) <= 0 (Brent's zero, 1973). Returns
/// the end of the final bracket at which |g| is smaller. Bounded by max_iterations.
template <class G>
double brent_root(const G& g, double a, double b, double ga, double gb, double tol,
                  int max_iterations) {
  if (ga == 0.0) return a;
  if (gb == 0.0) return b;
  if ((ga > 0.0) == (gb > 0.0)) throw std::invalid_argument("brent_root: root not bracketed");
  constexpr double kEps = 2.220446049250313e-16;
  double c = a;
  double gc = ga;
  double d = b - a;
  double e = d;
  for (int it = 0; it < max_iterations; ++it) {
    if ((gb > 0.0) == (gc > 0.0)) {  // keep the root between b and c
      c = a;
      gc = ga;
      d = b - a;
      e = d;
    }
    if (std::abs(gc) < std::abs(gb)) {  // b is the best estimate
      a = b;
      b = c;
      c = a;
      ga = gb;
      gb = gc;
      gc = ga;
    }
    const double tol1 = 2.0 * kEps * std::abs(b) + 0.5 * tol;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol1 || gb == 0.0) return b;
    detail::brent_step(a, b, c, ga, gb, gc, m, tol1, &d, &e);
    a = b;
    ga = gb;
    b += (std::abs(d) > tol1) ? d : (m > 0.0 ? tol1 : -tol1);
    gb = g(b);
  }
  return b;
}

/// Looks for a sign change of g over the last accepted step of `integ`, given g at the
/// start of the step (g_prev) and at its end (g_now). Returns the event, if any.
template <class Vector, class G>
std::optional<EventRecord<Vector>> locate_event_in_step(const Dop853<Vector>& integ, const G& g,
                                                        double g_prev, double g_now,
                                                        const EventOptions& opt = {}) {
  // g_prev == 0 was reported at the end of the previous step (or is the initial point).
  if (g_prev == 0.0 || !std::isfinite(g_prev) || !std::isfinite(g_now)) return std::nullopt;
  if ((g_prev > 0.0) == (g_now > 0.0) && g_now != 0.0) return std::nullopt;
  // Sign change in integration order, converted to increasing physical time.
  const int forward = (integ.t_s() > integ.t_prev_s()) ? +1 : -1;
  const int dir = ((g_prev < 0.0) ? +1 : -1) * forward;
  if (opt.direction != EventDirection::kAny && static_cast<int>(opt.direction) != dir) {
    return std::nullopt;
  }
  auto g_of_t = [&](double t) { return g(t, integ.dense(t)); };
  const double t_root = brent_root(g_of_t, integ.t_prev_s(), integ.t_s(), g_prev, g_now,
                                   opt.time_tol_s, opt.max_iterations);
  EventRecord<Vector> ev;
  ev.t_s = t_root;
  ev.x = (t_root == integ.t_s()) ? integ.x() : integ.dense(t_root);
  ev.direction = dir;
  return ev;
}

/// Integrates [t0_s, t1_s] (either direction) with DOP853 and returns every sign change of
/// g(t, x) (filtered by opt.direction), in the order met. With opt.terminal the integration
/// stops at the first event. Throws std::runtime_error if the integration fails.
template <class Vector, class Rhs, class G>
std::vector<EventRecord<Vector>> propagate_until_events(const Rhs& f, double t0_s,
                                                        const Vector& x0, double t1_s, const G& g,
                                                        const AdaptiveOptions& integ_opt = {},
                                                        const EventOptions& event_opt = {},
                                                        IntegrationStats* stats = nullptr) {
  if (!(event_opt.time_tol_s > 0.0) || event_opt.max_iterations < 1) {
    throw std::invalid_argument("EventOptions: need time_tol_s > 0 and max_iterations >= 1");
  }
  std::vector<EventRecord<Vector>> events;
  Dop853<Vector> integ(typename Dop853<Vector>::Rhs(f), integ_opt);
  integ.reset(t0_s, x0);
  double g_prev = g(t0_s, x0);
  while (integ.t_s() != t1_s) {
    if (!integ.step(t1_s)) {
      throw std::runtime_error("propagate_until_events failed: " + integ.failure_reason());
    }
    const double g_now = g(integ.t_s(), integ.x());
    auto ev = locate_event_in_step(integ, g, g_prev, g_now, event_opt);
    g_prev = g_now;
    if (ev) {
      events.push_back(std::move(*ev));
      if (event_opt.terminal ||
          static_cast<long>(events.size()) >= event_opt.max_events) {
        break;
      }
    }
  }
  if (stats != nullptr) *stats = integ.stats();
  return events;
}

}  // namespace evade
