// The 3D-Nc collision rate at one time: the peak overlap position (POP) of the two objects'
// position PDFs, the linearized relative state PDF about it, and the unit-sphere integral of
// the inward flux (pc_3d_nc.cpp's header gives the method, the sources and the equations).
#include "nc_rate.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "evade/assessment/equinoctial.hpp"
#include "evade/assessment/sphere_quadrature.hpp"

namespace evade::assessment::nc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kFclip = 1e-4;     // eigenvalue clip (Fclip HBR)^2 of position covariances
constexpr double kMd2Cut = 1491.0;  // exp(-MD2/2) underflows to 0 beyond this
constexpr int kMaxIter = 100;       // POP iterations; averaging, relaxation, oscillation
constexpr int kAvgIter = 35;        //   checks start after these (as CARA's defaults)
constexpr int kAccIter = 25;
constexpr int kOscIter = 15;
constexpr double kMd2Tol1 = 1e-6;
constexpr double kMd2Tol2 = 1e-3;

// The expansion centre of one object: Cartesian state at t, the elements it has at TCA and
// the Jacobian dX(t)/dE(0) there.
struct Expansion {
  Vec6 xs = Vec6::Zero();
  Vec6 es0 = Vec6::Zero();
  Mat6 js = Mat6::Zero();
};

struct ClippedInverse {
  Mat3 inv = Mat3::Zero();
  double log_det = 0.0;
  Vec3 stiffest = Vec3::UnitZ();  // eigenvector of the smallest (clipped) eigenvalue
};

ClippedInverse clipped_inverse(const Mat3& a, double lclip) {
  Eigen::SelfAdjointEigenSolver<Mat3> es(0.5 * (a + a.transpose()));
  Vec3 l = es.eigenvalues();
  ClippedInverse c;
  for (int i = 0; i < 3; ++i) {
    l(i) = std::max(l(i), lclip);
    c.log_det += std::log(l(i));
  }
  c.inv = es.eigenvectors() * l.cwiseInverse().asDiagonal() * es.eigenvectors().transpose();
  c.stiffest = es.eigenvectors().col(0);
  return c;
}

Mat6 element_phi(double t_s) {
  Mat6 phi = Mat6::Identity();
  phi(5, 0) = t_s;
  return phi;
}

// The offset state x_s + J_s (E_mean(0) - E_s(0)), the mean longitude difference wrapped.
Vec6 offset_state(const ElementPdf& pdf, const Expansion& x) {
  Vec6 de = pdf.e0 - x.es0;
  de(5) = std::asin(std::sin(pdf.e0(5) - x.es0(5)));
  return x.xs + x.js * de;
}

bool expand_about(const Vec6& xs, double t_s, double mu, Expansion* out) {
  Vec6 et;
  if (!cartesian_to_equinoctial(xs, mu, &et)) return false;
  out->xs = xs;
  out->es0 = et;
  out->es0(5) = std::fmod(et(5) - et(0) * t_s, kTwoPi);
  if (out->es0(5) < 0.0) out->es0(5) += kTwoPi;
  out->js = jacobian_equinoctial_to_cartesian(et, xs, mu) * element_phi(t_s);
  return true;
}

Expansion mean_expansion(const ElementPdf& pdf, double t_s, double mu) {
  Expansion x;
  x.es0 = pdf.e0;
  x.js = jacobian_epoch_elements_to_cartesian(pdf.e0, t_s, mu, &x.xs);
  return x;
}

// One POP step: the peak of the product of the two position PDFs and the velocities there.
struct OverlapStep {
  Vec3 mup = Vec3::Zero();
  Mat3 sigp_rem_inv = Mat3::Identity();
  Vec3 vup[2];
};

OverlapStep overlap_step(const ElementPdf* pdf[2], const Expansion* x[2], bool first,
                         double hbr_m) {
  const double lclip = (kFclip * hbr_m) * (kFclip * hbr_m);
  Mat3 ainv[2];
  Mat3 bs[2];
  Vec6 xu[2];
  for (int i = 0; i < 2; ++i) {
    xu[i] = first ? x[i]->xs : offset_state(*pdf[i], *x[i]);
    const Mat6 ps = x[i]->js * pdf[i]->q * x[i]->js.transpose();
    ainv[i] = clipped_inverse(ps.block<3, 3>(0, 0), lclip).inv;
    bs[i] = 0.5 * (ps.block<3, 3>(3, 0) + ps.block<3, 3>(0, 3).transpose());
  }
  OverlapStep s;
  const Mat3 sigp = (ainv[0] + ainv[1]).inverse();
  s.mup = sigp * (ainv[0] * xu[0].head<3>() + ainv[1] * xu[1].head<3>());
  s.sigp_rem_inv = (sigp + hbr_m * hbr_m * Mat3::Identity()).inverse();
  for (int i = 0; i < 2; ++i) {
    s.vup[i] = xu[i].tail<3>() + bs[i] * ainv[i] * (s.mup - xu[i].head<3>());
  }
  return s;
}

