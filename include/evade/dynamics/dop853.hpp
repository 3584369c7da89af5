// Adaptive explicit Runge–Kutta integrator DOP853 (Dormand & Prince 8(5,3)) with its native
// 7th-order dense output.
//
// Reference: Hairer, Nørsett & Wanner, "Solving Ordinary Differential Equations I", 2nd ed.
// (1993), sec. II.10 (the method and its 5th/3rd-order embedded error estimators), sec. II.4
// (automatic step-size control and the starting step size), sec. II.6 (dense output); and
// Hairer's Fortran dop853.f, whose control we reproduce exactly:
//   sk_i  = abs_tol + rel_tol * max(|x_i|, |x_new_i|)
//   err5  = sum_i ((sum_j er_j k_j,i) / sk_i)^2,  err3 = sum_i ((sum_j (b_j - bhh_j) k_j,i)/sk_i)^2
//   err   = |h| err5 / sqrt(N (err5 + 0.01 err3))            (the "stretched" 5(3) estimate)
//   fac   = clamp(err^(1/8) / 0.9, 1/6, 1/0.333);  h_new = h / fac   (beta = 0: no PI term)
//   after a rejection: h_new = h / min(1/0.333, err^(1/8)/0.9), and the next accepted step
//   may not grow h; a step is too small when 0.1 |h| <= |t| * 2.3e-16.
// Stiffness detection of dop853.f is not implemented.
//
// Its options and statistics (AdaptiveOptions, IntegrationStats, default tolerances):
// adaptive_options.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "evade/dynamics/adaptive_options.hpp"
#include "evade/dynamics/dop853_coefficients.hpp"

namespace evade {

/// Vector = any Eigen column vector (fixed or dynamic size). After reset(), each step()
/// advances by one accepted step; dense() interpolates inside that step. Work vectors are
/// sized in reset(), so stepping does not allocate beyond what the Rhs itself does.
/// Fn = the right-hand side's type: std::function by default; a function object type (called
/// as Vector(double, const Vector&)) lets the compiler inline it and makes copies of the
/// integrator cheap (no heap), with the same arithmetic and therefore the same steps.
template <class Vector, class Fn = std::function<Vector(double, const Vector&)>>
class Dop853 {
 public:
  using Rhs = Fn;

  explicit Dop853(Rhs f, const AdaptiveOptions& opt = {}) : f_(std::move(f)), opt_(opt) {
    opt_.validate();
    if (is_empty(f_)) throw std::invalid_argument("Dop853: empty right-hand side");
  }

  /// Starts a new integration at (t0_s, x0). Throws std::invalid_argument if not finite.
  void reset(double t0_s, const Vector& x0) {
    if (!std::isfinite(t0_s) || !x0.allFinite()) {
      throw std::invalid_argument("Dop853::reset: non-finite initial time or state");
    }
    t_ = t0_s;
    t_prev_ = t0_s;
    x_ = x0;
    x_prev_ = x0;
    for (Vector& k : k_) k = Vector::Zero(x0.size());
    for (Vector& c : cont_) c = Vector::Zero(x0.size());
    y_ = x0;
    x_new_ = x0;
    k1_step_ = x0;
    k13_ = x0;
    k14_ = x0;
    k15_ = x0;
    k16_ = x0;
    stats_ = IntegrationStats{};
    f_now_ = eval(t_, x_);
    h_ = opt_.h_initial_s;
    direction_ = 0.0;
    facold_ = 1e-4;
    reject_ = false;
    have_step_ = false;
    dense_ready_ = false;
    failure_.clear();
    initialized_ = true;
  }

