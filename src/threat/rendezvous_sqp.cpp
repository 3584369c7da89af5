// N-impulse (N = 2..4) minimum-total-Δv HCW rendezvous with fixed transfer time, solved by
// SQP (NLopt LD_SLSQP) with analytic gradients. Paper 001 (Yu, Wang, Sun 2017) sec. 2.1,
// eq. 3 (min Σ|Δv_k| over impulse times and vectors, fixed t0/tf and boundary states); the
// paper uses SQP too. Formulation, gradient derivation and smoothing: see rendezvous_sqp.hpp.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

#include <nlopt.hpp>

#include "evade/dynamics/hcw.hpp"
#include "evade/threat/rendezvous_sqp.hpp"

namespace evade::threat {
namespace {

struct Problem {
  const HcwTransfer* tr;
  const Vec6* d;
  int m;       // intermediate impulses N − 2
  double eps;  // smoothing
};

// Φvv'(s) = dΦvv/ds (entrywise derivative of the closed form in hcw.cpp).
Mat3 dphi_vv_ds(double n, double s_time) {
  const double c = std::cos(n * s_time);
  const double s = std::sin(n * s_time);
  Mat3 m;
  m << -n * s, 2.0 * n * c, 0.0,
       -2.0 * n * c, -4.0 * n * s, 0.0,
       0.0, 0.0, -n * s;
  return m;
}

double phi(const Vec3& v, double eps) { return std::sqrt(v.squaredNorm() + eps * eps) - eps; }
Vec3 dphi(const Vec3& v, double eps) { return v / std::sqrt(v.squaredNorm() + eps * eps); }

// The end impulses closing the residual of the intermediate ones.
void end_impulses(const HcwTransfer& tr, const Vec6& d, int m, const double* x, Vec3& dv1,
                  Vec3& dvn) {
  Vec6 e = d;
  for (int i = 0; i < m; ++i) {
    const Vec3 dv(x[m + 3 * i], x[m + 3 * i + 1], x[m + 3 * i + 2]);
    const HcwBlocks b = hcw_stm_blocks(tr.n_radps(), tr.transfer_s() - x[i]);
    e.head<3>() -= b.rv * dv;
    e.tail<3>() -= b.vv * dv;
  }
  dv1 = tr.phi_rv_T_inv() * e.head<3>();
  dvn = e.tail<3>() - tr.phi_vv_T() * dv1;
}

double objective(const Problem& p, const double* x, double* grad) {
  const HcwTransfer& tr = *p.tr;
  const int m = p.m;
  const double T = tr.transfer_s();
  const double n = tr.n_radps();
  Vec3 dv1, dvn;
  end_impulses(tr, *p.d, m, x, dv1, dvn);
  double J = phi(dv1, p.eps) + phi(dvn, p.eps);
  for (int i = 0; i < m; ++i) {
    J += phi(Vec3(x[m + 3 * i], x[m + 3 * i + 1], x[m + 3 * i + 2]), p.eps);
  }
  if (grad != nullptr) {
    const Vec3 g1 = dphi(dv1, p.eps);
    const Vec3 gn = dphi(dvn, p.eps);
    const Vec3 lr = tr.phi_rv_T_inv().transpose() * (g1 - tr.phi_vv_T().transpose() * gn);
    const Vec3& lv = gn;
    for (int i = 0; i < m; ++i) {
      const Vec3 dv(x[m + 3 * i], x[m + 3 * i + 1], x[m + 3 * i + 2]);
      const double s = T - x[i];
      const HcwBlocks b = hcw_stm_blocks(n, s);
      // ∂J/∂Δv_i = g_i − B(s)ᵀλ
      const Vec3 gdv = dphi(dv, p.eps) - (b.rv.transpose() * lr + b.vv.transpose() * lv);
      // ∂J/∂τ_i = λᵀ B'(s) Δv_i, B'(s) = [Φvv(s); Φvv'(s)]
      grad[i] = lr.dot(b.vv * dv) + lv.dot(dphi_vv_ds(n, s) * dv);
      for (int k = 0; k < 3; ++k) grad[m + 3 * i + k] = gdv(k);
    }
  }
  return J;
}

double nlopt_objective(unsigned nvar, const double* x, double* grad, void* data) {
  (void)nvar;
  return objective(*static_cast<const Problem*>(data), x, grad);
}

RendezvousPlan plan_from_vars(const HcwTransfer& tr, const Vec6& d, int m, const double* x) {
  Vec3 dv1, dvn;
  end_impulses(tr, d, m, x, dv1, dvn);
  RendezvousPlan plan;
  plan.impulses.push_back({0.0, dv1});
  for (int i = 0; i < m; ++i) {
    plan.impulses.push_back({x[i], Vec3(x[m + 3 * i], x[m + 3 * i + 1], x[m + 3 * i + 2])});
  }
  plan.impulses.push_back({tr.transfer_s(), dvn});
  std::sort(plan.impulses.begin() + 1, plan.impulses.end() - 1,
            [](const Impulse& a, const Impulse& b) { return a.t_s < b.t_s; });
  plan.cost_mps = 0.0;
  for (const Impulse& imp : plan.impulses) plan.cost_mps += imp.dv_rsw_mps.norm();
  return plan;
}

void check_inputs(const Vec6& d, const SqpOptions& opt) {
  if (opt.impulses < 2 || opt.impulses > 4) {
    throw std::invalid_argument("optimize_rendezvous: impulses = " +
                                std::to_string(opt.impulses) + " must be in [2, 4]");
  }
  if (!d.allFinite()) {
    throw std::invalid_argument("optimize_rendezvous: required state change is not finite");
  }
  if (opt.starts < 1 || !(opt.smoothing_mps > 0.0)) {
    throw std::invalid_argument("optimize_rendezvous: starts >= 1 and smoothing_mps > 0 needed");
  }
}

// Start k: intermediate times (start 0's first at the primer's maximum, the others spread by
// the golden ratio) with impulses of dv0_mps along the primer there.
std::vector<double> start_point(const HcwTransfer& tr, const PrimerBound& pb, const Vec6& lambda,
                                int m, int k, double dv0_mps) {
  const double T = tr.transfer_s();
  const double kGolden = 0.6180339887498949;
  std::vector<double> x(static_cast<std::size_t>(4 * m));
  for (int i = 0; i < m; ++i) {
    double frac;
    if (k == 0 && i == 0) {
      frac = pb.primer_argmax_s / T;  // where |p| is largest: an added impulse pays most
    } else {
      frac = std::fmod((i + 1.0) / (m + 1.0) + k * kGolden, 1.0);
    }
    x[i] = std::clamp(frac * T, 0.0, T);
    Vec3 pdir = tr.primer(lambda, x[i]);
    if (pdir.norm() > 0.0) pdir.normalize();
    const Vec3 dv0 = dv0_mps * pdir;
    for (int c = 0; c < 3; ++c) x[m + 3 * i + c] = dv0(c);
  }
  return x;
}

// One SLSQP run from x within [lb, ub]; x ends at the last iterate (a valid plan even when
// NLopt stops on round-off or another failure: its exact cost judges it).
void run_slsqp(const Problem& prob, const SqpOptions& opt, const std::vector<double>& lb,
               const std::vector<double>& ub, std::vector<double>& x) {
  nlopt::opt o(nlopt::LD_SLSQP, static_cast<unsigned>(x.size()));
  o.set_lower_bounds(lb);
  o.set_upper_bounds(ub);
  o.set_min_objective(nlopt_objective, const_cast<Problem*>(&prob));
  o.set_xtol_rel(opt.xtol_rel);
  o.set_ftol_abs(opt.ftol_abs);
  o.set_maxeval(opt.max_eval_per_start);
  if (std::isfinite(opt.stop_at_cost_mps) && opt.stop_at_cost_mps > 0.0) {
    o.set_stopval(opt.stop_at_cost_mps - opt.impulses * opt.smoothing_mps);
  }
  double f = 0.0;
  try {
    o.optimize(x, f);
  } catch (const nlopt::roundoff_limited&) {
    // x holds the last iterate: still a valid plan, judged by its exact cost below.
  } catch (const std::runtime_error&) {  // NOLINT(bugprone-empty-catch): see below
    // generic NLopt failure: x still holds a valid (if unconverged) plan.
  }
}

}  // namespace

double sqp_objective(const HcwTransfer& tr, const Vec6& d, int impulses, double smoothing_mps,
                     const std::vector<double>& vars, std::vector<double>* grad) {
  const int m = impulses - 2;
  if (m < 0 || static_cast<int>(vars.size()) != 4 * m) {
    throw std::invalid_argument("sqp_objective: vars must hold 4*(impulses-2) values");
  }
  const Problem p{&tr, &d, m, smoothing_mps};
  if (grad != nullptr) grad->assign(vars.size(), 0.0);
  return objective(p, vars.data(), grad != nullptr ? grad->data() : nullptr);
}

RendezvousPlan optimize_rendezvous(const HcwTransfer& tr, const Vec6& d, const SqpOptions& opt) {
  check_inputs(d, opt);
  RendezvousPlan best = tr.two_impulse(d);
  const int m = opt.impulses - 2;
  if (m == 0 || best.cost_mps == 0.0) return best;
  if (best.cost_mps <= opt.stop_at_cost_mps) return best;

  const double T = tr.transfer_s();
  const PrimerBound pb = tr.primer_bound(d);
  const Vec6 lambda = tr.primer_lambda(d);
  const double dv_bound = 2.0 * best.cost_mps + 1.0;
  const unsigned nvar = static_cast<unsigned>(4 * m);
  std::vector<double> lb(nvar, -dv_bound), ub(nvar, dv_bound);
  for (int i = 0; i < m; ++i) {
    lb[i] = 0.0;
    ub[i] = T;
  }
  const Problem prob{&tr, &d, m, opt.smoothing_mps};
  for (int k = 0; k < opt.starts; ++k) {
    std::vector<double> x = start_point(tr, pb, lambda, m, k, 0.05 * best.cost_mps);
    run_slsqp(prob, opt, lb, ub, x);
    RendezvousPlan cand = plan_from_vars(tr, d, m, x.data());
    if (std::isfinite(cand.cost_mps) && cand.cost_mps < best.cost_mps) best = std::move(cand);
    if (best.cost_mps <= opt.stop_at_cost_mps) break;
    if (opt.stop_at_cost_mps >= 0.0 &&
        best.cost_mps > opt.stop_at_cost_mps + opt.decision_margin_mps) {
      break;  // decision mode: clearly above the threshold after the primer-guided start
    }
  }
  return best;
}

}  // namespace evade::threat
