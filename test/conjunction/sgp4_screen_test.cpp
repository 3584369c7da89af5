// Screening with SGP4 motion (issue 12): rejection of bad element sets, the velocity as the
// derivative of the SGP4 position, the perturbation envelope, the primary mode, and the
// options that tie a motion source to its Earth model.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "evade/conjunction/robust_screen.hpp"
#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/sgp4/tle_reader.hpp"
#include "sgp4_test_catalog.hpp"

namespace evade::conjunction {
namespace {

using testing::sgp4_test_catalog;
using testing::Sgp4TestCatalogOptions;

Sgp4TestCatalogOptions small_catalog(std::uint64_t seed) {
  Sgp4TestCatalogOptions o;
  o.background = 40;
  o.coorbital_pairs = 2;
  o.tangent_pairs = 2;
  o.crossing_pairs = 2;
  o.seed = seed;
  return o;
}

ScreenOptions sgp4_options(const Sgp4Screening& s) {
  ScreenOptions opt;
  opt.motion = s.motion;
  opt.gravity = GravityModel::kTwoBodyJ2;
  opt.earth = wgs72_earth();
  opt.threshold_m = 5000.0;
  opt.step_s = 60.0;
  opt.threads = 2;
  return opt;
}

TEST(Sgp4Screening, RejectsBadElementSetsNamingThemAndKeepsTheRest) {
  auto cat = sgp4_test_catalog(small_catalog(3));
  const std::size_t good = cat.size();
  sgp4::MeanElements hyperbolic = cat[0];
  hyperbolic.norad_id = 99001;
  hyperbolic.name = "HYPER";
  hyperbolic.eccentricity = 1.2;  // SGP4 error 1 at the epoch
  sgp4::MeanElements decaying = cat[0];
  decaying.norad_id = 99002;
  decaying.name = "FALLING";
  decaying.mean_motion_revpday = 16.4;  // perigee ~150 km
  decaying.eccentricity = 0.001;
  decaying.bstar_per_er = 0.5;          // decays within the day
  cat.push_back(hyperbolic);
  cat.push_back(decaying);
  Sgp4MotionOptions mo;
  mo.span_s = 86400.0;
  const Sgp4Screening s = sgp4_screening(cat, mo);
  ASSERT_EQ(s.rejected.size(), 2u);
  EXPECT_EQ(s.objects.size(), good);
  EXPECT_EQ(s.motion->size(), good);
  EXPECT_NE(s.rejected[0].message().find("NORAD 99001 (HYPER): SGP4 error 1"), std::string::npos)
      << s.rejected[0].message();
  EXPECT_NE(s.rejected[1].message().find("NORAD 99002 (FALLING)"), std::string::npos)
      << s.rejected[1].message();
  EXPECT_NE(s.rejected[1].message().find("from the start"), std::string::npos) << s.rejected[1].message();
}

// The velocity is d(position)/dt (a 4-point difference at 0.5 s is the check: truncation
// ~1e-11 m/s, and SGP4's up-to-7-um position jumps (sgp4_motion.hpp) add up to 2e-5 m/s to
// it and 7e-5 m/s to the central difference at 0.05 s under test): 2e-4 m/s.
TEST(Sgp4Screening, VelocityIsTheDerivativeOfThePosition) {
  const Sgp4Screening s = sgp4_screening(sgp4_test_catalog(small_catalog(4)), Sgp4MotionOptions{});
  const double h = 0.5;
  double worst = 0.0;
  for (std::size_t i = 0; i < s.objects.size(); i += 5) {
    for (double t = 0.0; t < 86400.0; t += 7919.0) {
      const StateEci st = s.motion->state_at(i, t);
      const Vec3 d4 = (-s.motion->state_at(i, t + 2 * h).r_eci_m + 8.0 * s.motion->state_at(i, t + h).r_eci_m -
                       8.0 * s.motion->state_at(i, t - h).r_eci_m + s.motion->state_at(i, t - 2 * h).r_eci_m) /
                      (12.0 * h);
      worst = std::max(worst, (st.v_eci_mps - d4).norm());
      // The bound the screener widens its tests by (plus the check's own 2e-5 m/s).
      EXPECT_LE((st.v_eci_mps - d4).norm(), s.motion->velocity_error_mps(i) + 2e-5);
    }
  }
  EXPECT_LT(worst, 2e-4);
}

// The envelope (factor 2 over 64 samples per orbit) holds at 2 s sampling of every object
// over 2 h
// (same five-point difference; the rate from differences 60 s apart, where the position's
// jumps add < 3e-8 m/s^3).
TEST(Sgp4Screening, PerturbationEnvelopeHoldsOnFineSampling) {
  Sgp4MotionOptions mo;
  mo.span_s = 7200.0;
  Sgp4TestCatalogOptions co = small_catalog(5);
  co.background = 20;  // with the 12 pair objects: 32 objects (time under ASan)
  const Sgp4Screening s = sgp4_screening(sgp4_test_catalog(co), mo);
  const EarthModel e = wgs72_earth();
  double worst_ratio = 0.0, worst_rate_ratio = 0.0;
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const PerturbationBound b = s.motion->perturbation(i);
    std::vector<Vec3> ps;
    for (double t = 0.0; t <= mo.span_s; t += 2.0) {
      auto r = [&](double dt) { return s.motion->state_at(i, t + dt).r_eci_m; };
      const Vec3 acc = (-r(-10.0) + 16.0 * r(-5.0) - 30.0 * r(0.0) + 16.0 * r(5.0) - r(10.0)) / 300.0;
      const Vec3 p = acc - accel_eci_mps2(r(0.0), GravityModel::kTwoBodyJ2, e);
      worst_ratio = std::max(worst_ratio, p.norm() / b.accel_mps2);
      ps.push_back(p);
      if (ps.size() > 30)
        worst_rate_ratio = std::max(worst_rate_ratio, (p - ps[ps.size() - 31]).norm() / 60.0 / b.rate_mps3);
    }
  }
  std::printf("largest |p| / bound %.3f, largest |p'| / bound %.3f\n", worst_ratio, worst_rate_ratio);
  EXPECT_LT(worst_ratio, 0.75);
  EXPECT_LT(worst_rate_ratio, 0.75);
}

TEST(Sgp4Screening, PrimaryGivesExactlyThePrimarysEventsOfTheFullScreening) {
  Sgp4MotionOptions mo;
  mo.span_s = 21600.0;
  const Sgp4Screening s = sgp4_screening(sgp4_test_catalog(small_catalog(6)), mo);
  ScreenOptions opt = sgp4_options(s);
  const ScreenResult all = screen_robust(s.objects, mo.span_s, opt);
  long primary = -1;
  for (std::size_t k = 0; k < s.objects.size() && primary < 0; ++k)
    if (s.objects[k].name.find("co0a") != std::string::npos) primary = static_cast<long>(k);
  ASSERT_GE(primary, 0);
  opt.primary = primary;
  const ScreenResult one = screen_robust(s.objects, mo.span_s, opt);
  std::size_t expected = 0;
  for (const auto& e : all.events) {
    if (static_cast<long>(e.i) != primary && static_cast<long>(e.j) != primary) continue;
    ++expected;
    bool found = false;
    for (const auto& f : one.events) found |= f.i == e.i && f.j == e.j && f.tca_s == e.tca_s && f.miss_m == e.miss_m;
    EXPECT_TRUE(found) << e.i << "-" << e.j << " at " << e.tca_s;
  }
  EXPECT_EQ(one.events.size(), expected);
  EXPECT_GE(expected, 3u) << "the co-orbital partner should pass within 5 km several times in 6 h";
  opt.primary = static_cast<long>(s.objects.size());
  EXPECT_THROW(screen_robust(s.objects, mo.span_s, opt), std::invalid_argument);
}

// The grid states come four at a time: from the lane groups prepared per 64-object window when
// a call covers whole windows (the step runner's chunks), else grouped on the spot. Lanes do
// not mix, so every object's state is the same bits either way; and each is within the stated
// grid position error of the scalar SGP4 state. The shipped catalog: 925 near-Earth and 275
// deep-space objects, mixed in each window.
TEST(Sgp4Screening, GridStatesAreTheSameBitsHoweverTheObjectsAreSplit) {
  std::ifstream in(EVADE_SYNTHETIC_CATALOG);
  std::ostringstream os;
  os << in.rdbuf();
  const sgp4::Catalog cat = sgp4::read_tle(os.str(), "synthetic-1200.tle");
  Sgp4MotionOptions mo;
  mo.span_s = 86400.0;
  mo.envelopes = false;  // the grid states only
  const Sgp4Screening s = sgp4_screening(cat.objects, mo);
  const std::size_t n = s.objects.size();
  ASSERT_GT(n, 1000u);
  const std::vector<std::vector<std::size_t>> splits = {
      {0, n}, {0, 64, 128, n}, {0, 5, 70, 133, 200, n - 3, n}, {0, 1, 2, 3, 64, 65, 67, n}};
  for (const double t : {0.0, 5400.0, 43210.5, 86400.0}) {
    std::vector<std::vector<StateEci>> out(splits.size(), std::vector<StateEci>(n));
    for (std::size_t k = 0; k < splits.size(); ++k)
      for (std::size_t r = 0; r + 1 < splits[k].size(); ++r)
        s.motion->grid_states_at(t, splits[k][r], splits[k][r + 1], out[k].data());
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 1; k < splits.size(); ++k) {
        ASSERT_EQ(out[k][i].r_eci_m, out[0][i].r_eci_m) << "object " << i << " split " << k << " t " << t;
        ASSERT_EQ(out[k][i].v_eci_mps, out[0][i].v_eci_mps) << "object " << i << " split " << k << " t " << t;
      }
      const StateEci exact = s.motion->grid_state_at(i, t);
      EXPECT_LE((out[0][i].r_eci_m - exact.r_eci_m).norm(), s.motion->grid_position_error_m(i))
          << "object " << i << " t " << t;
    }
  }
}

