// The minimum-dv collision-avoidance burn (include/evade/cam/cam_planner.hpp gives the
// method and the sources).
#include "evade/cam/cam_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlopt.hpp>

#include "evade/assessment/encounter_plane.hpp"

namespace evade::cam {
namespace {

using Mat23 = Eigen::Matrix<double, 2, 3>;

std::string num(double x) {
  char b[32];
  // %.6g is at most 13 characters: the count snprintf returns is not needed.
  (void)std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

bool feasible(const EncounterOutcome& e, double pc_target, double min_miss_m) {
  return e.pc <= pc_target && e.miss_m >= min_miss_m;
}

[[noreturn]] void unreachable(const CamRequest& req, double dv_mps, const CamConfig& cfg) {
  throw std::invalid_argument(
      "pc_max = " + num(req.pc_max) + (req.min_miss_m > 0 ? " with min_miss_m = " + num(req.min_miss_m) : "") +
      " is unreachable at lead_s = " + num(req.lead_s) + " s" +
      (req.along_track_only ? " (along track only)" : "") + ": it needs |dv| " +
      (std::isfinite(dv_mps) ? "= " + num(dv_mps) : "beyond the search") + " m/s > cam.max_dv_mps = " +
      num(cfg.max_dv_mps) + " m/s");
}

// The model with the encounter plane held at the reference TCA (step 1).
struct PlaneModel {
  assessment::Vec2 m0 = assessment::Vec2::Zero();  ///< miss point of dv = 0
  Mat23 a = Mat23::Zero(); ///< d miss point / d dv_rtn
  assessment::Mat2 w = assessment::Mat2::Identity();  ///< (A A^T)^-1
  assessment::Mat2 cov = assessment::Mat2::Identity();
  double hbr_m = 0.0, rel_tol = 1e-8;

  double pc(const assessment::Vec2& m) const {
    assessment::EncounterPlane ep;
    ep.miss_m = m;
    ep.cov_m2 = cov;
    return assessment::pc_2d(assessment::principal_axes(ep), hbr_m, rel_tol).pc;
  }
  double cost(const assessment::Vec2& m) const { return (m - m0).dot(w * (m - m0)); }
  Vec3 burn(const assessment::Vec2& m) const { return a.transpose() * (w * (m - m0)); }
};

PlaneModel plane_model(const CamLinearModel& m) {
  const assessment::EncounterPlane ep = assessment::encounter_plane(m.primary_ref, m.cov1_m2, m.secondary_ref, m.cov2_m2);
  Mat23 p;
  p.row(0) = ep.axes_eci.row(0);
  p.row(1) = ep.axes_eci.row(2);
  PlaneModel pm;
  pm.a = -p * m.dr_ddv;
  pm.m0 = p * (m.secondary_ref.r_eci_m - m.primary_ref.r_eci_m) - pm.a * m.dv_ref_rtn_mps;
  const assessment::Mat2 aat = pm.a * pm.a.transpose();
  if (!(std::abs(aat.determinant()) > 1e-30 * aat.squaredNorm()))
    throw std::invalid_argument("the burn cannot move the miss point in two directions");
  pm.w = aat.inverse();
  pm.cov = ep.cov_m2;
  pm.hbr_m = m.hbr_m;
  pm.rel_tol = m.pc_rel_tol;
  return pm;
}

// Smallest radius >= min_miss_m along u where Pc <= p (Pc decreases along the ray).
double boundary_radius(const PlaneModel& pm, const assessment::Vec2& u, double p, double min_miss_m) {
  double lo = min_miss_m;
  if (pm.pc(lo * u) <= p) return lo;
  double hi = std::max(2.0 * lo, std::sqrt(pm.cov.trace()) + pm.hbr_m);
  for (int i = 0; i < 200 && pm.pc(hi * u) > p; ++i) {
    lo = hi;
    hi *= 2.0;
  }
  for (int i = 0; i < 100 && hi - lo > 1e-9 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (pm.pc(mid * u) > p ? lo : hi) = mid;
  }
  return hi;
}

assessment::Vec2 boundary_point(const PlaneModel& pm, double theta, double p, double min_miss_m) {
  const assessment::Vec2 u(std::cos(theta), std::sin(theta));
  return boundary_radius(pm, u, p, min_miss_m) * u;
}

// Golden-section refinement of the boundary cost on [lo, hi] (a bracket of a grid minimum).
double refine_angle(const PlaneModel& pm, double lo, double hi, double p, double min_miss_m,
                    double* cost) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = pm.cost(boundary_point(pm, x1, p, min_miss_m));
  double f2 = pm.cost(boundary_point(pm, x2, p, min_miss_m));
  for (int i = 0; i < 60 && hi - lo > 1e-12; ++i) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo);
      f1 = pm.cost(boundary_point(pm, x1, p, min_miss_m));
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo);
      f2 = pm.cost(boundary_point(pm, x2, p, min_miss_m));
    }
  }
  *cost = std::min(f1, f2);
  return f1 < f2 ? x1 : x2;
}

