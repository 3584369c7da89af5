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

#include "evade/assessment/conjunction_input.hpp"
#include "evade/assessment/equinoctial.hpp"
#include "evade/assessment/pc_3d_nc.hpp"
#include "evade/assessment/sphere_quadrature.hpp"

namespace evade::assessment {
namespace {

constexpr double kMu = 3.986004418e14;  // CARA's GM [m^3/s^2]

// The requirement of the issue: every case within 2 % of CARA's 3D-Nc value. The CDMs round
// positions to 1 mm and velocities to 1 um/s (CARA used its unrounded tables), which alone
// can move the slow-encounter cases by a fraction of a percent; the largest deviation seen
// is reported by the test output and in the commit message.
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
  return conjunction_from_cdm(read_cdm_text(ss.str()), hbr_m, kEarthDefault);
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
struct LeoCase {
  StateEci s1, s2;
  Mat6 c1, c2;
};

LeoCase similar_to_2d() {
  LeoCase k;
  k.s1 = {Vec3(-9.841950433215101e+05, +3.932342044549424e+05, +6.991223682230414e+06),
          Vec3(+4.883696742000000e+03, +5.689086045000000e+03, +3.665361590000000e+02)};
  k.s2 = {Vec3(-9.839696058965517e+05, +3.936845951174244e+05, +6.991219291625473e+06),
          Vec3(+1.509562687000000e+03, +7.372938617000000e+03, -1.492509430000000e+02)};
  k.c1 << +4.976545641899520e+04, +5.787130862568278e+04, +3.370410320935015e+03, +1.137272273949272e+01, -4.325472616114674e+00, -8.009705480233521e+01,
      +5.787130862568278e+04, +6.730377643610841e+04, +3.926542932121541e+03, +1.321992688238858e+01, -5.035560720747812e+00, -9.314985106902773e+01,
      +3.370410320935015e+03, +3.926542932121541e+03, +2.461403197221289e+02, +7.586865834476763e-01, -3.077848629905763e-01, -5.434034460756914e+00,
      +1.137272273949272e+01, +1.321992688238858e+01, +7.586865834476763e-01, +2.608186227148725e-03, -9.804181796720670e-04, -1.829751672999786e-02,
      -4.325472616114674e+00, -5.035560720747812e+00, -3.077848629905763e-01, -9.804181796720670e-04, +3.895883508545853e-04, +6.968892326415779e-03,
      -8.009705480233521e+01, -9.314985106902773e+01, -5.434034460756914e+00, -1.829751672999786e-02, +6.968892326415779e-03, +1.289253320300791e-01;
  k.c2 << +4.246862551076427e+04, +2.066374367781032e+05, -5.011108933888592e+03, +3.104606531932427e+01, -1.201093683199582e+01, -2.207975848324051e+02,
      +2.066374367781032e+05, +1.005854717283451e+06, -2.434876491048039e+04, +1.510022508670080e+02, -5.850063541467530e+01, -1.074752763805685e+03,
      -5.011108933888592e+03, -2.434876491048039e+04, +6.131274993037449e+02, -3.667147183233717e+00, +1.391769957262238e+00, +2.601457791444154e+01,
      +3.104606531932427e+01, +1.510022508670080e+02, -3.667147183233717e+00, +2.272826228568773e-02, -8.778253314778023e-03, -1.613538091053610e-01,
      -1.201093683199582e+01, -5.850063541467530e+01, +1.391769957262238e+00, -8.778253314778023e-03, +3.428801115804722e-03, +6.251148178133809e-02,
      -2.207975848324051e+02, -1.074752763805685e+03, +2.601457791444154e+01, -1.613538091053610e-01, +6.251148178133809e-02, +1.148404222181769e+00;
  return k;
}

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

}  // namespace
}  // namespace evade::assessment