  /// Takes one accepted step toward t_end_s without passing it. Returns false (and sets
  /// failure_reason()) when max_steps is reached, the step underflows, the state is not
  /// finite, or t_end_s equals the current time.
  bool step(double t_end_s) {
    using namespace dop853_detail;
    if (!initialized_) throw std::logic_error("Dop853::step before reset()");
    if (!std::isfinite(t_end_s)) return fail("t_end_s is not finite");
    if (t_end_s == t_) return fail("already at t_end_s");
    const double dir = (t_end_s > t_) ? 1.0 : -1.0;
    if (dir != direction_) {  // first step, or reversed direction: fresh step-size start
      direction_ = dir;
      reject_ = false;
      facold_ = 1e-4;
      h_ = (opt_.h_initial_s > 0.0) ? opt_.h_initial_s : initial_step(t_end_s);
    }
    const double h_max = (opt_.h_max_s > 0.0) ? opt_.h_max_s : std::abs(t_end_s - t_);
    double h = dir * std::min(std::abs(h_), h_max);
    for (;;) {
      if (stats_.steps_accepted + stats_.steps_rejected >= opt_.max_steps) {
        return fail("max_steps = " + std::to_string(opt_.max_steps) + " reached at t = " +
                    std::to_string(t_) + " s");
      }
      if (0.1 * std::abs(h) <= std::abs(t_) * kUround || h == 0.0) {
        return fail("step size underflow (h = " + std::to_string(h) + " s at t = " +
                    std::to_string(t_) + " s)");
      }
      bool last = false;
      if ((t_ + 1.01 * h - t_end_s) * dir > 0.0) {
        h = t_end_s - t_;
        last = true;
      }
      eval_stages(h);
      const double err = error_norm(h);
      const double fac11 = std::pow(err, kExpo1);
      const double fac = std::max(kFacc2, std::min(kFacc1, fac11 / kSafe));
      double h_new = h / fac;
      if (err <= 1.0) return accept_step(h, h_new, err, dir, h_max, last, t_end_s);
      // Rejected (DP86CO): shrink by at most a factor 1/kFacc1.
      h_new = h / std::min(kFacc1, fac11 / kSafe);
      reject_ = true;
      ++stats_.steps_rejected;
      h = h_new;
    }
  }

  double t_s() const { return t_; }
  const Vector& x() const { return x_; }
  double t_prev_s() const { return t_prev_; }
  const Vector& x_prev() const { return x_prev_; }
  const IntegrationStats& stats() const { return stats_; }
  const std::string& failure_reason() const { return failure_; }

  /// 7th-order continuous extension on [t_prev_s, t_s] of the last accepted step (CONTD8).
  /// The first call after a step costs three extra Rhs evaluations. Throws
  /// std::logic_error if no step was taken; t_s outside the step is extrapolation.
  Vector dense(double t_s) const {
    if (!have_step_) throw std::logic_error("Dop853::dense before the first step");
    if (!dense_ready_) build_dense();
    const double s = (t_s - t_prev_) / h_step_;
    const double s1 = 1.0 - s;
    // CONTD8: conpar = c4 + s(c5 + s1(c6 + s c7)); x = c0 + s(c1 + s1(c2 + s(c3 + s1 conpar)))
    return cont_[0] +
           s * (cont_[1] +
                s1 * (cont_[2] +
                      s * (cont_[3] +
                           s1 * (cont_[4] + s * (cont_[5] + s1 * (cont_[6] + s * cont_[7]))))));
  }