// Step 1: every local minimum of the boundary cost on the grid of directions, refined by
// golden section; the best. (Near a whole number of orbits the radial and normal burns barely
// move the miss point, A A^T is nearly singular and the cost has sharp valleys where the
// along-track line crosses the boundary: each valley is refined, not only the grid's best.)
Vec3 sweep_boundary(const PlaneModel& pm, double p, double min_miss_m, int angles) {
  const double step = kTwoPi / angles;
  std::vector<double> c(static_cast<std::size_t>(angles));
  for (int k = 0; k < angles; ++k)
    c[static_cast<std::size_t>(k)] = pm.cost(boundary_point(pm, k * step, p, min_miss_m));
  double best_theta = 0.0, best_cost = std::numeric_limits<double>::infinity();
  for (int k = 0; k < angles; ++k) {
    const double ck = c[static_cast<std::size_t>(k)];
    const double cl = c[static_cast<std::size_t>((k + angles - 1) % angles)];
    const double cr = c[static_cast<std::size_t>((k + 1) % angles)];
    if (ck > cl || ck > cr) continue;  // not a local minimum of the grid
    if (ck < best_cost) best_cost = ck, best_theta = k * step;
    double refined = 0.0;
    const double t = refine_angle(pm, (k - 1) * step, (k + 1) * step, p, min_miss_m, &refined);
    if (refined < best_cost) best_cost = refined, best_theta = t;
  }
  return pm.burn(boundary_point(pm, best_theta, p, min_miss_m));
}

struct NloptData {
  const CamLinearModel* m;
  double p, min_miss_m;
};

double constraint_value(const NloptData& d, const Vec3& x, int which) {
  const EncounterOutcome e = d.m->predict(x);
  if (which == 0) return std::log(std::max(e.pc, 1e-300) / d.p);
  return (d.min_miss_m - e.miss_m) / std::max(d.min_miss_m, 1.0);
}

template <int kWhich>
double nlopt_constraint(unsigned, const double* x, double* grad, void* data) {
  const auto& d = *static_cast<const NloptData*>(data);
  const Vec3 v(x[0], x[1], x[2]);
  if (grad) {
    const double h = 1e-5 * std::max(v.norm(), 1e-4);
    for (int j = 0; j < 3; ++j) {
      Vec3 vp = v, vm = v;
      vp(j) += h;
      vm(j) -= h;
      grad[j] = (constraint_value(d, vp, kWhich) - constraint_value(d, vm, kWhich)) / (2.0 * h);
    }
  }
  return constraint_value(d, v, kWhich);
}

double nlopt_objective(unsigned, const double* x, double* grad, void*) {
  if (grad) for (int j = 0; j < 3; ++j) grad[j] = 2.0 * x[j];
  return x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
}

// Step 2: SLSQP on the full linear model from the sweep's burn.
Vec3 polish(const CamLinearModel& m, const CamRequest& req, double p, const Vec3& start,
            int* result) {
  NloptData d{&m, p, req.min_miss_m};
  nlopt::opt o(nlopt::LD_SLSQP, 3);
  o.set_min_objective(nlopt_objective, nullptr);
  o.add_inequality_constraint(nlopt_constraint<0>, &d, 1e-10);
  if (req.min_miss_m > 0.0) o.add_inequality_constraint(nlopt_constraint<1>, &d, 1e-10);
  o.set_xtol_rel(1e-10);
  o.set_maxeval(200);
  std::vector<double> x(start.data(), start.data() + 3);
  double f = 0.0;
  try {
    *result = static_cast<int>(o.optimize(x, f));
  } catch (const std::exception&) {
    *result = -1;
    return start;
  }
  const Vec3 v(x[0], x[1], x[2]);
  return feasible(m.predict(v), p, req.min_miss_m) && v.norm() <= start.norm() ? v : start;
}

