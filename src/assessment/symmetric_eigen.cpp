// Small symmetric eigen-decompositions for flight code (symmetric_eigen.hpp): Golub & Van Loan,
// "Matrix Computations", 4th ed., 2013, Algorithms 8.5.1 (the 2x2 symmetric Schur rotation)
// and 8.5.3 (cyclic-by-row Jacobi).
#include "evade/assessment/symmetric_eigen.hpp"

#include <cmath>

namespace evade::assessment {
namespace {

// Algorithm 8.5.1: (c, s) such that [c s; -s c]^T [app apq; apq aqq] [c s; -s c] is diagonal,
// the rotation of the smaller angle; t = s / c.
void schur2(double app, double apq, double aqq, double* c, double* s, double* t) noexcept {
  if (apq == 0.0) {
    *c = 1.0;
    *s = 0.0;
    *t = 0.0;
    return;
  }
  const double tau = (aqq - app) / (2.0 * apq);
  *t = (tau >= 0.0 ? 1.0 : -1.0) / (std::abs(tau) + std::hypot(1.0, tau));
  *c = 1.0 / std::hypot(1.0, *t);
  *s = *t * *c;
}

// Sorts the eigenvalues ascending with their columns (insertion sort: N <= 6).
template <int N>
void sort_ascending(Eigen::Matrix<double, N, 1>* l, Eigen::Matrix<double, N, N>* v) noexcept {
  for (int i = 1; i < N; ++i) {
    for (int j = i; j > 0 && (*l)(j - 1) > (*l)(j); --j) {
      std::swap((*l)(j - 1), (*l)(j));
      v->col(j - 1).swap(v->col(j));
    }
  }
}

// One rotation of the cyclic Jacobi method in the (p, q) plane: A <- J^T A J, V <- V J.
template <int N>
void rotate(int p, int q, Eigen::Matrix<double, N, N>* a, Eigen::Matrix<double, N, N>* v) noexcept {
  double c = 1.0, s = 0.0, t = 0.0;
  schur2((*a)(p, p), (*a)(p, q), (*a)(q, q), &c, &s, &t);
  if (s == 0.0) return;
  for (int k = 0; k < N; ++k) {  // columns p and q of A J
    const double akp = (*a)(k, p), akq = (*a)(k, q);
    (*a)(k, p) = c * akp - s * akq;
    (*a)(k, q) = s * akp + c * akq;
  }
  for (int k = 0; k < N; ++k) {  // rows p and q of J^T (A J)
    const double apk = (*a)(p, k), aqk = (*a)(q, k);
    (*a)(p, k) = c * apk - s * aqk;
    (*a)(q, k) = s * apk + c * aqk;
  }
  (*a)(p, q) = 0.0;  // zero by construction; rounding would leave a trace
  (*a)(q, p) = 0.0;
  for (int k = 0; k < N; ++k) {
    const double vkp = (*v)(k, p), vkq = (*v)(k, q);
    (*v)(k, p) = c * vkp - s * vkq;
    (*v)(k, q) = s * vkp + c * vkq;
  }
}

template <int N>
double off_diagonal_norm(const Eigen::Matrix<double, N, N>& a) noexcept {
  double sum = 0.0;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      if (i != j) sum += a(i, j) * a(i, j);
  return std::sqrt(sum);
}

}  // namespace

void symmetric_eigen_2x2(const Mat2& a, Vec2* values, Mat2* vectors) noexcept {
  const double apq = 0.5 * (a(0, 1) + a(1, 0));
  double c = 1.0, s = 0.0, t = 0.0;
  schur2(a(0, 0), apq, a(1, 1), &c, &s, &t);
  *values << a(0, 0) - t * apq, a(1, 1) + t * apq;
  *vectors << c, s, -s, c;
  sort_ascending<2>(values, vectors);
}

template <int N>
bool symmetric_eigen_jacobi(const Eigen::Matrix<double, N, N>& a, Eigen::Matrix<double, N, 1>* values,
                            Eigen::Matrix<double, N, N>* vectors) noexcept {
  Eigen::Matrix<double, N, N> w = 0.5 * (a + a.transpose());
  *vectors = Eigen::Matrix<double, N, N>::Identity();
  const double norm = w.norm();
  bool converged = std::isfinite(norm);
  if (converged) {
    converged = false;
    for (int sweep = 0; sweep < kMaxJacobiSweeps && !converged; ++sweep) {
      converged = off_diagonal_norm<N>(w) <= 1e-14 * norm;
      for (int p = 0; p < N - 1 && !converged; ++p)
        for (int q = p + 1; q < N; ++q) rotate<N>(p, q, &w, vectors);
    }
    converged = converged || off_diagonal_norm<N>(w) <= 1e-14 * norm;
  }
  *values = w.diagonal();
  sort_ascending<N>(values, vectors);
  return converged;
}

template bool symmetric_eigen_jacobi<6>(const Mat6&, Vec6*, Mat6*) noexcept;

}  // namespace evade::assessment
