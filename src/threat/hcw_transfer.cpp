// HCW 2-impulse rendezvous in closed form and the primer-vector lower bound on the cost of
// any impulsive rendezvous. Paper 001 (Yu, Wang, Sun 2017) sec. 2.1, eq. 1–3 (C-W transition
// through impulses); the derivation of the bound is in evade/threat/hcw_transfer.hpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/dynamics/hcw.hpp"
#include "evade/threat/hcw_transfer.hpp"

namespace evade::threat {
namespace {

Vec3 unit_or_zero(const Vec3& v) {
  const double n = v.norm();
  return n > 0.0 ? Vec3(v / n) : Vec3::Zero();
}

constexpr int kSamples = HcwTransfer::kPrimerSamples;
using Samples = std::array<Mat3, kSamples + 1>;

// The IRLS's candidate impulse times (sample indices j, τ_j = jT/M), their weights, and the
// last IRLS plan's impulses v_k.
struct IrlsCandidates {
  static constexpr int kMax = 14;
  std::array<int, kMax> cand{};
  std::array<double, kMax> w{};
  std::array<Vec3, kMax> v;  // zero until an IRLS step sets it (Eigen does not initialize)
  int nc = 0;
  double w_floor = 0.0;

  IrlsCandidates() { v.fill(Vec3::Zero()); }

