// Monte Carlo Pc against the 2D Pc: inside the interval where the short-term assumptions hold
// (a 7.5 km/s LEO crossing), away from it where they fail (Alfano 2009 case 1, two GEO
// objects 5 m apart at 1.4 cm/s, the states and RTN covariances of the published case).
#include <gtest/gtest.h>

#include "evade/assessment/assess.hpp"
#include "evade/assessment/covariance.hpp"

namespace evade::assessment {
namespace {

Mat6 lower_rtn(const double* l) {  // CDM order: CR_R, CT_R, CT_T, CN_R, ... CNDOT_NDOT
  Mat6 c;
  int k = 0;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j <= i; ++j) c(i, j) = c(j, i) = l[k++];
  }
  return c;
}

TEST(MonteCarloPc, IntervalContains2dPcForFastEncounter) {
  ConjunctionInput in;
  in.hbr_m = 10.0;
  const double v = 7546.0;
  in.obj[0].state = {Vec3(7000e3, 0, 0), Vec3(0, v, 0)};
  in.obj[1].state = {Vec3(7000e3 + 15.0, 0, 0), Vec3(0, v * 0.5, v * 0.8660254037844386)};
  in.obj[0].cov_eci.block<3, 3>(0, 0) = Mat3::Identity() * 400.0;
  in.obj[1].cov_eci.block<3, 3>(0, 0) = Mat3::Identity() * 225.0;
  MonteCarloOptions mc;
  mc.samples = 20000;
  mc.seed = 7;
  const Assessment a = assess(in, AssessConfig{}, mc);
  ASSERT_TRUE(a.mc.has_value());
  EXPECT_TRUE(a.short_term.valid) << a.short_term.reason;
  EXPECT_GT(a.pc_2d.pc, 1e-2);
  EXPECT_LE(a.mc->pc_low, a.pc_2d.pc);
  EXPECT_GE(a.mc->pc_high, a.pc_2d.pc);
}

TEST(MonteCarloPc, DepartsFrom2dPcAtLowRelativeSpeed) {
  const double c1[21] = {1.988970273925819e+01, -3.524140813027809e+02, 6.496749385722737e+03,
                         0, 0, 1.205039522307600e+00, 2.675448519614438e-02,
                         -4.943011253984911e-01, 0, 3.761358714147070e-05,
                         -1.027762112958557e-03, 1.780445954821163e-02, 0,
                         -1.349905611451490e-06, 5.376164545080801e-08, 0, 0,
                         -6.070876344492500e-05, 0, 0, 3.390390010767800e-09};
  const double c2[21] = {1.989074842319444e+01, -3.524310089952797e+02, 6.496894829253188e+03,
                         0, 0, 1.204674647143796e+00, 2.675573872452930e-02,
                         -4.943115446971844e-01, 0, 3.761433292802947e-05,
                         -1.027907518900499e-03, 1.780719276302711e-02, 0,
                         -1.350111723313400e-06, 5.377343757879955e-08, 0, 0,
                         -6.071534561359923e-05, 0, 0, 3.392080345234430e-09};
  ConjunctionInput in;
  in.hbr_m = 15.0;
  in.obj[0].state = {Vec3(153.446765, 41874.155870, 0.0) * 1e3,
                     Vec3(3.066874761, -0.011373615, 0.0) * 1e3};
  in.obj[1].state = {Vec3(153.447264, 41874.156370, 0.005) * 1e3,
                     Vec3(3.066864761, -0.011363615, -0.000000001) * 1e3};
  for (int i = 0; i < 2; ++i) {
    in.obj[i].cov_eci = cov_eci_from_rtn(lower_rtn(i == 0 ? c1 : c2), in.obj[i].state);
    in.obj[i].has_velocity_cov = true;
  }
  AssessConfig cfg;
  cfg.tca_search_s = 0.0;  // the published case is evaluated at the given states
  MonteCarloOptions mc;
  mc.samples = 4000;
  mc.seed = 3;
  const Assessment a = assess(in, cfg, mc);
  EXPECT_NEAR(a.pc_2d.pc, 1.46749549e-01, 1e-3 * 1.46749549e-01);  // CARA Pc2D_Foster
  EXPECT_FALSE(a.short_term.valid);
  EXPECT_FALSE(a.short_term.reason.empty());
  ASSERT_TRUE(a.mc.has_value());
  EXPECT_TRUE(a.pc_2d.pc < a.mc->pc_low || a.pc_2d.pc > a.mc->pc_high)
      << "MC [" << a.mc->pc_low << ", " << a.mc->pc_high << "] 2D " << a.pc_2d.pc;
  std::printf("Alfano case 1: 2D %.6g, MC %.6g [%.6g, %.6g], window %.0f s, %s\n", a.pc_2d.pc,
              a.mc->pc, a.mc->pc_low, a.mc->pc_high, a.mc->window_s, a.short_term.reason.c_str());
}

TEST(Covariance, NonPositiveDefiniteIsRepairedAndFlagged) {
  Mat3 c;
  c << 4, 2, 0, 2, 1, 0, 0, 0, -1e-3;  // eigenvalues 5, 0, -1e-3
  const CovarianceRepair r = repair_covariance(c, "object1");
  EXPECT_TRUE(r.npd);
  EXPECT_LT(r.min_eigenvalue_m2, 0.0);
  Eigen::SelfAdjointEigenSolver<Mat3> es(r.cov_m2);
  EXPECT_GT(es.eigenvalues().minCoeff(), 0.0);
  EXPECT_NEAR((r.cov_m2 - c).norm(), std::sqrt(1e-6 + 0.0), 1e-3);
  Mat3 asym = Mat3::Identity();
  asym(0, 1) = 1.0;
  EXPECT_THROW(repair_covariance(asym, "object2"), std::invalid_argument);
  EXPECT_FALSE(repair_covariance(Mat3::Identity(), "object1").npd);
}

}  // namespace
}  // namespace evade::assessment
