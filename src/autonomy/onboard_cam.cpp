// The onboard avoidance burn (include/evade/autonomy/onboard_cam.hpp gives the model and its
// sources).
#include "evade/autonomy/onboard_cam.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "evade/assessment/encounter_2d.hpp"
#include "evade/assessment/symmetric_eigen.hpp"
#include "evade/autonomy/internal/cam_boundary.hpp"
#include "evade/autonomy/orbit_stm.hpp"
#include "evade/core/constants.hpp"

namespace evade::autonomy {

namespace {

constexpr int kTcaIterations = 8;        // Newton steps on the range rate
constexpr double kTcaTolS = 1e-7;        // |dt| that ends them [s]
constexpr double kMaxTcaShiftS = 3600.0; // a burn moving the TCA further is another encounter
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
  Vec2 l;
  Mat2 q;
  assessment::symmetric_eigen_2x2(ep.cov_m2, &l, &q);  // as principal_axes_into
  if (!(l(0) > 0.0)) return CamStatus::kNoEncounter;
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

bool cam_options_ok(const OnboardCamOptions& o) noexcept {
  for (const Param<OnboardCamOptions>& p : cam_options_params()) {
    if (!param_value_ok(p.spec, p.get(o))) return false;
  }
  return true;
}

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

int candidate_burn_times(const ConjunctionEvent& e, std::int64_t now_us, const OnboardCamOptions& o,
                         double* taus_s) noexcept {
  if (!cam_options_ok(o)) return 0;
  const double earliest_us = static_cast<double>(now_us) + 1e6 * o.min_lead_s;
  const double t0 = 1e-6 * (std::max(static_cast<double>(e.burn_start_us), earliest_us) - static_cast<double>(e.tca_us));
  const double t1 = 1e-6 * static_cast<double>(e.burn_end_us - e.tca_us);
  if (!(t0 <= t1) || !(t1 < 0.0)) return 0;
  const int n = (t1 > t0) ? o.burn_times : 1;
  for (int k = 0; k < n; ++k)
    taus_s[k] = n == 1 ? t1 : t0 + (t1 - t0) * static_cast<double>(k) / static_cast<double>(n - 1);
  return n;
}

CamStatus plan_burn(const ConjunctionEvent& e, std::int64_t now_us, const OnboardCamOptions& o,
                    const EarthModel& earth, CamWorkspace* ws, CamProposal* out) noexcept {
  *out = CamProposal{};
  if (!cam_options_ok(o)) return out->status = CamStatus::kBadOptions;
  std::array<double, OnboardCamOptions::kMaxBurnTimes> taus{};
  const int n = candidate_burn_times(e, now_us, o, taus.data());
  if (n == 0) return out->status = CamStatus::kNoBurnTime;
  CamStatus last = CamStatus::kUnreachable;
  for (int k = 0; k < n; ++k) {
    CamProposal p;
    last = plan_burn_at(e, taus[static_cast<std::size_t>(k)], o, earth, ws, &p);
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