  // Adds sample j with weight max(wj, w_floor) unless it is out of range, present or full.
  void add(int j, double wj) {
    if (j < 0 || j > kSamples || nc >= kMax) return;
    for (int k = 0; k < nc; ++k) {
      if (cand[k] == j) return;
    }
    cand[nc] = j;
    w[nc] = std::max(wj, w_floor);
    ++nc;
  }
};

// Weights start from the 2-impulse plan plus a small share at the primer's largest |p| and
// its neighbours.
IrlsCandidates initial_candidates(const Vec6& d, const PrimerBound& primer, const Mat3& rv_T_inv,
                                  const Mat3& vv_T, double T) {
  const double J2 = primer.two_impulse_cost_mps;
  IrlsCandidates c;
  c.w_floor = 1e-9 * J2;
  const Vec3 dv1 = rv_T_inv * d.head<3>();
  const Vec3 dv2 = d.tail<3>() - vv_T * dv1;
  c.add(0, dv1.norm());
  c.add(kSamples, dv2.norm());
  const int jstar = static_cast<int>(std::lround(primer.primer_argmax_s / T * kSamples));
  for (int dj = -1; dj <= 1; ++dj) c.add(jstar + dj, 0.05 * J2);
  return c;
}

// S = Σ_k w_k B_k B_kᵀ, B_k = [Φrv(s_k); Φvv(s_k)].
Mat6 weighted_gram(const IrlsCandidates& c, const Samples& rv_s, const Samples& vv_s) {
  Mat6 S = Mat6::Zero();
  for (int k = 0; k < c.nc; ++k) {
    const Mat3& rv = rv_s[c.cand[k]];
    const Mat3& vv = vv_s[c.cand[k]];
    S.block<3, 3>(0, 0).noalias() += c.w[k] * rv * rv.transpose();
    S.block<3, 3>(0, 3).noalias() += c.w[k] * rv * vv.transpose();
    S.block<3, 3>(3, 3).noalias() += c.w[k] * vv * vv.transpose();
  }
  S.block<3, 3>(3, 0) = S.block<3, 3>(0, 3).transpose();
  return S;
}

// Keeps λ = μ / pmax if its bound μᵀd / pmax beats the best so far.
void keep_better_certificate(double num, double pmax, double argmax_s, PrimerBound& best) {
  if (pmax > 0.0 && num > 0.0) {
    const double lb = num / pmax;
    if (lb > best.lower_bound_mps) {
      best.lower_bound_mps = lb;
      best.primer_max = best.two_impulse_cost_mps / lb;  // equivalent scaling of J2
      best.primer_argmax_s = argmax_s;
    }
  }
}

// True when the IRLS has nothing to do: no cost to bound, bad input, no iterations, or (with
// a stop) the primer bound already above the stop or the 2-impulse plan within it.
bool settled(const Vec6& d, const PrimerBound& primer, double stop_above_mps, int max_iterations) {
  const double J2 = primer.two_impulse_cost_mps;
  if (J2 == 0.0 || !d.allFinite() || max_iterations <= 0) return true;
  return stop_above_mps >= 0.0 && (primer.lower_bound_mps > stop_above_mps || J2 <= stop_above_mps);
}

// Close call: when the sampled bound is at or below the stop, the finer certification may
// show max|p| < λᵀd/stop, i.e. a bound just above the stop.
void certify_close_call(const HcwTransfer& tr, const Vec6& mu, double num, double stop_above_mps,
                        PrimerBound& best) {
  if (best.lower_bound_mps <= stop_above_mps && num > 0.0 &&
      tr.certify_primer_below(mu, num / stop_above_mps)) {
    best.lower_bound_mps = std::nextafter(stop_above_mps, 2.0 * stop_above_mps + 1.0);
    best.primer_max = best.two_impulse_cost_mps / best.lower_bound_mps;
  }
}

// IRLS step: v_k = w_k B_kᵀμ is feasible; its cost (returned) bounds the optimum from above.
double irls_step(const Vec6& mu, const Samples& rv_s, const Samples& vv_s, IrlsCandidates& c) {
  double primal = 0.0;
  for (int k = 0; k < c.nc; ++k) {
    const Vec3 pk =
        rv_s[c.cand[k]].transpose() * mu.head<3>() + vv_s[c.cand[k]].transpose() * mu.tail<3>();
    c.v[k] = c.w[k] * pk;
    c.w[k] = std::max(c.w[k] * pk.norm(), c.w_floor);
    primal += c.w[k];
  }
  return primal;
}

// Merges the interior impulses within ±2 samples of the largest one into one impulse at their
// |v|-weighted mean time (first-order cost-neutral for nearby times), drops the others, and
// closes the rendezvous exactly with the end impulses. Leaves `plan` empty without interior
// impulses.
void merged_three_impulse(const IrlsCandidates& c, const Vec6& d, double n, double T,
                          const Mat3& rv_T_inv, const Mat3& vv_T, RendezvousPlan& plan) {
  auto interior = [&](int k) { return c.cand[k] != 0 && c.cand[k] != kSamples; };
  int top = -1;
  for (int k = 0; k < c.nc; ++k) {
    if (!interior(k)) continue;
    if (top < 0 || c.v[k].norm() > c.v[top].norm()) top = k;
  }
  if (top < 0) return;
  Vec3 dvm = Vec3::Zero();
  double wsum = 0.0, tsum = 0.0;
  for (int k = 0; k < c.nc; ++k) {
    if (!interior(k) || std::abs(c.cand[k] - c.cand[top]) > 2) continue;
    dvm += c.v[k];
    wsum += c.v[k].norm();
    tsum += c.v[k].norm() * (T * c.cand[k] / kSamples);
  }
  const double tm = wsum > 0.0 ? std::clamp(tsum / wsum, 0.0, T) : T * c.cand[top] / kSamples;
  const HcwBlocks b = hcw_stm_blocks(n, T - tm);
  const Vec3 e1 = rv_T_inv * (d.head<3>() - b.rv * dvm);
  const Vec3 en = d.tail<3>() - b.vv * dvm - vv_T * e1;
  plan.impulses = {{0.0, e1}, {tm, dvm}, {T, en}};
  plan.cost_mps = e1.norm() + dvm.norm() + en.norm();
}

}  // namespace

HcwTransfer::HcwTransfer(double n_radps, double transfer_s) : n_(n_radps), T_(transfer_s) {
  if (!std::isfinite(n_radps) || n_radps <= 0.0) {
    throw std::invalid_argument("HcwTransfer: mean motion n_radps = " + std::to_string(n_radps) +
                                " must be finite and > 0");
  }
  if (!std::isfinite(transfer_s) || transfer_s <= 0.0) {
    throw std::invalid_argument("HcwTransfer: transfer time dt_transfer_s = " +
                                std::to_string(transfer_s) + " must be finite and > 0");
  }
  const HcwBlocks b = hcw_stm_blocks(n_, T_);
  rr_T_ = b.rr;
  rv_T_ = b.rv;
  vr_T_ = b.vr;
  vv_T_ = b.vv;
  // Φrv(T) is singular when sin(nT) = 0 (out-of-plane block s/n) or when the in-plane block's
  // determinant [s(4s − 3nT) + 4(1 − c)²]/n² vanishes (nT = 2πk among its roots). The
  // 2-impulse closed form and the SQP's elimination of the end impulses need Φrv(T)⁻¹:
  // reject a condition number (Frobenius estimate) above 1e9.
  const double det = rv_T_.determinant();
  const Mat3 inv = (det != 0.0) ? Mat3(rv_T_.inverse()) : Mat3::Zero();
  const double cond = rv_T_.norm() * inv.norm();
  if (det == 0.0 || !std::isfinite(cond) || cond > 1e9) {
    throw std::invalid_argument(
        "HcwTransfer: transfer time dt_transfer_s = " + std::to_string(transfer_s) +
        " makes the HCW 2-impulse problem singular (n*T = " + std::to_string(n_ * T_) +
        " rad is at a root of det(Phi_rv)); choose another transfer time");
  }
  rv_T_inv_ = rv_T_.inverse();
  for (int j = 0; j <= kPrimerSamples; ++j) {
    const double tau = T_ * j / kPrimerSamples;
    const HcwBlocks bj = hcw_stm_blocks(n_, T_ - tau);
    rv_s_[j] = bj.rv;
    vv_s_[j] = bj.vv;
  }
}

Vec6 HcwTransfer::required_change(const Vec6& x0, const Vec6& xf) const {
  Vec6 d;
  d.head<3>() = xf.head<3>() - rr_T_ * x0.head<3>() - rv_T_ * x0.tail<3>();
  d.tail<3>() = xf.tail<3>() - vr_T_ * x0.head<3>() - vv_T_ * x0.tail<3>();
  return d;
}

RendezvousPlan HcwTransfer::two_impulse(const Vec6& d) const {
  const Vec3 dv1 = rv_T_inv_ * d.head<3>();
  const Vec3 dv2 = d.tail<3>() - vv_T_ * dv1;
  RendezvousPlan p;
  p.impulses = {{0.0, dv1}, {T_, dv2}};
  p.cost_mps = dv1.norm() + dv2.norm();
  return p;
}

double HcwTransfer::two_impulse_cost(const Vec6& d) const {
  const Vec3 dv1 = rv_T_inv_ * d.head<3>();
  const Vec3 dv2 = d.tail<3>() - vv_T_ * dv1;
  return dv1.norm() + dv2.norm();
}

Vec6 HcwTransfer::primer_lambda(const Vec6& d) const {
  const Vec3 dv1 = rv_T_inv_ * d.head<3>();
  const Vec3 dv2 = d.tail<3>() - vv_T_ * dv1;
  const Vec3 u1 = unit_or_zero(dv1);
  const Vec3 u2 = unit_or_zero(dv2);
  Vec6 lambda;
  lambda.head<3>() = rv_T_inv_.transpose() * (u1 - vv_T_.transpose() * u2);
  lambda.tail<3>() = u2;
  return lambda;
}

Vec3 HcwTransfer::primer(const Vec6& lambda, double tau_s) const {
  const HcwBlocks b = hcw_stm_blocks(n_, T_ - tau_s);
  return b.rv.transpose() * lambda.head<3>() + b.vv.transpose() * lambda.tail<3>();
}

PrimerBound HcwTransfer::primer_bound(const Vec6& d) const {
  PrimerBound out;
  const Vec3 dv1 = rv_T_inv_ * d.head<3>();
  const Vec3 dv2 = d.tail<3>() - vv_T_ * dv1;
  out.two_impulse_cost_mps = dv1.norm() + dv2.norm();
  if (out.two_impulse_cost_mps == 0.0) {
    out.primer_max = 1.0;
    out.lower_bound_mps = 0.0;
    return out;
  }
  const Vec3 u1 = unit_or_zero(dv1);
  const Vec3 u2 = unit_or_zero(dv2);
  Vec6 lambda;
  lambda.head<3>() = rv_T_inv_.transpose() * (u1 - vv_T_.transpose() * u2);
  lambda.tail<3>() = u2;
  int best_j = 0;
  // λᵀd = u1ᵀΔv1 + u2ᵀΔv2 = J2; |p(0)| or |p(T)| is 1 unless both impulses vanish.
  out.primer_max = std::max(1.0, certified_primer_max(lambda, &best_j));
  out.lower_bound_mps = out.two_impulse_cost_mps / out.primer_max;
  out.primer_argmax_s = T_ * best_j / kPrimerSamples;
  return out;
}

double HcwTransfer::certified_primer_max(const Vec6& lambda, int* argmax_j) const {
  const Vec3 lr = lambda.head<3>();
  const Vec3 lv = lambda.tail<3>();
  double best2 = 0.0;  // q >= 0: the first maximum wins, as with any negative start
  int best_j = 0;
  for (int j = 0; j <= kPrimerSamples; ++j) {
    const double q = (rv_s_[j].transpose() * lr + vv_s_[j].transpose() * lv).squaredNorm();
    if (q > best2) {
      best2 = q;
      best_j = j;
    }
  }
  const double h = T_ / kPrimerSamples;
  const double sqrt26 = std::sqrt(26.0);
  const double p2_max = n_ * sqrt26 * lr.norm() + n_ * n_ * sqrt26 * lv.norm();
  if (argmax_j != nullptr) *argmax_j = best_j;
  return std::sqrt(best2) + h * h / 8.0 * p2_max;
}

bool HcwTransfer::certify_primer_below(const Vec6& lambda, double cap) const {
  const Vec3 lr = lambda.head<3>();
  const Vec3 lv = lambda.tail<3>();
  const double h = T_ / kPrimerSamples;
  const double sqrt26 = std::sqrt(26.0);
  const double p2_max = n_ * sqrt26 * lr.norm() + n_ * n_ * sqrt26 * lv.norm();
  const double margin = h * h / 8.0 * p2_max;
  constexpr int kSub = 8;  // sub-steps of a refined interval: margin / 64
  const double sub_margin = margin / (kSub * kSub);
  std::array<double, static_cast<std::size_t>(kPrimerSamples) + 1> q{};
  for (int j = 0; j <= kPrimerSamples; ++j) {
    q[j] = (rv_s_[j].transpose() * lr + vv_s_[j].transpose() * lv).norm();
    if (q[j] >= cap) return false;
  }
  for (int j = 0; j < kPrimerSamples; ++j) {
    if (std::max(q[j], q[j + 1]) + margin < cap) continue;
    double prev = q[j];
    for (int k = 1; k <= kSub; ++k) {
      const double qk = (k == kSub) ? q[j + 1] : primer(lambda, h * (j + double(k) / kSub)).norm();
      if (std::max(prev, qk) + sub_margin >= cap) return false;
      prev = qk;
    }
  }
  return true;
}

PrimerBound HcwTransfer::dual_bound(const Vec6& d, double stop_above_mps,
                                    int max_iterations) const {
  return dual_bound(d, primer_bound(d), stop_above_mps, max_iterations);
}

PrimerBound HcwTransfer::dual_bound(const Vec6& d, const PrimerBound& primer,
                                    double stop_above_mps, int max_iterations,
                                    RendezvousPlan* three_impulse) const {
  if (three_impulse != nullptr) *three_impulse = RendezvousPlan{};
  PrimerBound best = primer;
  const bool stopping = stop_above_mps >= 0.0;
  if (settled(d, best, stop_above_mps, max_iterations)) return best;

  IrlsCandidates c = initial_candidates(d, best, rv_T_inv_, vv_T_, T_);
  bool have_plan = false;
  for (int it = 0; it < max_iterations; ++it) {
    const Vec6 mu = weighted_gram(c, rv_s_, vv_s_).ldlt().solve(d);
    if (!mu.allFinite()) break;
    // Score μ as a certificate: λ = μ / certified max|p|.
    int ja = 0;
    const double pmax = certified_primer_max(mu, &ja);
    const double num = mu.dot(d);
    keep_better_certificate(num, pmax, T_ * ja / kPrimerSamples, best);
    if (stopping) certify_close_call(*this, mu, num, stop_above_mps, best);
    if (stopping && best.lower_bound_mps > stop_above_mps) break;
    const double primal = irls_step(mu, rv_s_, vv_s_, c);
    have_plan = true;
    if (stopping && primal <= stop_above_mps) break;  // a plan within the limit: no bound can pass
    for (int dj = -1; dj <= 1; ++dj) c.add(ja + dj, 0.05 * primal);
  }
  if (three_impulse != nullptr && have_plan) {
    merged_three_impulse(c, d, n_, T_, rv_T_inv_, vv_T_, *three_impulse);
  }
  return best;
}

Vec6 HcwTransfer::plan_residual(const RendezvousPlan& plan, const Vec6& d) const {
  Vec6 sum = Vec6::Zero();
  for (const Impulse& imp : plan.impulses) {
    sum += hcw_impulse_response(n_, T_ - imp.t_s, imp.dv_rsw_mps);
  }
  return sum - d;
}

}  // namespace evade::threat