 private:
  // Stages 2..12 of a step of size h from (t_, x_) and the 8th-order solution x_new_ (DP86CO).
  void eval_stages(double h) {
    using namespace dop853_detail;
    const Vector& k1 = f_now_;
    // k_[j] holds stage j+2 here: k_[0] = stage 2, ..., k_[10] = stage 12.
    Vector& k2 = k_[0];
    Vector& k3 = k_[1];
    Vector& k4 = k_[2];
    Vector& k5 = k_[3];
    Vector& k6 = k_[4];
    Vector& k7 = k_[5];
    Vector& k8 = k_[6];
    Vector& k9 = k_[7];
    Vector& k10 = k_[8];
    Vector& k11 = k_[9];
    Vector& k12 = k_[10];
    y_ = x_ + h * (a21 * k1);
    k2 = eval(t_ + c2 * h, y_);
    y_ = x_ + h * (a31 * k1 + a32 * k2);
    k3 = eval(t_ + c3 * h, y_);
    y_ = x_ + h * (a41 * k1 + a43 * k3);
    k4 = eval(t_ + c4 * h, y_);
    y_ = x_ + h * (a51 * k1 + a53 * k3 + a54 * k4);
    k5 = eval(t_ + c5 * h, y_);
    y_ = x_ + h * (a61 * k1 + a64 * k4 + a65 * k5);
    k6 = eval(t_ + c6 * h, y_);
    y_ = x_ + h * (a71 * k1 + a74 * k4 + a75 * k5 + a76 * k6);
    k7 = eval(t_ + c7 * h, y_);
    y_ = x_ + h * (a81 * k1 + a84 * k4 + a85 * k5 + a86 * k6 + a87 * k7);
    k8 = eval(t_ + c8 * h, y_);
    y_ = x_ + h * (a91 * k1 + a94 * k4 + a95 * k5 + a96 * k6 + a97 * k7 + a98 * k8);
    k9 = eval(t_ + c9 * h, y_);
    y_ = x_ + h * (a101 * k1 + a104 * k4 + a105 * k5 + a106 * k6 + a107 * k7 + a108 * k8 +
                   a109 * k9);
    k10 = eval(t_ + c10 * h, y_);
    y_ = x_ + h * (a111 * k1 + a114 * k4 + a115 * k5 + a116 * k6 + a117 * k7 + a118 * k8 +
                   a119 * k9 + a1110 * k10);
    k11 = eval(t_ + c11 * h, y_);
    y_ = x_ + h * (a121 * k1 + a124 * k4 + a125 * k5 + a126 * k6 + a127 * k7 + a128 * k8 +
                   a129 * k9 + a1210 * k10 + a1211 * k11);
    k12 = eval(t_ + h, y_);
    // 8th-order solution; k4 reused as the weighted slope (as in DP86CO).
    k4 = b1 * k1 + b6 * k6 + b7 * k7 + b8 * k8 + b9 * k9 + b10 * k10 + b11 * k11 + b12 * k12;
    x_new_ = x_ + h * k4;
  }

  // Scaled error norm of the step just evaluated by eval_stages (DP86CO); +inf when the
  // step produced a non-finite value (rejected with the largest reduction).
  double error_norm(double h) const {
    using namespace dop853_detail;
    const Vector& k1 = f_now_;
    const Vector& k4 = k_[2];
    const Vector& k6 = k_[4];
    const Vector& k7 = k_[5];
    const Vector& k8 = k_[6];
    const Vector& k9 = k_[7];
    const Vector& k10 = k_[8];
    const Vector& k11 = k_[9];
    const Vector& k12 = k_[10];
    // Error estimate (DP86CO): 5th- and 3rd-order estimators, scaled per component.
    double err5 = 0.0;
    double err3 = 0.0;
    const auto n = x_.size();
    for (decltype(x_.size()) i = 0; i < n; ++i) {
      const double sk =
          opt_.abs_tol + opt_.rel_tol * std::max(std::abs(x_[i]), std::abs(x_new_[i]));
      const double e3 = (k4[i] - bhh1 * k1[i] - bhh2 * k9[i] - bhh3 * k12[i]) / sk;
      const double e5 = (er1 * k1[i] + er6 * k6[i] + er7 * k7[i] + er8 * k8[i] + er9 * k9[i] +
                         er10 * k10[i] + er11 * k11[i] + er12 * k12[i]) /
                        sk;
      err3 += e3 * e3;
      err5 += e5 * e5;
    }
    double deno = err5 + 0.01 * err3;
    if (deno <= 0.0) deno = 1.0;
    double err = std::abs(h) * err5 * std::sqrt(1.0 / (static_cast<double>(n) * deno));
    if (!std::isfinite(err) || !x_new_.allFinite()) {
      err = std::numeric_limits<double>::infinity();  // reject with the largest reduction
    }
    return err;
  }

