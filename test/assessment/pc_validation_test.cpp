// Collision probability against published reference values (docs/ASSESSMENT.md table).
// Source 1: Orekit's short-term encounter tests (CS GROUP, Apache-2.0): Laas2015Test
//   (accurate values, used for pc_2d) and Chan1997Test (Chan's series, used for pc_chan),
//   each with the absolute tolerance those tests state.
// Source 2: NASA CARA Analysis Tools, Pc2D_Foster_UnitTest (Omitron test case 01 with full
//   states and covariances; Alfano 2009 cases 3 and 5), relative tolerance 1e-3 as stated.
#include <gtest/gtest.h>

#include <cmath>

#include "evade/assessment/assess.hpp"
#include "evade/assessment/pc_2d.hpp"

namespace evade::assessment {
namespace {

struct Case {
  const char* name;
  double xm, ym, sx, sy, r;
  double expected, abs_tol;
};

// Orekit Laas2015Test: value and stated absolute tolerance.
const Case kOrekitLaas[] = {
    {"Chan01", 0, 10, 25, 50, 5, 9.742e-3, 1e-6},
    {"Chan02", 10, 0, 25, 50, 5, 9.181e-3, 1e-6},
    {"Chan03", 0, 10, 25, 75, 5, 6.571e-3, 1e-6},
    {"Chan04", 10, 0, 25, 75, 5, 6.125e-3, 1e-6},
    {"Chan05", 0, 1000, 1000, 3000, 10, 1.577e-5, 1e-8},
    {"Chan06", 1000, 0, 1000, 3000, 10, 1.011e-5, 1e-8},
    {"Chan07", 0, 10000, 1000, 3000, 10, 6.443e-8, 1e-11},
    {"Chan08", 10000, 0, 1000, 3000, 10, 3.219e-27, 1e-30},
    {"Chan09", 0, 10000, 1000, 10000, 10, 3.033e-6, 1e-9},
    {"Chan10", 10000, 0, 1000, 10000, 10, 9.656e-28, 1e-31},
    {"Chan11", 0, 5000, 1000, 3000, 50, 1.039e-4, 1e-7},
    {"Chan12", 5000, 0, 1000, 3000, 50, 1.564e-9, 1e-12},
    {"Csm1", 84.875546, 60.583685, 57.918666, 152.8814468, 10.3, 1.9002e-3, 1e-7},
    {"Csm2", -81.618369, 115.055899, 15.988242, 5756.840725, 1.3, 2.0553e-11, 1e-15},
    {"Csm3", 102.177247, 693.405893, 94.230921, 643.409272, 5.3, 7.2003e-5, 1e-9},
    {"Cdm1", -752.672701, 644.939441, 445.859950, 6095.858688, 3.5, 5.3904e-7, 1e-11},
    {"Cdm2", -692.362272, 4475.456261, 193.454603, 562.027293, 13.2, 2.2796e-20, 1e-24},
};

// Orekit Chan1997Test: Chan's series.
const Case kOrekitChan[] = {
    {"Chan01", 0, 10, 25, 50, 5, 9.754e-3, 1e-6},
    {"Chan02", 10, 0, 25, 50, 5, 9.189e-3, 1e-6},
    {"Chan03", 0, 10, 25, 75, 5, 6.586e-3, 1e-6},
    {"Chan04", 10, 0, 25, 75, 5, 6.135e-3, 1e-6},
    {"Chan05", 0, 1000, 1000, 3000, 10, 1.577e-5, 1e-8},
    {"Chan06", 1000, 0, 1000, 3000, 10, 1.011e-5, 1e-8},
    {"Chan07", 0, 10000, 1000, 3000, 10, 6.443e-8, 1e-11},
    {"Chan08", 10000, 0, 1000, 3000, 10, 3.216e-27, 1e-30},
    {"Chan11", 0, 5000, 1000, 3000, 50, 1.039e-4, 1e-7},
    {"Chan12", 5000, 0, 1000, 3000, 50, 1.556e-9, 1e-12},
};

TEST(PcValidation, OrekitLaas2015AccurateValues) {
  for (const Case& c : kOrekitLaas) {
    const Pc2dResult r = pc_2d({c.xm, c.ym, c.sx, c.sy}, c.r);
    EXPECT_NEAR(r.pc, c.expected, c.abs_tol) << c.name;
    EXPECT_LE(r.abs_error, 1e-8 * r.pc) << c.name;
  }
}

TEST(PcValidation, OrekitChan1997Series) {
  for (const Case& c : kOrekitChan) {
    EXPECT_NEAR(pc_chan({c.xm, c.ym, c.sx, c.sy}, c.r), c.expected, c.abs_tol) << c.name;
  }
}

// CARA Alfano 2009 cases 3 and 5 (encounter-plane inputs as tabulated in Orekit's tests),
// CARA's Pc2D_Foster values with its stated relative tolerance 1e-3.
TEST(PcValidation, CaraAlfanoCases3And5) {
  EXPECT_NEAR(pc_2d({-3.8872073, 0.1591646, 1.4101830, 114.2585190}, 15).pc, 1.00351176e-1,
              1e-3 * 1.00351176e-1);
  EXPECT_NEAR(pc_2d({-1.2217895, 2.1230067, 0.0373279, 177.8109003}, 10).pc, 4.44873860e-2,
              1e-3 * 4.44873860e-2);
}

// CARA Omitron test case 01: full states and ECI covariances (km, km^2 in the source; the
// Pc is scale-free so they are converted to m, m^2), HBR 20 m, expected 2.70601573490125e-05.
TEST(PcValidation, CaraOmitronCase01FromStates) {
  ConjunctionInput in;
  in.hbr_m = 20.0;
  in.obj[0].name = "object1";
  in.obj[0].state.r_eci_m = Vec3(378.39559, 4305.721887, 5752.767554) * 1e3;
  in.obj[0].state.v_eci_mps = Vec3(2.360800244, 5.580331936, -4.322349039) * 1e3;
  Mat3 c1;
  c1 << 44.5757544811362, 81.6751751052616, -67.8687662707124, 81.6751751052616,
      158.453402956163, -128.616921644857, -67.8687662707124, -128.616921644858,
      105.490542562701;
  in.obj[1].name = "object2";
  in.obj[1].state.r_eci_m = Vec3(374.5180598, 4307.560983, 5751.130418) * 1e3;
  in.obj[1].state.v_eci_mps = Vec3(-5.388125081, -3.946827739, 3.322820358) * 1e3;
  Mat3 c2;
  c2 << 2.31067077720423, 1.69905293875632, -1.4170164577661, 1.69905293875632,
      1.24957388457206, -1.04174164279599, -1.4170164577661, -1.04174164279599,
      0.869260558223714;
  in.obj[0].cov_eci.block<3, 3>(0, 0) = c1 * 1e6;
  in.obj[1].cov_eci.block<3, 3>(0, 0) = c2 * 1e6;
  AssessConfig cfg;
  cfg.tca_search_s = 0.0;  // CARA evaluates at the given states: no TCA shift
  const Assessment a = assess(in, cfg);
  const double expected = 2.70601573490125e-05;
  EXPECT_NEAR(pc_of(a.plane_pc, PcMethod::k2d), expected, 1e-3 * expected);
}

TEST(PcMax, MatchesSmallDiskLimitAndBoundsPc) {
  // Small disk: Pc_max -> R^2 / (e sx sy v), v = (xm/sx)^2 + (ym/sy)^2 (Alfano 2005).
  const PrincipalEncounter e{300.0, 400.0, 50.0, 200.0};
  const double r = 1.0;
  const PcMaxResult m = pc_max_alfano(e, r);
  const double v = std::pow(300.0 / 50.0, 2) + std::pow(400.0 / 200.0, 2);
  EXPECT_NEAR(m.pc_max, r * r / (std::exp(1.0) * 50.0 * 200.0 * v), 1e-3 * m.pc_max);
  EXPECT_NEAR(m.scale, std::sqrt(v / 2.0), 1e-3 * m.scale);
  EXPECT_GE(m.pc_max, pc_2d(e, r).pc);
}

TEST(PcInput, BadInputIsRejected) {
  EXPECT_THROW(pc_2d({0, 0, 0, 1}, 1), std::invalid_argument);
  EXPECT_THROW(pc_2d({0, 0, 1, 1}, -1), std::invalid_argument);
  EXPECT_THROW(pc_chan({NAN, 0, 1, 1}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace evade::assessment
