// DOP853 integrator mechanics: order, dynamic-size vectors, failure modes, options.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

#include "evade/dynamics/dop853.hpp"

namespace evade {
namespace {

using Vec2 = Eigen::Vector2d;

// Harmonic oscillator x'' = -x, exact solution (cos t, -sin t).
Vec2 oscillator(double, const Vec2& x) { return Vec2(x(1), -x(0)); }

// With a fixed step (h_initial = h_max = h, tolerance loose enough never to reject), the
// global error of an 8th-order method falls by 2^8 = 256 when h halves (accept 200..320).
TEST(Dop853, ConvergesAtEighthOrderWithFixedSteps) {
  double err[2];
  for (int k = 0; k < 2; ++k) {
    AdaptiveOptions opt;
    opt.rel_tol = 1.0;
    opt.abs_tol = 1.0;
    opt.h_initial_s = 0.5 / (k + 1);
    opt.h_max_s = opt.h_initial_s;
    IntegrationStats st;
    const Vec2 x = propagate_adaptive(oscillator, 0.0, Vec2(1.0, 0.0), 10.0, opt, &st);
    EXPECT_EQ(st.steps_rejected, 0);
    EXPECT_EQ(st.steps_accepted, 20 * (k + 1));
    err[k] = (x - Vec2(std::cos(10.0), -std::sin(10.0))).norm();
  }
  EXPECT_NEAR(err[0] / err[1], 256.0, 60.0);
}

// The dense output is 7th order: the error at mid-step falls by ~2^8 (local error O(h^8))
// when h halves; require at least 2^6.
TEST(Dop853, DenseOutputIsHighOrder) {
  double err[2];
  for (int k = 0; k < 2; ++k) {
    AdaptiveOptions opt;
    opt.rel_tol = 1.0;
    opt.abs_tol = 1.0;
    opt.h_initial_s = 0.8 / (k + 1);
    opt.h_max_s = opt.h_initial_s;
    Dop853<Vec2> integ(oscillator, opt);
    integ.reset(0.0, Vec2(1.0, 0.0));
    ASSERT_TRUE(integ.step(10.0));
    const double tm = 0.37 * integ.t_s();
    const Vec2 exact(std::cos(tm), -std::sin(tm));
    err[k] = (integ.dense(tm) - exact).norm();
  }
  EXPECT_GT(err[0] / err[1], 64.0);
}

// Any Eigen column vector works, including dynamic size. The components decay to 1e-5..1e-1,
// where abs_tol = 1e-9 of the tight preset dominates the error scale: require 1e-9.
TEST(Dop853, IntegratesDynamicSizeVectors) {
  auto f = [](double, const Eigen::VectorXd& x) {
    Eigen::VectorXd d(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) d(i) = -(i + 1.0) * x(i);
    return d;
  };
  const Eigen::VectorXd x0 = Eigen::VectorXd::Ones(5);
  const Eigen::VectorXd x = propagate_adaptive(f, 0.0, x0, 2.0, AdaptiveOptions::tight());
  for (Eigen::Index i = 0; i < 5; ++i) EXPECT_NEAR(x(i), std::exp(-(i + 1.0) * 2.0), 1e-9);
}

// x' = x^2, x(0) = 1 blows up at t = 1: the integrator must fail, not loop or return junk.
TEST(Dop853, FailsOnFiniteTimeBlowUp) {
  using Vec1 = Eigen::Matrix<double, 1, 1>;
  auto f = [](double, const Vec1& x) { return Vec1(x(0) * x(0)); };
  EXPECT_THROW(propagate_adaptive(f, 0.0, Vec1(1.0), 2.0), std::runtime_error);
}

TEST(Dop853, StopsAtMaxSteps) {
  AdaptiveOptions opt;
  opt.max_steps = 5;
  opt.h_max_s = 0.01;
  Dop853<Vec2> integ(oscillator, opt);
  integ.reset(0.0, Vec2(1.0, 0.0));
  int ok = 0;
  while (integ.step(1.0)) ++ok;
  EXPECT_EQ(ok, 5);
  EXPECT_NE(integ.failure_reason().find("max_steps"), std::string::npos);
}

TEST(Dop853, NeverStepsPastTheEnd) {
  Dop853<Vec2> integ(oscillator);
  integ.reset(0.0, Vec2(1.0, 0.0));
  int guard = 0;
  while (integ.t_s() != 3.3 && guard++ < 100000) {
    ASSERT_TRUE(integ.step(3.3));
    EXPECT_LE(integ.t_s(), 3.3);
    EXPECT_GT(integ.t_s(), integ.t_prev_s());
  }
  EXPECT_EQ(integ.t_s(), 3.3);
  EXPECT_FALSE(integ.step(3.3));  // already there
}

TEST(Dop853, RejectsInvalidOptionsAndState) {
  AdaptiveOptions bad;
  bad.rel_tol = -1.0;
  EXPECT_THROW(Dop853<Vec2>(oscillator, bad), std::invalid_argument);
  bad = AdaptiveOptions{};
  bad.rel_tol = 0.0;
  bad.abs_tol = 0.0;
  EXPECT_THROW(Dop853<Vec2>(oscillator, bad), std::invalid_argument);
  bad = AdaptiveOptions{};
  bad.max_steps = 0;
  EXPECT_THROW(Dop853<Vec2>(oscillator, bad), std::invalid_argument);
  Dop853<Vec2> integ(oscillator);
  EXPECT_THROW(integ.reset(0.0, Vec2(NAN, 0.0)), std::invalid_argument);
}

}  // namespace
}  // namespace evade
