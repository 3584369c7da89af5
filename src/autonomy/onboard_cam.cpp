// The onboard avoidance burn (include/evade/autonomy/onboard_cam.hpp gives the model and its
// sources).
#include "evade/autonomy/onboard_cam.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <Eigen/Eigenvalues>

#include "evade/assessment/encounter_2d.hpp"
#include "evade/autonomy/orbit_stm.hpp"
#include "evade/core/constants.hpp"

namespace evade::autonomy {

namespace {

constexpr int kTcaIterations = 8;        // Newton steps on the range rate
constexpr double kTcaTolS = 1e-7;        // |dt| that ends them [s]
constexpr double kMaxTcaShiftS = 3600.0; // a burn moving the TCA further is another encounter
constexpr int kMaxDoublings = 60;        // of the boundary bracket
using Mat23 = Eigen::Matrix<double, 2, 3>;
using assessment::Mat2;
using assessment::Vec2;

// The primary at the burn time, propagated back from TCA, with its covariance there.
struct BurnStart {
  double tau_s = 0.0;  // burn time minus TCA
  Vec6 x1 = Vec6::Zero();
  Mat6 cov1 = Mat6::Zero();
};

bool primary_at_burn(const ConjunctionEvent& e, double tau_s, const OnboardCamOptions& o,
                     const EarthModel& earth, BurnStart* out) noexcept {
  StateStm s{e.x1_eci, Mat6::Identity()};
  if (!propagate_stm(&s, tau_s, o.step_s, earth)) return false;
  out->tau_s = tau_s;
  out->x1 = s.x_eci;
  out->cov1 = s.phi * e.cov1_eci * s.phi.transpose();
  return true;
}

// The burned primary (from the burn) and the secondary (from TCA) at the new TCA.
struct AtTca {
  StateStm p1, p2;
  double shift_s = 0.0;
};

bool to_new_tca(const ConjunctionEvent& e, const BurnStart& b, const Vec3& dv, const OnboardCamOptions& o,
                const EarthModel& earth, AtTca* t) noexcept {
  t->p1 = StateStm{b.x1, Mat6::Identity()};
  t->p1.x_eci.tail<3>() += dv;
  t->p2 = StateStm{e.x2_eci, Mat6::Identity()};
  t->shift_s = 0.0;
  if (!propagate_stm(&t->p1, -b.tau_s, o.step_s, earth)) return false;
  for (int k = 0; k < kTcaIterations; ++k) {
    const Vec3 r = t->p2.x_eci.head<3>() - t->p1.x_eci.head<3>();
    const Vec3 v = t->p2.x_eci.tail<3>() - t->p1.x_eci.tail<3>();
    const double vv = v.squaredNorm();
    if (!(vv > 0.0)) return false;
    const double dt = -r.dot(v) / vv;
    if (std::fabs(dt) < kTcaTolS) break;
    if (!(std::fabs(t->shift_s + dt) < kMaxTcaShiftS)) return false;
    if (!propagate_stm(&t->p1, dt, o.step_s, earth) || !propagate_stm(&t->p2, dt, o.step_s, earth)) return false;
    t->shift_s += dt;
  }
  return true;
}

StateEci state_of(const Vec6& x) noexcept {
  StateEci s;
  s.r_eci_m = x.head<3>();
  s.v_eci_mps = x.tail<3>();
  return s;
}

// The outcome at the new TCA: plane, principal axes (as assessment::principal_axes_into),
// the model's A and the 2D Pc.
CamStatus outcome_at(const ConjunctionEvent& e, const BurnStart& b, const AtTca& t, const OnboardCamOptions& o,
                     CamWorkspace* ws, BurnOutcome* out) noexcept {
  const Mat3 c1 = (t.p1.phi * b.cov1 * t.p1.phi.transpose()).topLeftCorner<3, 3>();
  const Mat3 c2 = (t.p2.phi * e.cov2_eci * t.p2.phi.transpose()).topLeftCorner<3, 3>();
  assessment::EncounterPlane ep;
  if (!assessment::encounter_plane_into(state_of(t.p1.x_eci), c1, state_of(t.p2.x_eci), c2, &ep))
    return CamStatus::kNoEncounter;
  const Eigen::SelfAdjointEigenSolver<Mat2> es(0.5 * (ep.cov_m2 + ep.cov_m2.transpose()));
  const Vec2& l = es.eigenvalues();
  if (!(l(0) > 0.0)) return CamStatus::kNoEncounter;
  const Mat2& q = es.eigenvectors();
  const Vec2 m = q.transpose() * ep.miss_m;
  out->principal = {m(0), m(1), std::sqrt(l(0)), std::sqrt(l(1))};
  Mat23 p;
  p.row(0) = ep.axes_eci.row(0);
  p.row(1) = ep.axes_eci.row(2);
  out->a = -(q.transpose() * p * t.p1.phi.block<3, 3>(0, 3));
  out->tca_shift_s = t.shift_s;
  out->miss_m = ep.miss_3d_m;
  assessment::Pc2dResult pc;
  if (assessment::pc_2d(out->principal, e.hbr_m, o.pc_rel_tol, &ws->pc, &pc) != assessment::Pc2dStatus::kOk)
    return CamStatus::kNoEncounter;
  out->pc = pc.pc;
  return CamStatus::kOk;
}

CamStatus outcome_from(const ConjunctionEvent& e, const BurnStart& b, const Vec3& dv, const OnboardCamOptions& o,
                       const EarthModel& earth, CamWorkspace* ws, BurnOutcome* out) noexcept {
  AtTca t;
  if (!to_new_tca(e, b, dv, o, earth, &t)) return CamStatus::kPropagation;
  return outcome_at(e, b, t, o, ws, out);
}

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

// Step 3 for one aim: models rebuilt about the burn until it settles; *cur its exact outcome.
CamStatus relinearize(const ConjunctionEvent& e, const BurnStart& b, double aim, const OnboardCamOptions& o,
                      const EarthModel& earth, CamWorkspace* ws, Vec3* dv, BurnOutcome* cur, int* count) noexcept {
  for (int k = 0; k < o.relinearizations; ++k) {
    Vec3 next;
    const CamStatus s = solve_model(e, *cur, *dv, aim, o, ws, &next);
    if (s != CamStatus::kOk) return s;
    const CamStatus t = outcome_from(e, b, next, o, earth, ws, cur);
    if (t != CamStatus::kOk) return t;
    ++*count;
    const double change = (next - *dv).norm();
    *dv = next;
    if (change < o.dv_tol_mps) break;
  }
  return CamStatus::kOk;
}

Vec3 eci_to_rsw(const Vec6& x, const Vec3& v_eci) noexcept {
  const Vec3 r = x.head<3>().normalized();
  const Vec3 w = x.head<3>().cross(x.tail<3>()).normalized();
  const Vec3 s = w.cross(r);
  return Vec3(r.dot(v_eci), s.dot(v_eci), w.dot(v_eci));
}

// Step 3 from a starting burn, with the aim corrected after each exact outcome (plan cam's
// rule); out->status kOk when the outcome's Pc meets the target.
CamStatus start_chain(const ConjunctionEvent& e, const BurnStart& b, const Vec3& start, const BurnOutcome& unburned,
                      const OnboardCamOptions& o, const EarthModel& earth, CamWorkspace* ws,
                      CamProposal* out) noexcept {
  const double aim0 = e.pc_target * (1.0 - o.pc_margin);
  double aim = aim0;
  Vec3 dv = start;
  BurnOutcome cur = unburned;
  if (start.squaredNorm() > 0.0) {
    const CamStatus s = outcome_from(e, b, start, o, earth, ws, &cur);
    if (s != CamStatus::kOk) return out->status = s;
  }
  for (int c = 0; c <= o.target_corrections; ++c) {
    const CamStatus s = relinearize(e, b, aim, o, earth, ws, &dv, &cur, &out->relinearizations);
    if (s != CamStatus::kOk) return out->status = s;
    out->aim = aim;
    if (cur.pc <= e.pc_target) break;
    aim = std::min(aim, cur.pc) * aim0 / cur.pc;  // evade plan cam's correction
    out->target_corrections = c + 1;
  }
  out->after = cur;
  out->dv_eci_mps = dv;
  out->dv_rsw_mps = eci_to_rsw(b.x1, dv);
  return out->status = cur.pc <= e.pc_target ? CamStatus::kOk : CamStatus::kUnreachable;
}

}  // namespace

const char* cam_status_name(CamStatus s) noexcept {
  switch (s) {
    case CamStatus::kOk: return "ok";
    case CamStatus::kNotNeeded: return "not_needed";
    case CamStatus::kBadOptions: return "bad_options";
    case CamStatus::kNoBurnTime: return "no_burn_time";
    case CamStatus::kPropagation: return "propagation";
    case CamStatus::kNoEncounter: return "no_encounter";
    case CamStatus::kUnreachable: return "unreachable";
  }
  return "unknown";
}

namespace {

bool counts_ok(const OnboardCamOptions& o) noexcept {
  auto in = [](int v, int lo, int hi) { return v >= lo && v <= hi; };
  return in(o.burn_times, 1, 64) && in(o.boundary_angles, 8, 720) && in(o.bisections, 10, 100) &&
         in(o.golden_iterations, 0, 100) && in(o.relinearizations, 1, 20) && in(o.target_corrections, 0, 10);
}

bool values_ok(const OnboardCamOptions& o) noexcept {
  auto pos = [](double v) { return v > 0.0 && std::isfinite(v); };
  return pos(o.step_s) && o.step_s <= 60.0 && pos(o.max_dv_mps) && o.pc_margin >= 0.0 && o.pc_margin < 1.0 &&
         pos(o.dv_tol_mps) && o.min_lead_s >= 0.0 && std::isfinite(o.min_lead_s) && pos(o.pc_rel_tol);
}

}  // namespace

bool cam_options_ok(const OnboardCamOptions& o) noexcept { return counts_ok(o) && values_ok(o); }

CamStatus burn_outcome(const ConjunctionEvent& e, double burn_from_tca_s, const Vec3& dv_eci_mps,
                       const OnboardCamOptions& o, const EarthModel& earth, CamWorkspace* ws,
                       BurnOutcome* out) noexcept {
  if (!cam_options_ok(o) || !(burn_from_tca_s <= 0.0) || !dv_eci_mps.allFinite()) return CamStatus::kBadOptions;
  BurnStart b;
  if (!primary_at_burn(e, burn_from_tca_s, o, earth, &b)) return CamStatus::kPropagation;
  return outcome_from(e, b, dv_eci_mps, o, earth, ws, out);
}

CamStatus plan_burn_at(const ConjunctionEvent& e, double burn_from_tca_s, const OnboardCamOptions& o,
                       const EarthModel& earth, CamWorkspace* ws, CamProposal* out) noexcept {
  *out = CamProposal{};
  out->burn_from_tca_s = burn_from_tca_s;
  if (!cam_options_ok(o) || !(burn_from_tca_s < 0.0)) return out->status = CamStatus::kBadOptions;
  BurnStart b;
  if (!primary_at_burn(e, burn_from_tca_s, o, earth, &b)) return out->status = CamStatus::kPropagation;
  BurnOutcome cur;
  const CamStatus s0 = outcome_from(e, b, Vec3::Zero(), o, earth, ws, &cur);
  if (s0 != CamStatus::kOk) return out->status = s0;
  out->pc_before = cur.pc;
  if (cur.pc <= e.pc_target) return out->status = CamStatus::kNotNeeded;
  const BurnOutcome unburned = cur;
  const double aim = e.pc_target * (1.0 - o.pc_margin);
  const Vec3 starts[3] = {Vec3::Zero(), along_track_start(e, unburned, b.x1, aim, 1.0, o, ws),
                          along_track_start(e, unburned, b.x1, aim, -1.0, o, ws)};
  CamProposal best = *out;
  best.status = CamStatus::kUnreachable;
  for (int k = 0; k < 3; ++k) {
    const Vec3& start = starts[k];
    if (k > 0 && start.squaredNorm() == 0.0) continue;  // that side is out of reach
    CamProposal p = *out;
    if (start_chain(e, b, start, unburned, o, earth, ws, &p) == CamStatus::kOk &&
        (best.status != CamStatus::kOk || p.dv_eci_mps.norm() < best.dv_eci_mps.norm()))
      best = p;
  }
  *out = std::move(best);
  return out->status;
}

CamStatus plan_burn(const ConjunctionEvent& e, std::int64_t now_us, const OnboardCamOptions& o,
                    const EarthModel& earth, CamWorkspace* ws, CamProposal* out) noexcept {
  *out = CamProposal{};
  if (!cam_options_ok(o)) return out->status = CamStatus::kBadOptions;
  const double earliest_us = static_cast<double>(now_us) + 1e6 * o.min_lead_s;
  const double t0 = 1e-6 * (std::max(static_cast<double>(e.burn_start_us), earliest_us) - static_cast<double>(e.tca_us));
  const double t1 = 1e-6 * static_cast<double>(e.burn_end_us - e.tca_us);
  if (!(t0 <= t1) || !(t1 < 0.0)) return out->status = CamStatus::kNoBurnTime;
  const int n = (t1 > t0) ? o.burn_times : 1;
  CamStatus last = CamStatus::kUnreachable;
  for (int k = 0; k < n; ++k) {
    const double tau = n == 1 ? t1 : t0 + (t1 - t0) * static_cast<double>(k) / static_cast<double>(n - 1);
    CamProposal p;
    last = plan_burn_at(e, tau, o, earth, ws, &p);
    if (last == CamStatus::kNotNeeded) {
      *out = std::move(p);
      return out->status;
    }
    if (last == CamStatus::kOk && (out->status != CamStatus::kOk || p.dv_eci_mps.norm() < out->dv_eci_mps.norm()))
      *out = p;
  }
  if (out->status != CamStatus::kOk) out->status = last;
  return out->status;
}

CamStatus check_other_event(const ConjunctionEvent& other, std::int64_t burn_us, const Vec3& dv_eci_mps,
                            const OnboardCamOptions& o, const EarthModel& earth, CamWorkspace* ws,
                            BurnOutcome* out, bool* within_red) noexcept {
  *within_red = false;
  const double tau = 1e-6 * static_cast<double>(burn_us - other.tca_us);
  // A burn after the other event's TCA leaves it as it is.
  const CamStatus s = burn_outcome(other, std::min(tau, 0.0), tau < 0.0 ? dv_eci_mps : Vec3::Zero(), o, earth,
                                   ws, out);
  if (s == CamStatus::kOk) *within_red = out->pc <= other.pc_red;
  return s;
}

}  // namespace evade::autonomy
