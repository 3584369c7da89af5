// 3D-Nc Pc (pc_3d_nc) against NASA CARA's published Pc3D_Hall values for the Alfano 2009 test
// cases (CARA_Analysis_Tools, Pc3D_Hall_UnitTest.m / A09TestCases_01_12_Distributed.csv, with
// CARA's 1e8-trial Monte Carlo beside them), the CARA unit-test LEO case testSimilarTo2D,
// bad input, the equinoctial Jacobian, and the convergence of the quadratures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "evade/ccsds/cdm_formats.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/assessment/equinoctial.hpp"
#include "evade/assessment/monte_carlo_pc.hpp"
#include "evade/assessment/pc_3d_nc.hpp"
#include "evade/assessment/sphere_quadrature.hpp"
#include "data/cara_similar_to_2d.hpp"

namespace evade::assessment {
namespace {

using namespace evade::commands;

constexpr double kMu = 3.986004418e14;  // CARA's GM [m^3/s^2]

// The requirement of the issue: every case within 2 % of CARA's 3D-Nc value. The CDMs round
// positions to 1 mm and velocities to 1 um/s (CARA used its unrounded tables), which alone
// can move the slow-encounter cases by a fraction of a percent. Seen (GCC 12, default
// rel_tol 1e-4): largest deviation -0.226 % (case 02, inside CARA's Monte Carlo 95 % interval),
// all others within 0.05 %.
constexpr double kRequiredRelTol = 0.02;

struct AlfanoCase {
  const char* name;
  int file;
  double hbr_m;
  double window_s;
  double cara_3d;
  double cara_mc;
};

const AlfanoCase kCases[] = {
    {"Case01", 1, 15.0, 21600.0, 0.216808362760001, 0.21686537},
    {"Case02", 2, 4.0, 21600.0, 0.0155677489682704, 0.0155469},
    {"Case03", 3, 15.0, 21600.0, 0.100336423200142, 0.10034086},
    {"Case04", 4, 15.0, 21600.0, 0.0736404193831196, 0.07364054},
    {"Case05", 5, 10.0, 1419.0, 0.0444898133497832, 0.04446611},
    {"Case06", 6, 10.0, 1419.0, 0.00433313097018186, 0.00432422},
    {"Case07", 7, 10.0, 1419.0, 0.000161841230198079, 0.00016011},
    {"Case08", 8, 4.0, 10135.0, 0.0352501749613797, 0.03523735},
    {"Case09", 9, 6.0, 10800.0, 0.279834261489978, 0.27977477},
    {"Case10", 9, 6.0, 21600.0, 0.364063796450824, 0.0},  // case 09's states, longer window
    {"Case11", 11, 4.0, 1420.0, 0.00244074884499185, 0.00243642},
};

ConjunctionInput load_case(int file, double hbr_m) {
  char name[64];
  std::snprintf(name, sizeof name, "/AlfanoTestCase%02d.cdm", file);
  std::ifstream in(std::string(EVADE_TEST_ALFANO_DIR) + name);
  if (!in) throw std::runtime_error(std::string("cannot open ") + name);
  std::stringstream ss;
  ss << in.rdbuf();
  return conjunction_from_cdm(ccsds::read_cdm_text(ss.str()), hbr_m, kEarthDefault);
}

Nc3dResult run(const ConjunctionInput& c, const Nc3dOptions& opt) {
  return pc_3d_nc(c.obj[0].state, c.obj[0].cov_eci, c.obj[1].state, c.obj[1].cov_eci, c.hbr_m,
                  kMu, opt);
}

class Pc3dNcAlfano : public ::testing::TestWithParam<AlfanoCase> {};

TEST_P(Pc3dNcAlfano, WithinTwoPercentOfCara) {
  const AlfanoCase& k = GetParam();
  const ConjunctionInput c = load_case(k.file, k.hbr_m);
  Nc3dOptions opt;
  opt.window_s = k.window_s;
  const Nc3dResult r = run(c, opt);
  const double dev = r.pc / k.cara_3d - 1.0;
  std::printf("[ Nc ] %s: ours %.9g  CARA 3D-Nc %.9g  (%+.4f %%)  CARA MC %.8g  small-HBR %.6g  "
              "evals %d  peak at %.1f s%s%s\n",
              k.name, r.pc, k.cara_3d, 100.0 * dev, k.cara_mc, r.pc_small_hbr,
              r.rate_evaluations, r.t_peak_s, r.converged ? "" : "  NOT CONVERGED: ",
              r.failure.c_str());
  EXPECT_TRUE(r.converged) << r.failure;
  EXPECT_NEAR(r.pc, k.cara_3d, kRequiredRelTol * k.cara_3d);
}

INSTANTIATE_TEST_SUITE_P(Cases, Pc3dNcAlfano, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<AlfanoCase>& i) {
                           return std::string(i.param.name);
                         });

// CARA Pc3D_Hall_UnitTest.m, testSimilarTo2D: a LEO crossing, HBR 20 m, default window.
using test_data::LeoCase;

LeoCase similar_to_2d() { return test_data::cara_similar_to_2d(); }

TEST(Pc3dNc, CaraSimilarTo2dLeo) {
  const LeoCase k = similar_to_2d();
  const Nc3dResult r = pc_3d_nc(k.s1, k.c1, k.s2, k.c2, 20.0, kMu);
  std::printf("[ Nc ] SimilarTo2D: ours %.9g  CARA %.9g  (%+.4f %%)  window [%.3f, %.3f] s  "
              "evals %d\n",
              r.pc, 1.0289973e-02, 100.0 * (r.pc / 1.0289973e-02 - 1.0), r.t_begin_s,
              r.t_end_s, r.rate_evaluations);
  EXPECT_TRUE(r.converged) << r.failure;
  EXPECT_NEAR(r.pc, 1.0289973e-02, 1e-3 * 1.0289973e-02);  // CARA's own unit-test tolerance
  EXPECT_LT(r.coppola.tau0_s, 0.0);
  EXPECT_GT(r.coppola.tau1_s, 0.0);
}


// Bad input: std::invalid_argument naming what is wrong.
void expect_invalid(const LeoCase& k, double hbr_m, const std::string& fragment) {
  try {
    (void)pc_3d_nc(k.s1, k.c1, k.s2, k.c2, hbr_m, kMu);
    ADD_FAILURE() << "no exception for " << fragment;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Pc3dNc, BadInputThrowsInvalidArgument) {
  LeoCase k = similar_to_2d();
  expect_invalid(k, 0.0, "hard-body radius must be finite and > 0 m");
  expect_invalid(k, -5.0, "hard-body radius must be finite and > 0 m");
  LeoCase nan_state = k;
  nan_state.s2.v_eci_mps.y() = std::nan("");
  expect_invalid(nan_state, 20.0, "object 2 state has a non-finite component");
  LeoCase not_psd = k;
  not_psd.c1(0, 1) = not_psd.c1(1, 0) = 2.0 * std::sqrt(k.c1(0, 0) * k.c1(1, 1));
  expect_invalid(not_psd, 20.0, "object 1 covariance is not positive semi-definite");
  LeoCase negative = k;
  negative.c2(3, 3) = -1e-3;
  expect_invalid(negative, 20.0, "object 2 covariance has a negative variance");
  LeoCase asym = k;
  asym.c2(0, 2) *= 1.5;
  expect_invalid(asym, 20.0, "object 2 covariance is not symmetric");
  LeoCase escape = k;
  escape.s1.v_eci_mps *= 1.5;
  expect_invalid(escape, 20.0, "object 1 orbit is unbound");
}

// The analytic dX/dE against central differences, and the element round trip.
TEST(Pc3dNc, EquinoctialJacobianMatchesFiniteDifferences) {
  const LeoCase k = similar_to_2d();
  for (const StateEci& s : {k.s1, k.s2}) {
    Vec6 e;
    ASSERT_TRUE(cartesian_to_equinoctial(s.stacked(), kMu, &e));
    const Vec6 x = equinoctial_to_cartesian(e, kMu);
    EXPECT_LT((x - s.stacked()).head<3>().norm(), 1e-6);
    EXPECT_LT((x - s.stacked()).tail<3>().norm(), 1e-9);
    const Mat6 j = jacobian_epoch_elements_to_cartesian(e, 600.0, kMu, nullptr);
    for (int c = 0; c < 6; ++c) {
      const double h = 1e-7 * std::max(std::abs(e(c)), 1e-3);
      Vec6 ep = e, em = e;
      ep(c) += h;
      em(c) -= h;
      ep(5) += 600.0 * ep(0);  // lambda_M(600 s) = lambda_M0 + n 600 s
      em(5) += 600.0 * em(0);
      const Vec6 fd = (equinoctial_to_cartesian(ep, kMu) - equinoctial_to_cartesian(em, kMu)) / (2 * h);
      EXPECT_LT((fd - j.col(c)).norm(), 1e-5 * std::max(1.0, j.col(c).norm())) << "column " << c;
    }
  }
}

// The sphere rule: exact for low-degree polynomials from the first level, and converging by
// doubling on a narrow Gaussian cap exp(k (z - 1)), whose integral is 2 pi (1 - e^{-2k}) / k.
TEST(Pc3dNc, SphereQuadratureConverges) {
  const double pi = 3.14159265358979323846;
  const SphereRule& r0 = sphere_rule(0);
  double area = 0.0, z2 = 0.0;
  for (std::size_t i = 0; i < r0.dir.size(); ++i) {
    area += r0.weight[i];
    z2 += r0.weight[i] * r0.dir[i].z() * r0.dir[i].z();
  }
  EXPECT_NEAR(area, 4.0 * pi, 1e-12);
  EXPECT_NEAR(z2, 4.0 * pi / 3.0, 1e-12);
  const double kappa = 400.0;  // angular width ~ 0.05 rad, as a 1 m sigma on a 20 m sphere
  const Vec3 axis = Vec3(0.3, -0.5, 0.8).normalized();
  const double exact = 2.0 * pi * (1.0 - std::exp(-2.0 * kappa)) / kappa;
  double prev_err = 1.0;
  for (int level = 0; level < kSphereLevels; ++level) {
    const SphereRule& r = sphere_rule(level);
    double sum = 0.0;
    for (std::size_t i = 0; i < r.dir.size(); ++i) {
      sum += r.weight[i] * std::exp(kappa * (r.dir[i].dot(axis) - 1.0));
    }
    const double err = std::abs(sum / exact - 1.0);
    std::printf("[ Nc ] sphere level %d (%zu points): relative error %.3g\n", level, r.dir.size(), err);
    if (level >= 3) {
      EXPECT_LT(err, 0.1 * prev_err + 1e-13);
    }
    prev_err = err;
  }
  EXPECT_LT(prev_err, 1e-10);
}

// Halving both tolerances (time integral and unit-sphere integral) moves the Pc by less than
// the looser tolerance: the LEO case and a slow GEO case (Alfano 01, sphere 15 m vs 1 m sigma).
TEST(Pc3dNc, TighterTolerancesChangePcLessThanTolerance) {
  const LeoCase k = similar_to_2d();
  Nc3dOptions loose, tight;
  tight.rel_tol = 0.01 * loose.rel_tol;
  tight.sphere_rel_tol = 0.01 * loose.sphere_rel_tol;
  const Nc3dResult a = pc_3d_nc(k.s1, k.c1, k.s2, k.c2, 20.0, kMu, loose);
  const Nc3dResult b = pc_3d_nc(k.s1, k.c1, k.s2, k.c2, 20.0, kMu, tight);
  std::printf("[ Nc ] LEO: rel_tol %.0e -> %.9g (%d rates), %.0e -> %.9g (%d rates)\n",
              loose.rel_tol, a.pc, a.rate_evaluations, tight.rel_tol, b.pc, b.rate_evaluations);
  EXPECT_LT(std::abs(a.pc / b.pc - 1.0), loose.rel_tol);
  EXPECT_GT(b.rate_evaluations, a.rate_evaluations);
  const ConjunctionInput c = load_case(1, 15.0);
  loose.window_s = tight.window_s = 21600.0;
  const Nc3dResult ga = run(c, loose);
  const Nc3dResult gb = run(c, tight);
  std::printf("[ Nc ] Alfano 01: rel_tol %.0e -> %.9g (%d rates), %.0e -> %.9g (%d rates)\n",
              loose.rel_tol, ga.pc, ga.rate_evaluations, tight.rel_tol, gb.pc, gb.rate_evaluations);
  EXPECT_LT(std::abs(ga.pc / gb.pc - 1.0), 10.0 * loose.rel_tol);
}

// The default window and the small-HBR limit: for the LEO case the rate is concentrated
// inside Coppola's bounds; the secondary's smallest position sigma is not >> 20 m, so the
// small-HBR Nc is only of the same order (0.0077 against 0.0103).
TEST(Pc3dNc, LeoDefaultWindowAndSmallHbrLimit) {
  const LeoCase k = similar_to_2d();
  const Nc3dResult r = pc_3d_nc(k.s1, k.c1, k.s2, k.c2, 20.0, kMu);
  EXPECT_NEAR(r.t_begin_s, r.coppola.tau0_s, 1e-9);
  EXPECT_NEAR(r.t_end_s, r.coppola.tau1_s, 1e-9);
  EXPECT_GT(r.t_peak_s, r.t_begin_s);
  EXPECT_LT(r.t_peak_s, r.t_end_s);
  EXPECT_GT(r.pc_small_hbr, 0.5 * r.pc);
  EXPECT_LT(r.pc_small_hbr, 1.5 * r.pc);
  EXPECT_GT(r.period1_s, 5000.0);
}

// Zero relative velocity at TCA (the situation of Alfano's case 12, whose states we do not
// have as text): the 2D Pc is undefined (no encounter plane), 3D-Nc is not. Case 11's states
// with object 2 given object 1's velocity: a finite, converged Nc below 1 over +-1420 s, and a
// Monte Carlo of the same encounter (2e4 samples, 99.9 % interval, z = 3.29) holds it.
TEST(Pc3dNc, ZeroRelativeVelocityIsDefined) {
  ConjunctionInput c = load_case(11, 4.0);
  c.obj[1].state.v_eci_mps = c.obj[0].state.v_eci_mps;
  Nc3dOptions opt;
  opt.window_s = 1420.0;
  const Nc3dResult r = run(c, opt);
  EXPECT_TRUE(r.converged) << r.failure;
  EXPECT_TRUE(std::isfinite(r.pc));
  EXPECT_GT(r.pc, 0.0);
  EXPECT_LT(r.pc, 1.0);
  MonteCarloOptions mo;
  mo.samples = 2 * kMcBlockSamples;
  mo.window_s = 1420.0;
  mo.z = 3.29;
  mo.threads = 2;
  const MonteCarloResult m = pc_monte_carlo(
      McEncounter{c.obj[0].state, c.obj[1].state, c.obj[0].cov_eci, c.obj[1].cov_eci, 4.0, kEarthDefault}, mo);
  EXPECT_LE(m.pc_low, r.pc);
  EXPECT_GE(m.pc_high, r.pc);
  std::printf("[ Nc ] zero relative velocity (case 11 states): 3D-Nc %.6g, MC %.6g [%.6g, %.6g]\n",
              r.pc, m.pc, m.pc_low, m.pc_high);
}

}  // namespace
}  // namespace evade::assessment
