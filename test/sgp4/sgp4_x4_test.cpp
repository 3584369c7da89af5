// propagate_near_x4 (four near-Earth element sets at once, sgp4_x4.cpp) against
// propagate_min: the same lanes fail, and every position is within kSgp4X4PositionErrorRel
// |r| with a factor of 10 to spare (and kSgp4X4PositionError_m with 100): docs/VALIDATION.md
// states the bounds the screening adds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/sgp4.hpp"

namespace evade::sgp4 {
namespace {

std::vector<Sgp4Propagator> near_earth_propagators() {
  std::ifstream in(EVADE_TEST_SHIPPED_CATALOG);
  std::ostringstream os;
  os << in.rdbuf();
  std::vector<Sgp4Propagator> out;
  for (const MeanElements& m : read_catalog(os.str(), "synthetic-1200.tle").objects) {
    Sgp4Propagator p(m);
    if (!p.deep_space() && p.init_error() == Sgp4Error::kNone) out.push_back(p);
  }
  return out;
}

struct Worst {
  double dr_m = 0.0, dv_mps = 0.0, dr_rel = 0.0;  // dr_rel: |dr| / |r|
  long lanes = 0, failed = 0;
};

// Every group of four consecutive propagators at the times ts (lane k at ts + k * 7.3 min, so
// the lanes are at different instants too).
Worst compare(const std::vector<Sgp4Propagator>& props, const std::vector<double>& ts) {
  Worst w;
  for (std::size_t g = 0; g + 4 <= props.size(); g += 4) {
    const Sgp4Propagator* p[4] = {&props[g], &props[g + 1], &props[g + 2], &props[g + 3]};
    for (const double t : ts) {
      const double tk[4] = {t, t + 7.3, t + 14.6, t + 21.9};
      double r[4][3], v[4][3];
      bool ok[4];
      propagate_near_x4(p, tk, r, v, ok);
      for (int k = 0; k < 4; ++k) {
        const Sgp4State s = p[k]->propagate_min(tk[k]);
        ++w.lanes;
        EXPECT_EQ(ok[k], s.error == Sgp4Error::kNone) << "lane " << g + static_cast<std::size_t>(k) << " at " << tk[k];
        if (!ok[k]) {
          ++w.failed;
          continue;
        }
        const Eigen::Vector3d rx(r[k][0], r[k][1], r[k][2]), vx(v[k][0], v[k][1], v[k][2]);
        w.dr_m = std::max(w.dr_m, (rx - s.r_teme_m).norm());
        w.dr_rel = std::max(w.dr_rel, (rx - s.r_teme_m).norm() / s.r_teme_m.norm());
        w.dv_mps = std::max(w.dv_mps, (vx - s.v_teme_mps).norm());
      }
    }
  }
  return w;
}

TEST(Sgp4X4, PositionsWithinATenthOfTheStatedBoundOnTheShippedCatalogOverSevenDays) {
  const std::vector<Sgp4Propagator> props = near_earth_propagators();
  ASSERT_GT(props.size(), 400u);
  std::vector<double> ts;
  for (double t = -1440.0; t <= 7.0 * 1440.0; t += 97.7) ts.push_back(t);  // minutes
  const Worst w = compare(props, ts);
  std::printf("Sgp4X4: %s, %ld lanes (%ld failed in both), worst |dr| %.3e m (%.3e |r|), |dv| %.3e m/s\n",
              sgp4_x4_vectorized() ? "AVX2" : "scalar", w.lanes, w.failed, w.dr_m, w.dr_rel, w.dv_mps);
  EXPECT_LT(w.dr_rel, kSgp4X4PositionErrorRel / 10.0);
  EXPECT_LT(w.dr_m, kSgp4X4PositionError_m / 100.0);
  EXPECT_LT(w.dv_mps, 1e-6);  // velocity is not bounded by the screening; reported here
}

TEST(Sgp4X4, DecayedLanesAreFlaggedAsPropagateMinFlagsThem) {
  // A low, high-drag element set decays within days; its lane must say so at each instant
  // where propagate_min reports an error, beside three healthy lanes.
  MeanElements low;
  low.norad_id = 99001;
  low.mean_motion_revpday = 16.3;
  low.eccentricity = 0.001;
  low.inclination_deg = 51.6;
  low.bstar_per_er = 0.01;
  const std::vector<Sgp4Propagator> props = near_earth_propagators();
  ASSERT_GE(props.size(), 3u);
  const Sgp4Propagator decaying(low);
  const Sgp4Propagator* p[4] = {&props[0], &decaying, &props[1], &props[2]};
  long flagged = 0;
  for (double t = 0.0; t <= 20.0 * 1440.0; t += 60.0) {
    const double tk[4] = {t, t, t, t};
    double r[4][3], v[4][3];
    bool ok[4];
    propagate_near_x4(p, tk, r, v, ok);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(ok[k], p[k]->propagate_min(t).error == Sgp4Error::kNone) << "lane " << k << " t " << t;
    }
    flagged += ok[1] ? 0 : 1;
  }
  EXPECT_GT(flagged, 0);  // the element set did decay inside the 20 days
}

}  // namespace
}  // namespace evade::sgp4