  // Accepts the step of size h evaluated by eval_stages (error err) and proposes h_new for
  // the next one (DP86CO).
  bool accept_step(double h, double h_new, double err, double dir, double h_max, bool last,
                   double t_end_s) {
    const Vector& k1 = f_now_;
    // Accepted: FSAL stage 13 at the new point.
    facold_ = std::max(err, 1e-4);
    ++stats_.steps_accepted;
    k13_ = eval(t_ + h, x_new_);
    k1_step_ = k1;  // keep stage 1 of this step for the dense output
    std::swap(x_prev_, x_);
    std::swap(x_, x_new_);
    t_prev_ = t_;
    t_ = last ? t_end_s : t_ + h;
    h_step_ = t_ - t_prev_;
    f_now_ = k13_;
    if (std::abs(h_new) > h_max && opt_.h_max_s > 0.0) h_new = dir * opt_.h_max_s;
    if (reject_) h_new = dir * std::min(std::abs(h_new), std::abs(h));
    reject_ = false;
    h_ = h_new;
    have_step_ = true;
    dense_ready_ = false;
    if (!x_.allFinite()) return fail("non-finite state");
    return true;
  }

  static constexpr double kUround = 2.3e-16;
  static constexpr double kSafe = 0.9;
  static constexpr double kFacc1 = 1.0 / 0.333;  // largest step decrease 1/fac1
  static constexpr double kFacc2 = 1.0 / 6.0;    // largest step increase 1/fac2
  static constexpr double kExpo1 = 1.0 / 8.0;    // 1/8 - 0.2 beta, beta = 0

  template <class G>
  static bool is_empty(const std::function<G>& f) {
    return !f;
  }
  template <class G>
  static bool is_empty(const G&) {
    return false;
  }

  Vector eval(double t, const Vector& x) const {
    ++stats_.rhs_evaluations;
    return f_(t, x);
  }

  bool fail(std::string why) {
    failure_ = std::move(why);
    return false;
  }

  /// Hairer's HINIT (HNW sec. II.4, "Starting step size"), iord = 8.
  double initial_step(double t_end_s) {
    const Vector& f0 = f_now_;
    double dnf = 0.0;
    double dny = 0.0;
    const auto n = x_.size();
    for (decltype(x_.size()) i = 0; i < n; ++i) {
      const double sk = opt_.abs_tol + opt_.rel_tol * std::abs(x_[i]);
      dnf += (f0[i] / sk) * (f0[i] / sk);
      dny += (x_[i] / sk) * (x_[i] / sk);
    }
    double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : std::sqrt(dny / dnf) * 0.01;
    const double h_max = (opt_.h_max_s > 0.0) ? opt_.h_max_s : std::abs(t_end_s - t_);
    h = std::min(h, h_max) * direction_;
    y_ = x_ + h * f0;
    const Vector f1 = eval(t_ + h, y_);
    double der2 = 0.0;
    for (decltype(x_.size()) i = 0; i < n; ++i) {
      const double sk = opt_.abs_tol + opt_.rel_tol * std::abs(x_[i]);
      der2 += ((f1[i] - f0[i]) / sk) * ((f1[i] - f0[i]) / sk);
    }
    der2 = std::sqrt(der2) / std::abs(h);
    const double der12 = std::max(std::abs(der2), std::sqrt(dnf));
    const double h1 =
        (der12 <= 1e-15) ? std::max(1e-6, std::abs(h) * 1e-3) : std::pow(0.01 / der12, 1.0 / 8.0);
    return direction_ * std::min({100.0 * std::abs(h), h1, h_max});
  }

