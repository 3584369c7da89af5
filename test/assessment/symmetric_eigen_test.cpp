// The flight eigen-decompositions (src/assessment/symmetric_eigen.cpp): against Eigen's
// SelfAdjointEigenSolver (what they replace on the planning worker's path) on random symmetric
// matrices, definite and not, and on the ill-conditioned covariances of conjunctions (axis
// ratios to 1e6, velocity and position scales 1e8 apart). Bounds: a backward-stable symmetric
// eigensolver gives each eigenvalue within a few eps * ||A|| (Weyl), so both solvers agree to
// 1e-13 ||A||_F; the eigenvectors are orthonormal to 1e-14 and A V = V L to 1e-13 ||A||_F. The
// smaller eigenvalue of the 2x2 Schur rotation is a - t b, whose error is a few ulps of a(0,0)
// (Golub & Van Loan 2013, section 8.5.1): checked against long double on a 1 : 1e12 covariance.
#include <cmath>
#include <cstdio>
#include <random>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "evade/assessment/symmetric_eigen.hpp"

namespace {

using namespace evade;
using namespace evade::assessment;

template <int N>
void expect_decomposition(const Eigen::Matrix<double, N, N>& a, const Eigen::Matrix<double, N, 1>& l,
                          const Eigen::Matrix<double, N, N>& v) {
  const double norm = a.norm();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> ref(a);
  for (int i = 0; i < N; ++i) EXPECT_NEAR(l(i), ref.eigenvalues()(i), 1e-13 * norm) << i;
  for (int i = 1; i < N; ++i) EXPECT_LE(l(i - 1), l(i));
  EXPECT_LT((v.transpose() * v - Eigen::Matrix<double, N, N>::Identity()).norm(), 1e-14);
  EXPECT_LT((a * v - v * l.asDiagonal()).norm(), 1e-13 * norm);
}

template <int N>
Eigen::Matrix<double, N, N> random_symmetric(std::mt19937_64* rng, bool definite) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::Matrix<double, N, N> m;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) m(i, j) = g(*rng);
  return definite ? Eigen::Matrix<double, N, N>(m * m.transpose()) : Eigen::Matrix<double, N, N>(m + m.transpose());
}

TEST(SymmetricEigen, JacobiMatchesEigenOnRandomSymmetricMatrices) {
  std::mt19937_64 rng(43);
  for (int k = 0; k < 200; ++k) {
    const Mat6 a = random_symmetric<6>(&rng, k % 2 == 0);
    Vec6 l;
    Mat6 v;
    ASSERT_TRUE(symmetric_eigen_jacobi<6>(a, &l, &v));
    expect_decomposition<6>(a, l, v);
  }
}

// A conjunction's 6x6 covariance: position sigmas 10 m to 10 km, velocity sigmas 1e-4 to 1 m/s,
// correlated, rotated; and one made not positive definite (a CDM's rounding) as the repair sees it.
TEST(SymmetricEigen, JacobiMatchesEigenOnConjunctionCovariances) {
  std::mt19937_64 rng(8079);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    Vec6 s;
    for (int i = 0; i < 3; ++i) s(i) = std::pow(10.0, 1.0 + 3.0 * u(rng));
    for (int i = 3; i < 6; ++i) s(i) = std::pow(10.0, -4.0 + 4.0 * u(rng));
    const Mat6 q = Eigen::HouseholderQR<Mat6>(random_symmetric<6>(&rng, false)).householderQ();
    Vec6 d;
    for (int i = 0; i < 6; ++i) d(i) = 0.05 + 2.0 * u(rng);
    Mat6 c = s.asDiagonal() * q * d.asDiagonal() * q.transpose() * s.asDiagonal();
    if (k % 4 == 0) c(0, 1) = c(1, 0) = 1.01 * std::sqrt(c(0, 0) * c(1, 1));  // indefinite
    Vec6 l;
    Mat6 v;
    ASSERT_TRUE(symmetric_eigen_jacobi<6>(c, &l, &v));
    expect_decomposition<6>(c, l, v);
  }
}

TEST(SymmetricEigen, TwoByTwoMatchesEigenAndKeepsTheSmallEigenvalueRelativelyAccurate) {
  std::mt19937_64 rng(2);
  for (int k = 0; k < 500; ++k) {
    const Mat2 a = random_symmetric<2>(&rng, k % 2 == 0);
    Vec2 l;
    Mat2 v;
    symmetric_eigen_2x2(a, &l, &v);
    expect_decomposition<2>(a, l, v);
  }
  // sigmas 1 m and 1e6 m, axes turned by 0.3 rad: the variances 1 and 1e12, the small one from
  // a - t b; in long double the exact value of the rounded matrix's smaller eigenvalue.
  const double th = 0.3, c = std::cos(th), s = std::sin(th);
  Mat2 r;
  r << c, -s, s, c;
  const Mat2 a = r * Vec2(1.0, 1e12).asDiagonal() * r.transpose();
  Vec2 l;
  Mat2 v;
  symmetric_eigen_2x2(a, &l, &v);
  const long double p = a(0, 0), q = 0.5L * (static_cast<long double>(a(0, 1)) + a(1, 0)), w = a(1, 1);
  const long double m = 0.5L * (p + w), d = std::sqrt(0.25L * (p - w) * (p - w) + q * q);
  const long double small = (p * w - q * q) / (m + d);
  std::printf("2x2, variances 1 and 1e12: the small eigenvalue %.17g, long double %.17Lg\n", l(0), small);
  // a - t b cancels down from a(0,0) (8.7e10 here): a few ulps of it, 1e-4 of the value, where
  // eps ||A|| of a backward-stable solver is 2e-4 of it.
  EXPECT_NEAR(l(0), static_cast<double>(small), 4.0 * 2.2e-16 * std::abs(a(0, 0)));
  EXPECT_NEAR(l(1), 1e12, 1e-3);
}

TEST(SymmetricEigen, DiagonalAndNonFiniteInput) {
  Vec2 l;
  Mat2 v;
  symmetric_eigen_2x2(Vec2(3.0, -1.0).asDiagonal(), &l, &v);
  EXPECT_EQ(l, Vec2(-1.0, 3.0));
  Mat6 a = Mat6::Identity();
  a(2, 3) = a(3, 2) = std::nan("");
  Vec6 l6;
  Mat6 v6;
  EXPECT_FALSE(symmetric_eigen_jacobi<6>(a, &l6, &v6));
}

}  // namespace