// POP convergence: 1 converged, -1 iteration limit, 0 continue.
int pop_verdict(int iteration, const Vec3& d_old, const Vec3& d_old2, const Mat3& w) {
  const double dmd2 = d_old.dot(w * d_old);
  if (dmd2 <= kMd2Tol1) return 1;
  if (iteration >= kMaxIter) return -1;
  if (iteration <= kOscIter) return 0;
  if (d_old2.dot(w * d_old2) <= kMd2Tol1) return 1;  // oscillating between two points
  double cut = kMd2Tol1;
  if (iteration > kAvgIter) {
    cut = kMd2Tol2;
  } else if (iteration > kAccIter) {
    const double frc = double(iteration - kAccIter) / double(kAvgIter - kAccIter);
    cut = std::exp((1.0 - frc) * std::log(kMd2Tol1) + frc * std::log(kMd2Tol2));
  }
  return dmd2 <= cut ? 1 : 0;
}

bool unbound(const Vec3& r, const Vec3& v, double mu) {
  return 0.5 * v.squaredNorm() - mu / r.norm() >= 0.0;
}

struct PopResult {
  Expansion x[2];
  bool converged = false;
  int iterations = 0;
};

// Iterates the expansion centres to the peak overlap position at t_s.
PopResult peak_overlap(const ElementPdf& p1, const ElementPdf& p2, double t_s,
                       const RateSettings& s) {
  PopResult r;
  r.x[0] = mean_expansion(p1, t_s, s.mu_m3ps2);
  r.x[1] = mean_expansion(p2, t_s, s.mu_m3ps2);
  const ElementPdf* pdf[2] = {&p1, &p2};
  Vec3 mup_old = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  Vec3 mup_old2 = mup_old;
  for (int it = 0;; ++it) {
    const Expansion* xp[2] = {&r.x[0], &r.x[1]};
    OverlapStep st = overlap_step(pdf, xp, it == 0, s.hbr_m);
    if (it > kAvgIter) st.mup = 0.5 * (st.mup + mup_old);
    r.iterations = it;
    if (unbound(st.mup, st.vup[0], s.mu_m3ps2) || unbound(st.mup, st.vup[1], s.mu_m3ps2)) {
      return r;
    }
    const int verdict = it == 0 ? 0 : pop_verdict(it, mup_old - st.mup, mup_old2 - st.mup,
                                                  st.sigp_rem_inv);
    Expansion next[2];
    for (int i = 0; i < 2; ++i) {
      Vec6 xs;
      xs << st.mup, st.vup[i];
      if (!expand_about(xs, t_s, s.mu_m3ps2, &next[i])) return r;
    }
    r.x[0] = next[0];
    r.x[1] = next[1];
    if (verdict != 0) {
      r.converged = verdict > 0;
      return r;
    }
    mup_old2 = mup_old;
    mup_old = st.mup;
  }
}

}  // namespace