  /// Dense-output coefficients of the last step (dop853.f, block after acceptance).
  void build_dense() const {
    using namespace dop853_detail;
    const double h = h_step_;
    const Vector& k1 = k1_step_;
    const Vector& k6 = k_[4];
    const Vector& k7 = k_[5];
    const Vector& k8 = k_[6];
    const Vector& k9 = k_[7];
    const Vector& k10 = k_[8];
    const Vector& k11 = k_[9];
    const Vector& k12 = k_[10];
    const Vector& k13 = k13_;
    const Vector& xo = x_prev_;
    const double t = t_prev_;
    y_ = xo + h * (a141 * k1 + a147 * k7 + a148 * k8 + a149 * k9 + a1410 * k10 + a1411 * k11 +
                   a1412 * k12 + a1413 * k13);
    k14_ = eval(t + c14 * h, y_);
    y_ = xo + h * (a151 * k1 + a156 * k6 + a157 * k7 + a158 * k8 + a1511 * k11 + a1512 * k12 +
                   a1513 * k13 + a1514 * k14_);
    k15_ = eval(t + c15 * h, y_);
    y_ = xo + h * (a161 * k1 + a166 * k6 + a167 * k7 + a168 * k8 + a169 * k9 + a1613 * k13 +
                   a1614 * k14_ + a1615 * k15_);
    k16_ = eval(t + c16 * h, y_);
    cont_[0] = xo;
    cont_[1] = x_ - xo;                       // ydiff
    cont_[2] = h * k1 - cont_[1];             // bspl
    cont_[3] = cont_[1] - h * k13 - cont_[2];
    cont_[4] = h * (d41 * k1 + d46 * k6 + d47 * k7 + d48 * k8 + d49 * k9 + d410 * k10 +
                    d411 * k11 + d412 * k12 + d413 * k13 + d414 * k14_ + d415 * k15_ +
                    d416 * k16_);
    cont_[5] = h * (d51 * k1 + d56 * k6 + d57 * k7 + d58 * k8 + d59 * k9 + d510 * k10 +
                    d511 * k11 + d512 * k12 + d513 * k13 + d514 * k14_ + d515 * k15_ +
                    d516 * k16_);
    cont_[6] = h * (d61 * k1 + d66 * k6 + d67 * k7 + d68 * k8 + d69 * k9 + d610 * k10 +
                    d611 * k11 + d612 * k12 + d613 * k13 + d614 * k14_ + d615 * k15_ +
                    d616 * k16_);
    cont_[7] = h * (d71 * k1 + d76 * k6 + d77 * k7 + d78 * k8 + d79 * k9 + d710 * k10 +
                    d711 * k11 + d712 * k12 + d713 * k13 + d714 * k14_ + d715 * k15_ +
                    d716 * k16_);
    dense_ready_ = true;
  }

  Rhs f_;
  AdaptiveOptions opt_;
  bool initialized_ = false;
  double t_ = 0.0;
  double t_prev_ = 0.0;
  double h_ = 0.0;       // proposed next step (signed)
  double h_step_ = 0.0;  // size of the last accepted step (signed)
  double direction_ = 0.0;
  double facold_ = 1e-4;
  bool reject_ = false;
  bool have_step_ = false;
  Vector x_;
  Vector x_prev_;
  Vector x_new_;
  Vector f_now_;    // f(t_, x_): stage 1 of the next step
  Vector k1_step_;  // stage 1 of the last accepted step
  Vector k13_;
  std::array<Vector, 11> k_;  // stages 2..12
  mutable Vector y_;
  mutable Vector k14_, k15_, k16_;
  mutable std::array<Vector, 8> cont_;
  mutable bool dense_ready_ = false;
  mutable IntegrationStats stats_;
  std::string failure_;
};

/// Integrates x' = f(t, x) from t0_s to t1_s (t1 < t0 allowed) and returns x(t1).
/// Throws std::runtime_error with the integrator's reason on failure.
template <class Vector, class Rhs>
Vector propagate_adaptive(const Rhs& f, double t0_s, const Vector& x0, double t1_s,
                          const AdaptiveOptions& opt = {}, IntegrationStats* stats = nullptr) {
  Dop853<Vector> integ(typename Dop853<Vector>::Rhs(f), opt);
  integ.reset(t0_s, x0);
  while (integ.t_s() != t1_s) {
    if (!integ.step(t1_s)) {
      throw std::runtime_error("propagate_adaptive failed: " + integ.failure_reason());
    }
  }
  if (stats != nullptr) *stats = integ.stats();
  return integ.x();
}

}  // namespace evade
