// TCA refinement of `assess` (assess.hpp) on a slow pair: two LEO objects 917 m apart
// radially, drifting at ~1.2 m/s along-track (the co-orbital pairs of the synthetic
// population). The relative acceleration along the separation (differential gravity,
// ~2 n^2 917 m = 2.5e-3 m/s^2) makes r.a_rel (2.3 m^2/s^2) larger than |v|^2 (1.4 m^2/s^2):
// Newton with f' = |v|^2 alone then multiplies the error by 1 - f'/|v|^2 = -1.7 per step and
// diverges; with f' = |v|^2 + r.a_rel it converges. States 0.2 s before the TCA.
#include <gtest/gtest.h>

#include <cmath>

#include "evade/assessment/assess.hpp"
#include "evade/assessment/covariance_propagation.hpp"

namespace evade::assessment {
namespace {

TEST(TcaRefinement, SlowPairConvergesWithRelativeAcceleration) {
  const double r = 7.0e6, v = std::sqrt(kEarthDefault.mu_m3ps2 / r);
  ConjunctionInput in;
  in.hbr_m = 10.0;
  in.obj[0].state = {Vec3(r, 0.0, 0.0), Vec3(0.0, v, 0.0)};
  in.obj[1].state = {Vec3(r + 917.0, 0.0, 0.0), Vec3(0.0, v + 1.17, 0.0)};
  for (auto& o : in.obj) {
    o.state = propagate_j2(o.state, -0.2, in.earth);
    o.cov_eci.block<3, 3>(0, 0) = Mat3::Identity() * 1e4;
  }
  const Assessment a = assess(in, AssessConfig{});
  const Vec3 dr = a.at_tca[1].state.r_eci_m - a.at_tca[0].state.r_eci_m;
  const Vec3 dv = a.at_tca[1].state.v_eci_mps - a.at_tca[0].state.v_eci_mps;
  EXPECT_LT(std::abs(dr.dot(dv)) / dv.squaredNorm(), 1e-5);  // at the TCA to 10 us
  EXPECT_GT(std::abs(a.tca_shift_s), 0.01);                  // it did move the states
  EXPECT_LT(std::abs(a.tca_shift_s), 1.0);
}

}  // namespace
}  // namespace evade::assessment
