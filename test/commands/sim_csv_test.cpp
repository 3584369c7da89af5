// The CSV time history of `evade sim` (sim_csv.hpp): one value per header column, the true
// ZEM = R² λ̇ / (−Ṙ) of paper 000 eq. 7 and 12 while closing (NaN when opening), and rows of a
// real run that carry its truth.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/commands/sim_csv.hpp"
#include "evade/commands/sim_scenario.hpp"

namespace {

using namespace evade;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string f;
  while (std::getline(ss, f, ',')) out.push_back(f);
  return out;
}

sim::SimSample closing_sample() {
  sim::SimSample s;
  s.t_s = 1.25;
  s.satellite.r_eci_m = Vec3(7e6, 0.0, 0.0);
  s.satellite.v_eci_mps = Vec3(0.0, 7.5e3, 0.0);
  s.debris.r_eci_m = Vec3(7e6, 1000.0, 0.0);
  s.debris.v_eci_mps = Vec3(0.0, 7.4e3, 0.0);
  s.range_m = 1000.0;
  s.range_rate_mps = -100.0;
  s.los_rate_true_radps = 1e-3;
  s.status.los_rate_var_rad2ps2 = 4e-6;
  return s;
}

TEST(SimCsv, ZemIsRangeSquaredTimesLosRateOverClosingSpeed) {
  const sim::SimSample s = closing_sample();
  EXPECT_DOUBLE_EQ(commands::zem_true_m(s), 1000.0 * 1000.0 * 1e-3 / 100.0);
  sim::SimSample opening = s;
  opening.range_rate_mps = 100.0;
  EXPECT_TRUE(std::isnan(commands::zem_true_m(opening)));
}

TEST(SimCsv, RowHasOneValuePerHeaderColumn) {
  const std::vector<std::string> header = split(commands::sim_csv_header());
  EXPECT_EQ(header.size(), 39u);
  EXPECT_EQ(header.front(), "t_s");
  EXPECT_EQ(header[16], "zem_true_m");
  std::ostringstream os;
  commands::write_sim_csv_row(os, closing_sample());
  const std::string row = os.str();
  ASSERT_FALSE(row.empty());
  EXPECT_EQ(row.back(), '\n');
  const std::vector<std::string> f = split(row.substr(0, row.size() - 1));
  ASSERT_EQ(f.size(), header.size());
  EXPECT_EQ(std::stod(f[0]), 1.25);
  EXPECT_EQ(std::stod(f[11]), 1000.0);  // rel_y_m = debris − satellite
  EXPECT_DOUBLE_EQ(std::stod(f[16]), 10.0);
  EXPECT_DOUBLE_EQ(std::stod(f[24]), 2e-3);  // los_rate_est_sd_radps = sqrt(variance)
}

TEST(SimCsv, RowsOfARunCarryItsTruth) {
  sim::SimConfig c = commands::sim_config_from_scenario(config::Scenario::load("seed0"));
  c.guidance.max_accel_mps2 = 1.0;
  c.encounter.detect_before_tca_s = 2.0;
  auto ep = sim::make_in_process_endpoint(c.guidance, true);
  std::ostringstream os;
  std::vector<sim::SimSample> samples;
  const sim::SimResult r = sim::run_simulation(c, *ep, [&](const sim::SimSample& s) {
    samples.push_back(s);
    commands::write_sim_csv_row(os, s);
  });
  ASSERT_TRUE(r.closest_approach_found);
  ASSERT_EQ(static_cast<long>(samples.size()), r.cycles);
  std::istringstream is(os.str());
  std::string line;
  std::size_t n = 0;
  while (std::getline(is, line)) {
    const std::vector<std::string> f = split(line);
    ASSERT_EQ(f.size(), 39u);
    EXPECT_NEAR(std::stod(f[13]), samples[n].range_m, 1e-9 * samples[n].range_m);
    ++n;
  }
  EXPECT_EQ(n, samples.size());
}

}  // namespace
