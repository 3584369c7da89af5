// Lower bound of the threat arc over a ball of evasion burns (include/evade/threat/arc_bound.hpp).
// Paper 001 (Yu, Wang, Sun 2017) sec. 3.1, eq. 4–7 (arc after the burn); the bound of the
// chaser's cost over the ball (end impulses of a feasible plan plus the 2-impulse plan of the
// change, Lipschitz or second order) is derived in the header.
#include "evade/threat/arc_bound.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "evade/dynamics/hcw.hpp"

namespace evade::threat {
namespace {

using Mat63 = Eigen::Matrix<double, 6, 3>;

double spectral_norm(const Mat3& m) {
  const Eigen::SelfAdjointEigenSolver<Mat3> es(m.transpose() * m, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, es.eigenvalues().maxCoeff())) * (1.0 + 1e-12);
}

// max over the ball of |a + V_E G (e' − e)| (G = V_E-free map, norm gn), header's two forms.
double term_bound(const Vec3& a, const Mat3& g, double gn, const Vec3& e, double dv_mps,
                  double chord) {
  const double na = a.norm();
  const double lip = gn * dv_mps * chord;
  if (na == 0.0) return lip;
  const Vec3 h = dv_mps * (g.transpose() * (a / na));
  const double hr = h.dot(e);
  const double htan = std::sqrt(std::max(0.0, h.squaredNorm() - hr * hr));
  const double second = htan * chord + std::max(0.0, -hr) * 0.5 * chord * chord +
                        gn * gn * dv_mps * dv_mps * chord * chord / (2.0 * na);
  return na + std::min(lip, second) * (1.0 + 1e-12);
}

}  // namespace

ArcBound::ArcBound(const ThreatAreaSolver& solver) : solver_(solver) {
  const ThreatOptions& o = solver.options();
  const double n = solver.geometry().n_radps;
  const long k = static_cast<long>(std::ceil(o.span_s / o.step_s - 1e-9));
  for (long i = 0; i < k; ++i) {
    const double t = static_cast<double>(i) * o.step_s;
    t_.push_back(t);
    w_.push_back(solver.required_change(t, Vec3::Zero()));
    b_.push_back(hcw_impulse_matrix(n, t + o.transfer_s));
    maps_.push_back(maps_at(t));
  }
}

ArcBound::Maps ArcBound::maps_at(double t_s) const {
  const HcwTransfer& tr = solver_.transfer();
  const Mat63 b = hcw_impulse_matrix(solver_.geometry().n_radps, t_s + solver_.options().transfer_s);
  Maps m;
  m.m1 = tr.phi_rv_T_inv() * b.topRows<3>();
  m.m2 = b.bottomRows<3>() - tr.phi_vv_T() * m.m1;
  m.n1 = spectral_norm(m.m1);
  m.n2 = spectral_norm(m.m2);
  return m;
}

double ArcBound::cost_upper(const Vec6& d, const Maps& m, const Ball& ball, bool sqp,
                            double t_s) const {
  const HcwTransfer& tr = solver_.transfer();
  const Vec3 dv1 = tr.phi_rv_T_inv() * d.head<3>();
  const Vec3 dv2 = d.tail<3>() - tr.phi_vv_T() * dv1;
  double best = term_bound(dv1, m.m1, m.n1, ball.e, ball.dv_mps, ball.chord) +
                term_bound(dv2, m.m2, m.n2, ball.e, ball.dv_mps, ball.chord);
  if (sqp && solver_.options().impulses > 2) {
    // Any feasible plan will do: a 3-impulse one (a 4-impulse plan with a zero impulse) from
    // one SLSQP start costs a fraction of the full-effort N-impulse search.
    SqpOptions so = solver_.options().sqp;
    so.impulses = 3;
    so.starts = 1;
    so.stop_at_cost_mps = -1.0;
    (void)t_s;
    const RendezvousPlan p = optimize_rendezvous(tr, d, so);
    const Vec3& a1 = p.impulses.front().dv_rsw_mps;
    const Vec3& a2 = p.impulses.back().dv_rsw_mps;
    const double mid = std::max(0.0, p.cost_mps - a1.norm() - a2.norm());
    best = std::min(best, mid + term_bound(a1, m.m1, m.n1, ball.e, ball.dv_mps, ball.chord) +
                              term_bound(a2, m.m2, m.n2, ball.e, ball.dv_mps, ball.chord));
  }
  return best;
}

