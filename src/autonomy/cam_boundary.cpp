// The boundary solve of the onboard avoidance burn (include/evade/autonomy/onboard_cam.hpp,
// step 2; the declarations in include/evade/autonomy/internal/cam_boundary.hpp).
#include "evade/autonomy/internal/cam_boundary.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace evade::autonomy {

namespace {

constexpr int kMaxDoublings = 60;  // of a bracket
using assessment::Mat2;
using assessment::Vec2;

// The boundary solve of one model (the file comment of onboard_cam.hpp, step 2).
struct Model {
  const BurnOutcome* ref;
  Vec2 m0;          // the model's point without a burn
  Mat2 w;           // (A A^T)^-1
  double aim;
  double hbr_m;
  const OnboardCamOptions* o;
  CamWorkspace* ws;
};

// Pc at miss point (x, y) of the model's principal axes; 1 when the quadrature refuses it.
double pc_at(const Model& md, double x, double y) noexcept {
  const assessment::PrincipalEncounter pe{x, y, md.ref->principal.sigma_x_m, md.ref->principal.sigma_y_m};
  assessment::Pc2dResult r;
  if (assessment::pc_2d(pe, md.hbr_m, md.o->pc_rel_tol, &md.ws->pc, &r) != assessment::Pc2dStatus::kOk) return 1.0;
  return r.pc;
}

// ln(Pc / aim) at radius r along (c, s); Pc floored at 1e-300 so that it stays finite.
double log_ratio(const Model& md, double r, double c, double s) noexcept {
  return std::log(std::max(pc_at(md, r * c, r * s), 1e-300) / md.aim);
}

// The radius along theta where the Pc falls through the aim (just outside it): a bracket
// doubled from the largest sigma, then the Illinois variant of regula falsi on ln(Pc / aim)
// (Dowell & Jarratt 1971), at most `bisections` steps, until the bracket is 1e-10 of the radius.
double boundary_radius(const Model& md, double theta) noexcept {
  const double c = std::cos(theta), s = std::sin(theta);
  double lo = 0.0;
  double hi = std::max({md.ref->principal.sigma_x_m, md.ref->principal.sigma_y_m, md.hbr_m});
  double fhi = log_ratio(md, hi, c, s);
  for (int k = 0; k < kMaxDoublings && fhi > 0.0; ++k) {
    lo = hi;
    hi *= 2.0;
    fhi = log_ratio(md, hi, c, s);
  }
  double flo = log_ratio(md, lo, c, s);
  int side = 0;
  for (int k = 0; k < md.o->bisections && hi - lo > 1e-10 * hi && flo > 0.0; ++k) {
    double x = (flo * hi - fhi * lo) / (flo - fhi);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double fx = log_ratio(md, x, c, s);
    if (fx > 0.0) {
      lo = x;
      flo = fx;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = x;
      fhi = fx;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
  }
  return hi;
}

Vec2 boundary_point(const Model& md, double theta) noexcept {
  const double r = boundary_radius(md, theta);
  return Vec2(r * std::cos(theta), r * std::sin(theta));
}

double cost_at(const Model& md, double theta) noexcept {
  const Vec2 d = boundary_point(md, theta) - md.m0;
  return d.dot(md.w * d);
}

// Golden section of the cost on [centre - half, centre + half]: the best angle and its cost.
double golden(const Model& md, double centre, double half, double* cost) noexcept {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = centre - half, b = centre + half;
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = cost_at(md, x1), f2 = cost_at(md, x2);
  for (int k = 0; k < md.o->golden_iterations; ++k) {
    if (f1 < f2) {  // the minimum is in [a, x2]
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - g * (b - a);
      f1 = cost_at(md, x1);
    } else {        // in [x1, b]
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + g * (b - a);
      f2 = cost_at(md, x2);
    }
  }
  *cost = std::min(f1, f2);
  return f1 < f2 ? x1 : x2;
}

constexpr int kMaxMinima = 8;  // local minima of the sweep refined, the lowest first

// The sweep over boundary_angles directions; every local minimum of it (at most kMaxMinima, the
// lowest) and the hint (the direction of the reference burn's own miss point, so that a chain
// stays in its valley: the cost's valleys are narrow where A A^T is nearly singular) refined by
// golden section; the best direction.
double best_direction(const Model& md, double hint) noexcept {
  const int n = md.o->boundary_angles;
  const double step = kTwoPi / static_cast<double>(n);
  std::array<double, 720> c{};
  for (int k = 0; k < n; ++k) c[static_cast<std::size_t>(k)] = cost_at(md, step * static_cast<double>(k));
  std::array<int, kMaxMinima> minima{};
  int found = 0;
  for (int k = 0; k < n; ++k) {
    const double here = c[static_cast<std::size_t>(k)];
    if (!(here <= c[static_cast<std::size_t>((k + n - 1) % n)] && here < c[static_cast<std::size_t>((k + 1) % n)])) continue;
    int at = std::min(found, kMaxMinima - 1);  // keep the lowest kMaxMinima
    if (found >= kMaxMinima && !(here < c[static_cast<std::size_t>(minima[static_cast<std::size_t>(at)])])) continue;
    while (at > 0 && here < c[static_cast<std::size_t>(minima[static_cast<std::size_t>(at - 1)])]) {
      minima[static_cast<std::size_t>(at)] = minima[static_cast<std::size_t>(at - 1)];
      --at;
    }
    minima[static_cast<std::size_t>(at)] = k;
    found = std::min(found + 1, kMaxMinima);
  }
  double best_cost = 0.0;
  double best = golden(md, hint, step, &best_cost);
  for (int i = 0; i < found; ++i) {
    double cost = 0.0;
    const double t = golden(md, step * static_cast<double>(minima[static_cast<std::size_t>(i)]), step, &cost);
    if (cost < best_cost) {
      best_cost = cost;
      best = t;
    }
  }
  return best;
}

}  // namespace

// The smallest burn of the model about `ref` (made with dv_ref) reaching Pc <= aim.
CamStatus solve_model(const ConjunctionEvent& e, const BurnOutcome& ref, const Vec3& dv_ref, double aim,
                      const OnboardCamOptions& o, CamWorkspace* ws, Vec3* dv) noexcept {
  const Mat2 aat = ref.a * ref.a.transpose();
  if (!(std::fabs(aat.determinant()) > 0.0)) return CamStatus::kUnreachable;
  const Model md{&ref, Vec2(ref.principal.miss_x_m, ref.principal.miss_y_m) - ref.a * dv_ref, aat.inverse(),
                 aim, e.hbr_m, &o, ws};
  if (pc_at(md, md.m0.x(), md.m0.y()) <= aim) {
    *dv = Vec3::Zero();
    return CamStatus::kOk;
  }
  const Vec2 here(ref.principal.miss_x_m, ref.principal.miss_y_m);  // the reference burn's point
  const Vec2 m = boundary_point(md, best_direction(md, std::atan2(here.y(), here.x())));
  *dv = ref.a.transpose() * (md.w * (m - md.m0));
  return dv->norm() <= o.max_dv_mps ? CamStatus::kOk : CamStatus::kUnreachable;
}

// The along-track starts (evade plan cam's second start, on each side): the smallest burn
// along track, of sign `sign`, of the model about no burn that reaches the aim. The region
// Pc >= aim is convex and holds the model's point, so the half-line leaves it once: a bracket
// doubled from 1 mm/s, then bisection. Zero when the side needs more than max_dv_mps. Both
// sides are started from: which is cheaper after the exact outcome is not decided by the first
// model (the TCA moves with an along-track burn, and the plane with it).
Vec3 along_track_start(const ConjunctionEvent& e, const BurnOutcome& ref, const Vec6& x_burn, double aim,
                       double sign, const OnboardCamOptions& o, CamWorkspace* ws) noexcept {
  const Vec3 w = x_burn.head<3>().cross(x_burn.tail<3>()).normalized();
  const Vec3 t = sign * w.cross(x_burn.head<3>().normalized());  // along track, signed
  const Model md{&ref, Vec2(ref.principal.miss_x_m, ref.principal.miss_y_m), Mat2::Identity(), aim, e.hbr_m, &o, ws};
  const Vec2 at = ref.a * t;
  auto outside = [&](double x) {
    const Vec2 m = md.m0 + x * at;
    return pc_at(md, m.x(), m.y()) <= aim;
  };
  double lo = 0.0, hi = 1e-3;
  for (int k = 0; k < kMaxDoublings && hi <= o.max_dv_mps && !outside(hi); ++k) {
    lo = hi;
    hi *= 2.0;
  }
  if (hi > o.max_dv_mps || !outside(hi)) return Vec3::Zero();
  for (int k = 0; k < o.bisections; ++k) {
    const double mid = 0.5 * (lo + hi);
    (outside(mid) ? hi : lo) = mid;
  }
  return hi * t;
}

}  // namespace evade::autonomy
