// Paper 000 (Yao & Wang 2012) Table 2: miss distance for detection 10/20/30 s before the
// collision and maximum acceleration 0.5/1/1.5/2 m/s², reproduced with the closed-loop
// simulator (truth two-body + J2, ideal sensor: noise-free angles + true rates, thrust along
// −e_θ with the zenith convention).
//
// Tolerance: Table 1 prints positions to 1 mm and velocities to 1 mm/s. A velocity rounding
// error δv ≤ 0.5 mm/s per axis shifts the relative position at the encounter by up to
// δv·t_go ≈ 0.5 mm/s × 30 s ≈ 15 mm, the position rounding by ≤ 0.9 mm; the unforced miss
// itself is 1.35 mm. So the printed inputs alone allow ±1 cm (README: "±1 cm honest
// tolerance"). The paper thrusts continuously; we run the guidance at 1000 Hz to approximate
// that (1 cm). At the flight rate of 50 Hz the zero-order hold lags the rotating −e_θ by up
// to one cycle and the filter gates some measurements in the last ~0.1 s while the LOS whips
// round; that costs up to +5 mm at 30 s / 2 m/s² (measured: 899.7942 m at 50 Hz, 899.7913 m
// at 200 Hz, 899.7907 m at 1000 Hz); the 50 Hz case keeps the brief's 2 cm bound.
#include <cstdio>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/commands/sim_scenario.hpp"
#include "evade/sim/simulator.hpp"

namespace {

struct Entry {
  double detect_s;
  double accel_mps2;
  double paper_miss_m;
};

// Paper 000, Table 2 (unit: m).
constexpr Entry kTable2[] = {
    {10, 0.5, 25.0026},  {20, 0.5, 99.9996},  {30, 0.5, 224.9762},
    {10, 1.0, 50.0021},  {20, 1.0, 199.9921}, {30, 1.0, 449.9392},
    {10, 1.5, 75.0013},  {20, 1.5, 299.9801}, {30, 1.5, 674.8798},
    {10, 2.0, 100.0001}, {20, 2.0, 399.9614}, {30, 2.0, 899.7888},
};

void run_table(double rate_hz, double tol_m) {
  const auto sc = evade::config::Scenario::load("seed0");
  evade::sim::SimConfig base = evade::commands::sim_config_from_scenario(sc);
  base.guidance.rate_hz = rate_hz;
  base.sensor.rate_hz = rate_hz;
  std::printf("guidance at %.0f Hz\n", rate_hz);
  std::printf("detect_s accel_mps2   paper_m       ours_m      diff_mm  dv_mps\n");
  for (const Entry& e : kTable2) {
    evade::sim::SimConfig c = base;
    c.encounter.detect_before_tca_s = e.detect_s;
    c.guidance.max_accel_mps2 = e.accel_mps2;
    auto ep = evade::sim::make_in_process_endpoint(c.guidance, true);
    const evade::sim::SimResult r = evade::sim::run_simulation(c, *ep);
    ASSERT_TRUE(r.closest_approach_found);
    std::printf("%8.0f %10.1f %10.4f %12.4f %10.2f %7.3f\n", e.detect_s, e.accel_mps2,
                e.paper_miss_m, r.miss_m, 1e3 * (r.miss_m - e.paper_miss_m), r.dv_mps);
    EXPECT_NEAR(r.miss_m, e.paper_miss_m, tol_m)
        << "detect " << e.detect_s << " s, accel " << e.accel_mps2 << " m/s^2";
    // Continuous thrust at the maximum acceleration from detection to the encounter (the
    // thrust ends at the actual closest approach, up to 1.6 ms before the nominal one).
    EXPECT_NEAR(r.dv_mps, e.accel_mps2 * e.detect_s, 0.002 * e.accel_mps2 + 1e-9);
  }
}

TEST(Paper000Table2, AllTwelveMissDistancesWithinOneCentimetreWithNearContinuousGuidance) {
  run_table(1000.0, 0.01);
}

TEST(Paper000Table2, AllTwelveMissDistancesWithinTwoCentimetresAtFlightRate50Hz) {
  run_table(50.0, 0.02);
}

TEST(Paper000Table2, UnforcedEncounterIsTenSecondsAheadWithMillimetreMiss) {
  const auto sc = evade::config::Scenario::load("seed0");
  const evade::sim::SimConfig c = evade::commands::sim_config_from_scenario(sc);
  const evade::sim::Encounter e = evade::sim::find_nominal_encounter(c);
  ASSERT_TRUE(e.found);
  std::printf("nominal tca = %.6f s, miss = %.3f mm\n", e.tca_s, 1e3 * e.miss_m);
  EXPECT_NEAR(e.tca_s, 10.0, 1e-3);  // "collision in 10 s" (Table 1 digits: ms level)
  EXPECT_LT(e.miss_m, 0.01);         // "ZEM almost 0" (README: about 1.4 mm)
}

}  // namespace