// The smallest scale >= 1 of dv that the model finds feasible (closes the fixed-plane gap).
Vec3 make_feasible(const CamLinearModel& m, const CamRequest& req, double p, const Vec3& dv) {
  if (feasible(m.predict(dv), p, req.min_miss_m)) return dv;
  double lo = 1.0, hi = 1.0 + 1e-9;
  while (!feasible(m.predict(hi * dv), p, req.min_miss_m)) {
    lo = hi;
    hi = 1.0 + 2.0 * (hi - 1.0);
    if (hi > 2.0) return Vec3::Constant(std::numeric_limits<double>::infinity());
  }
  for (int i = 0; i < 60 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (feasible(m.predict(mid * dv), p, req.min_miss_m) ? hi : lo) = mid;
  }
  return hi * dv;
}

// along_track_only: the first feasible |dv_T| on each side (bracket, then bisection).
Vec3 solve_along_track(const CamLinearModel& m, const CamRequest& req, double p,
                       const CamConfig& cfg) {
  double best = std::numeric_limits<double>::infinity();
  for (const double sign : {1.0, -1.0}) {
    const auto ok = [&](double s) {
      return feasible(m.predict(Vec3(0.0, sign * s, 0.0)), p, req.min_miss_m);
    };
    double lo = 0.0, hi = 1e-7;
    while (!ok(hi) && hi <= 2.0 * cfg.max_dv_mps) lo = hi, hi *= 2.0;
    if (!ok(hi)) continue;
    for (int i = 0; i < 100 && hi - lo > 1e-12 * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (ok(mid) ? hi : lo) = mid;
    }
    if (hi < std::abs(best)) best = sign * hi;
  }
  if (!std::isfinite(best)) unreachable(req, best, cfg);
  return Vec3(0.0, best, 0.0);
}

// The better start of the encounter-plane sweep (scaled until the full model finds it
// feasible, within 2x) and the along-track burn; throws when neither gives one.
Vec3 best_start(const CamLinearModel& m, const CamRequest& req, double p, const CamConfig& cfg) {
  const PlaneModel pm = plane_model(m);
  Vec3 start = make_feasible(m, req, p, sweep_boundary(pm, p, req.min_miss_m, cfg.boundary_angles));
  try {
    const Vec3 along = solve_along_track(m, req, p, cfg);
    if (!(along.norm() >= start.norm())) start = along;  // also replaces a failed sweep
  } catch (const std::invalid_argument&) {
    if (!start.allFinite()) {
      throw std::invalid_argument(
          "the linear model has no feasible burn: the encounter-plane sweep's burn stays "
          "infeasible when scaled up to 2x and no along-track burn within cam.max_dv_mps = " +
          num(cfg.max_dv_mps) + " m/s meets the request");
    }
  }
  return start;
}

}  // namespace

void validate_cam_request(const CamRequest& req, const CamConfig& cfg) {
  if (!std::isfinite(req.lead_s) || !(req.lead_s > 0.0))
    throw std::invalid_argument("lead_s = " + num(req.lead_s) + ": must be a finite time > 0 s");
  if (req.lead_s > cfg.max_lead_s)
    throw std::invalid_argument("lead_s = " + num(req.lead_s) + " s is past the span " +
                                "cam.max_lead_s = " + num(cfg.max_lead_s) + " s");
  if (!(req.pc_max > 0.0 && req.pc_max < 1.0))
    throw std::invalid_argument("pc_max = " + num(req.pc_max) + ": must be in (0, 1)");
  if (!std::isfinite(req.min_miss_m) || req.min_miss_m < 0.0)
    throw std::invalid_argument("min_miss_m = " + num(req.min_miss_m) + ": must be >= 0 m");
}

Vec3 solve_cam_model(const CamLinearModel& m, const CamRequest& req, double pc_target,
                     const CamConfig& cfg, std::string* search, int* nlopt_result) {
  *nlopt_result = 0;
  Vec3 dv = Vec3::Zero();
  if (feasible(m.predict(dv), pc_target, req.min_miss_m)) {
    *search = "none: the model meets the request without a burn";
  } else if (req.along_track_only) {
    dv = solve_along_track(m, req, pc_target, cfg);
    *search = "along-track 1-D: bracket and bisection of the first feasible |dv_T| on each side";
  } else {
    dv = polish(m, req, pc_target, best_start(m, req, pc_target, cfg), nlopt_result);
    *search = "encounter-plane boundary sweep (" + std::to_string(cfg.boundary_angles) +
              " directions, every local minimum refined by golden section) and the along-track "
              "burn as starts, + NLopt SLSQP";
  }
  if (!(dv.norm() <= cfg.max_dv_mps)) unreachable(req, dv.norm(), cfg);
  return dv;
}