TEST(Sgp4Screening, MotionNeedsItsReferenceEarthModel) {
  const Sgp4Screening s = sgp4_screening(sgp4_test_catalog(small_catalog(7)), Sgp4MotionOptions{});
  ScreenOptions opt = sgp4_options(s);
  opt.earth = EarthModel{};  // WGS-84, not the motion's WGS-72
  EXPECT_THROW(opt.validate(), std::invalid_argument);
  opt = sgp4_options(s);
  opt.gravity = GravityModel::kTwoBody;
  EXPECT_THROW(opt.validate(), std::invalid_argument);
}

TEST(Sgp4Screening, AutomaticGridStepUsesTheGridStatesCalibration) {
  // h = h_10k (10 000 / N)^(1/3), clamped to [10, 120] s; SGP4 motion has grid states.
  const Sgp4Screening s = sgp4_screening(sgp4_test_catalog(small_catalog(7)), Sgp4MotionOptions{});
  const ScreenOptions sgp4 = sgp4_options(s);
  const ScreenOptions force_model;
  EXPECT_DOUBLE_EQ(auto_step_s(10000, sgp4), kAutoStepGridStates_s);
  EXPECT_DOUBLE_EQ(auto_step_s(10000, force_model), kAutoStepForceModels_s);
  EXPECT_NEAR(auto_step_s(30000, sgp4), kAutoStepGridStates_s / std::cbrt(3.0), 1e-9);
  EXPECT_DOUBLE_EQ(auto_step_s(500, sgp4), 120.0);
  EXPECT_DOUBLE_EQ(auto_step_s(100000000, force_model), 10.0);
}

}  // namespace
}  // namespace evade::conjunction