namespace {

// The relative-state PDF about the POP: mean (ru, vu), position covariance A (inverse and
// log-determinant), the conditional velocity mean slope b = B A^-1 and covariance
// C' = C - B A^-1 B^T (Coppola 2012a; Hall 2021).
struct RelativePdf {
  Vec3 ru, vu;
  Mat3 ainv, b, cp;
  double log_z = 0.0;  // -log of the Gaussian normalization, 1.5 log(2 pi) + 0.5 log det A
  Vec3 stiffest;
};

RelativePdf relative_pdf(const ElementPdf& p1, const ElementPdf& p2, const PopResult& pop,
                         double hbr_m) {
  const Vec6 xu = offset_state(p2, pop.x[1]) - offset_state(p1, pop.x[0]);
  Mat6 ps = pop.x[0].js * p1.q * pop.x[0].js.transpose() +
            pop.x[1].js * p2.q * pop.x[1].js.transpose();
  ps = 0.5 * (ps + ps.transpose()).eval();
  const ClippedInverse ai = clipped_inverse(ps.block<3, 3>(0, 0), (kFclip * hbr_m) * (kFclip * hbr_m));
  RelativePdf r;
  r.ru = xu.head<3>();
  r.vu = xu.tail<3>();
  r.ainv = ai.inv;
  r.b = ps.block<3, 3>(3, 0) * ai.inv;
  r.cp = ps.block<3, 3>(3, 3) - r.b * ps.block<3, 3>(3, 0).transpose();
  r.log_z = 1.5 * std::log(kTwoPi) + 0.5 * ai.log_det;
  r.stiffest = ai.stiffest;
  return r;
}

// Expected inward speed E[max(0, -rhat.v)] for rhat.v ~ N(nu0, sig2) (Coppola 2012a).
double inward_speed(double nu0, double sig2) {
  if (!(sig2 > 0.0)) return std::max(0.0, -nu0);
  const double sig = std::sqrt(sig2);
  const double x = nu0 / (sig * std::sqrt(2.0));
  const double h = std::exp(-x * x) - std::sqrt(kPi) * x * std::erfc(x);
  return std::max(0.0, sig * h / std::sqrt(kTwoPi));
}

// Orthonormal frame whose third axis is the quadrature pole.
Mat3 pole_frame(const Vec3& pole) {
  const Vec3 z = pole.normalized();
  const Vec3 helper = std::abs(z.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 x = helper.cross(z).normalized();
  Mat3 m;
  m.col(0) = x;
  m.col(1) = z.cross(x);
  m.col(2) = z;
  return m;
}

// The flux integral over the sphere of radius R with one rule, without the R^2 factor.
double sphere_sum(const RelativePdf& p, const Mat3& frame, double hbr_m, int level) {
  const SphereRule& rule = sphere_rule(level);
  double sum = 0.0;
  for (std::size_t k = 0; k < rule.dir.size(); ++k) {
    const Vec3 rhat = frame * rule.dir[k];
    const Vec3 dr = hbr_m * rhat - p.ru;
    const double md2 = dr.dot(p.ainv * dr);
    const double expo = p.log_z + 0.5 * md2;
    if (expo > 700.0) continue;
    const double nu0 = rhat.dot(p.vu + p.b * dr);
    sum += rule.weight[k] * inward_speed(nu0, rhat.dot(p.cp * rhat)) * std::exp(-expo);
  }
  return sum;
}

}  // namespace

Rate collision_rate(const ElementPdf& obj1, const ElementPdf& obj2, double t_s,
                    const RateSettings& s, double abs_floor_per_s) {
  const PopResult pop = peak_overlap(obj1, obj2, t_s, s);
  const RelativePdf p = relative_pdf(obj1, obj2, pop, s.hbr_m);
  const double h2 = s.hbr_m * s.hbr_m;
  Rate out;
  out.pop_converged = pop.converged;
  out.pop_iterations = pop.iterations;
  const double ms = p.ru.dot(p.ainv * p.ru);
  out.rate_small_per_s = h2 * kPi * std::exp(-p.log_z - 0.5 * ms) * p.vu.norm();
  out.ms2 = ms - 2.0 * s.hbr_m * (p.ainv * p.ru).norm();
  if (out.ms2 > kMd2Cut) return out;
  // Pole along the mean relative velocity at the sphere's centre, so that the kink of the
  // inward speed (rhat . v = 0) lies on the rule's equator between its two hemispheres.
  const Vec3 vc = p.vu - p.b * p.ru;
  const Mat3 frame = pole_frame(vc.norm() > 0.0 ? vc : (p.ru.norm() > 0.0 ? p.ru : p.stiffest));
  double prev = 0.0;
  for (int level = 0; level < kSphereLevels; ++level) {
    const double cur = h2 * sphere_sum(p, frame, s.hbr_m, level);
    out.sphere_points += static_cast<int>(sphere_rule(level).dir.size());
    out.rate_per_s = cur;
    out.sphere_error_per_s = std::abs(cur - prev);
    if (level > 0 && out.sphere_error_per_s <= s.sphere_rel_tol * std::abs(cur) + abs_floor_per_s) {
      return out;
    }
    prev = cur;
  }
  out.sphere_converged = false;
  return out;
}

}  // namespace evade::assessment::nc