namespace {

// The burn for one 2D target (steps 1-3 above), its exact outcome and its recommended Pc.
void plan_for_target(const CamEncounter& enc, const CamRequest& aim, const CamConfig& cfg,
                     const CamLinearModel& first, CamPlan* plan) {
  CamLinearModel m = first;
  for (int k = 0; k < cfg.max_relinearizations; ++k) {
    const Vec3 dv =
        solve_cam_model(m, aim, plan->pc_target_2d, cfg, &plan->search, &plan->nlopt_result);
    plan->last_change_mps = (dv - m.dv_ref_rtn_mps).norm();
    plan->dv_rtn_mps = dv;
    plan->predicted = m.predict(dv);
    plan->relinearizations = k + 1;
    if (plan->last_change_mps < cfg.dv_tol_mps || k + 1 == cfg.max_relinearizations) break;
    m = enc.linearize(dv);
  }
  plan->predicted_first = first.predict(plan->dv_rtn_mps);
  plan->dv_mps = plan->dv_rtn_mps.norm();
  plan->dv_eci_mps = enc.rtn_to_eci() * plan->dv_rtn_mps;
  plan->verified = enc.outcome(plan->dv_rtn_mps);
  plan->verified_recommended = enc.recommended_pc(plan->dv_rtn_mps);
}

bool recommended_ok(const EncounterOutcome& e, const RecommendedPc& r, const CamRequest& req) {
  return r.pc <= req.pc_max && e.miss_m >= req.min_miss_m;
}

}  // namespace

CamPlan plan_cam(const CamEncounter& enc, const CamRequest& req, const CamConfig& cfg) {
  validate_cam_request(req, cfg);
  const assessment::Assessment& a = enc.assessment();
  CamPlan plan;
  plan.lead_s = enc.lead_s();
  plan.tca_from_epoch_s = a.tca_shift_s;
  plan.burn_from_epoch_s = a.tca_shift_s - enc.lead_s();
  plan.primary_at_burn = enc.primary_at_burn();
  plan.pc_target = req.pc_max * (1.0 - cfg.pc_margin);
  plan.pc_target_2d = plan.pc_target;
  plan.before = {0.0, assessment::pc_of(a.plane_pc, assessment::PcMethod::k2d), a.plane.miss_3d_m, a.plane.rel_speed_mps};
  plan.before_recommended = enc.recommended_pc_before();
  if (recommended_ok(plan.before, plan.before_recommended, req)) {
    plan.maneuver_needed = false;
    plan.predicted = plan.predicted_first = plan.verified = plan.before;
    plan.verified_recommended = plan.before_recommended;
    plan.verified_ok = true;
    plan.search = "none: the recommended Pc and the miss already meet the request";
    return plan;
  }
  CamRequest aim = req;  // what the planner aims at: the request with its margins
  if (req.min_miss_m > 0.0) aim.min_miss_m = req.min_miss_m + cfg.miss_margin_m;
  const CamLinearModel first = enc.linearize(Vec3::Zero());
  for (int j = 0; j <= cfg.max_target_corrections; ++j) {
    plan_for_target(enc, aim, cfg, first, &plan);
    plan.target_corrections = j;
    plan.verified_ok = recommended_ok(plan.verified, plan.verified_recommended, req);
    const double p_rec = plan.verified_recommended.pc;
    if (plan.verified_ok || !(p_rec > 0.0) || plan.verified_recommended.method == "2d") break;
    plan.pc_target_2d =
        std::min(plan.pc_target_2d, plan.verified.pc) * plan.pc_target / p_rec;
  }
  return plan;
}

CamPlan plan_cam(const assessment::ConjunctionInput& in, const CamRequest& req, const assessment::AssessConfig& acfg,
                 const CamConfig& cfg) {
  validate_cam_request(req, cfg);
  return plan_cam(CamEncounter(in, req.lead_s, acfg), req, cfg);
}

std::vector<CamSweepRow> sweep_cam_lead(const assessment::ConjunctionInput& in, const std::vector<double>& leads_s,
                                        const CamRequest& req, const assessment::AssessConfig& acfg,
                                        const CamConfig& cfg) {
  std::vector<CamSweepRow> rows;
  for (const double lead : leads_s) {
    CamSweepRow row;
    row.lead_s = lead;
    CamRequest r = req;
    r.lead_s = lead;
    try {
      row.plan = plan_cam(in, r, acfg, cfg);
      row.ok = true;
    } catch (const std::invalid_argument& e) {
      row.error = e.what();
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace evade::cam