bool ArcBound::certain(double t_s, const Ball& ball, bool sqp) const {
  const Vec6 d = solver_.required_change(t_s, ball.dv_mps * ball.e);
  return cost_upper(d, maps_at(t_s), ball, sqp, t_s) <= solver_.options().dv_max_mps;
}

double ArcBound::certain_edge(double certain_t, double other_t, const Ball& ball,
                              bool sqp) const {
  const double tol = solver_.options().edge_tol_s;
  if (tol <= 0.0) return certain_t;
  double c = certain_t, u = other_t;
  while (std::abs(c - u) > tol) {
    const double mid = 0.5 * (c + u);
    (certain(mid, ball, sqp) ? c : u) = mid;
  }
  return c;
}

std::vector<char> ArcBound::certain_points(const Ball& ball) const {
  const double vmax = solver_.options().dv_max_mps;
  const long k = static_cast<long>(t_.size());
  const Vec3 dv = ball.dv_mps * ball.e;
  std::vector<char> sure(k, 0);
  const HcwTransfer& tr = solver_.transfer();
  for (long i = 0; i < k; ++i) {
    // Shortcuts: the bound is ≥ the 2-impulse cost and ≤ it plus the Lipschitz term.
    const Vec6 d = w_[i] + b_[i] * dv;
    const double j2 = tr.two_impulse_cost(d);
    if (j2 > vmax) continue;
    if (j2 + (maps_[i].n1 + maps_[i].n2) * ball.dv_mps * ball.chord * (1.0 + 1e-12) <= vmax) {
      sure[i] = 1;
      continue;
    }
    sure[i] = cost_upper(d, maps_[i], ball, false, t_[i]) <= vmax ? 1 : 0;
  }
  return sure;
}

void ArcBound::grow_runs(std::vector<char>& sure, const Ball& ball) const {
  const double vmax = solver_.options().dv_max_mps;
  const long k = static_cast<long>(t_.size());
  const Vec3 dv = ball.dv_mps * ball.e;
  std::vector<char> tested(k, 0);
  for (bool grew = true; grew;) {
    grew = false;
    for (long i = 0; i < k; ++i) {
      const bool next_to = (i > 0 && sure[i - 1]) || (i + 1 < k && sure[i + 1]);
      if (sure[i] || tested[i] || !next_to) continue;
      tested[i] = 1;
      if (cost_upper(w_[i] + b_[i] * dv, maps_[i], ball, true, t_[i]) <= vmax) {
        sure[i] = 1;
        grew = true;
      }
    }
  }
}

double ArcBound::runs_length(const std::vector<char>& sure, const Ball& ball,
                             bool refine_edges) const {
  const double span = solver_.options().span_s;
  const long k = static_cast<long>(t_.size());
  double bound = 0.0;
  for (long i = 0; i < k;) {
    if (!sure[i]) {
      ++i;
      continue;
    }
    long j = i;
    while (j + 1 < k && sure[j + 1]) ++j;
    const double start = i == 0 ? 0.0 : certain_edge(t_[i], t_[i - 1], ball, refine_edges);
    double end = t_[j];
    if (j + 1 < k) {
      end = certain_edge(t_[j], t_[j + 1], ball, refine_edges);
    } else if (certain(span, ball, refine_edges)) {
      end = span;
    } else {
      end = certain_edge(t_[j], span, ball, refine_edges);
    }
    bound += end - start;
    i = j + 1;
  }
  return bound;
}

double ArcBound::lower_bound_s(const Vec3& e_rsw, double dv_mps, double chord,
                               bool refine_edges) const {
  const Ball ball{e_rsw, dv_mps, chord};
  std::vector<char> sure = certain_points(ball);
  if (refine_edges && solver_.options().impulses > 2) {
    // Grid points next to a certain one may be certain with the SQP's plan: grow the runs
    // outward (and fill gaps) until a point is not; each point is tested once.
    grow_runs(sure, ball);
  }
  return runs_length(sure, ball, refine_edges);
}

}  // namespace evade::threat
