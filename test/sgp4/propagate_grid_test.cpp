// SGP4 of N objects x T instants into caller arrays (propagate_grid.hpp), the call under the
// Python evade.sgp4.propagate: errors per instant, instants in any order, threads that do
// not change a byte, the four-lane states within their stated bound of the scalar theory's
// (kSgp4X4PositionErrorRel |r| near Earth, kSgp4X4DeepPositionErrorRel |r| in deep space,
// velocities within the 1e-6 m/s sgp4_x4_test.cpp checks) with the scalar theory's error
// codes, positions without velocities, and the checks of its inputs. Against `evade
// propagate` on the SGP4-VER set of Vallado et al. 2006:
// test/commands/propagate_catalog_command_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/sgp4/propagate_grid.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::sgp4 {
namespace {

std::string read_file(const char* path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The element lines of SGP4-VER.TLE (its lines carry the test's start, stop and step after
// column 69). Checked non-empty, so that no test below passes on an empty catalog.
Catalog sgp4_ver() {
  std::ifstream in(EVADE_TEST_SGP4_VER_TLE);
  std::string line, text;
  while (std::getline(in, line))
    if (line.size() >= 69 && (line[0] == '1' || line[0] == '2')) text += line.substr(0, 69) + "\n";
  Catalog c = read_tle(text, "SGP4-VER.TLE");
  if (c.objects.size() < 30) throw std::runtime_error("SGP4-VER.TLE: too few element sets read");
  return c;
}

struct Grid {
  std::vector<double> r, v;
  std::vector<std::int32_t> err;
};

Grid run_grid(const Catalog& c, double start_j2000_s, const std::vector<double>& t_s, bool j2000,
              int threads, bool velocities = true) {
  Grid g;
  const std::size_t states = c.objects.size() * t_s.size();
  g.r.resize(3 * states);
  g.v.resize(3 * states);
  g.err.resize(states);
  StateGridRequest req;
  req.start_j2000_s = start_j2000_s;
  req.t_s = t_s.data();
  req.n_times = t_s.size();
  req.j2000 = j2000;
  req.threads = threads;
  propagate_grid(c, req, {g.r.data(), velocities ? g.v.data() : nullptr, g.err.data()});
  return g;
}

// The four-lane path's bound on a position of p (sgp4.hpp), and on a velocity.
double lane_bound_m(const Sgp4Propagator& p, const Eigen::Vector3d& r_m) {
  return (p.deep_space() ? kSgp4X4DeepPositionErrorRel : kSgp4X4PositionErrorRel) * r_m.norm();
}
constexpr double kLaneVelocityBound_mps = 1e-6;  // the check of sgp4_x4_test.cpp

Eigen::Vector3d at(const std::vector<double>& a, std::size_t s) {
  return Eigen::Vector3d(a[3 * s], a[3 * s + 1], a[3 * s + 2]);
}

// Every state of g against the scalar theory at that (object, instant): the same error code,
// NaN where it has no state, else within the lane bound (rotated to J2000 when asked).
// Returns the number of states compared.
long expect_scalar_theory(const Catalog& c, double start, const std::vector<double>& t, bool j2000,
                          const Grid& g) {
  long compared = 0;
  for (std::size_t i = 0; i < c.objects.size(); ++i) {
    const Sgp4Propagator p(c.objects[i], OperationMode::kImproved);
    const double offset_s = start - epoch_seconds_since_j2000(c.objects[i]);
    for (std::size_t k = 0; k < t.size(); ++k) {
      const std::size_t s = i * t.size() + k;
      const Sgp4State ref = p.init_error() != Sgp4Error::kNone ? Sgp4State{p.init_error(), {}, {}}
                                                               : p.propagate_s(offset_s + t[k]);
      EXPECT_EQ(g.err[s], static_cast<std::int32_t>(ref.error)) << c.objects[i].norad_id << " at " << t[k];
      const bool nan = ref.error != Sgp4Error::kNone && ref.error != Sgp4Error::kDecayed;
      EXPECT_EQ(std::isnan(g.r[3 * s]), nan);
      if (nan) continue;
      Eigen::Vector3d r = ref.r_teme_m, v = ref.v_teme_mps;
      if (j2000) teme_to_j2000(start + t[k], ref.r_teme_m, ref.v_teme_mps, r, v);
      EXPECT_LE((at(g.r, s) - r).norm(), lane_bound_m(p, r)) << c.objects[i].norad_id << " at " << t[k];
      if (!g.v.empty()) {
        EXPECT_LE((at(g.v, s) - v).norm(), kLaneVelocityBound_mps);
      }
      ++compared;
    }
  }
  return compared;
}

std::vector<double> hourly(int hours) {
  std::vector<double> t;
  for (int k = 0; k <= hours; ++k) t.push_back(3600.0 * k);
  return t;
}

// Each (object, instant) on its own: reversed instants give the reversed grid bit for bit,
// and every error code, NaN or state is the propagator's at that instant alone.
TEST(PropagateGrid, InstantsInAnyOrderAndErrorsPerInstant) {
  const Catalog c = sgp4_ver();
  const double start = latest_epoch_seconds_since_j2000(c.objects);
  std::vector<double> t = hourly(48), back(t.rbegin(), t.rend());
  const Grid g = run_grid(c, start, t, false, 1), b = run_grid(c, start, back, false, 1);
  const std::size_t n_t = t.size();
  for (std::size_t i = 0; i < c.objects.size(); ++i) {
    for (std::size_t k = 0; k < n_t; ++k) {
      const std::size_t s = i * n_t + k, sb = i * n_t + (n_t - 1 - k);
      EXPECT_EQ(g.err[s], b.err[sb]);
      for (int j = 0; j < 3; ++j)
        if (!std::isnan(g.r[3 * s + j])) {
          EXPECT_EQ(g.r[3 * s + j], b.r[3 * sb + j]);
        }
    }
  }
  EXPECT_GT(expect_scalar_theory(c, start, t, false, g), 1000);
}

// The shipped 1,200-object catalog (near-Earth and deep-space lanes, groups of fewer than four
// at block ends) over a week in both frames: the scalar theory's codes and states within the
// lane bound; positions without velocities are the same positions.
TEST(PropagateGrid, ShippedCatalogWithinTheLaneBoundOfTheScalarTheory) {
  const Catalog c = read_tle(read_file(EVADE_TEST_SHIPPED_CATALOG), "synthetic-1200.tle");
  ASSERT_GT(c.objects.size(), 1000u);
  const double start = latest_epoch_seconds_since_j2000(c.objects);
  std::vector<double> t;
  for (int k = 0; k <= 300; ++k) t.push_back(2017.0 * k - 3600.0);  // a week, not on a grid step
  for (const bool j2000 : {false, true}) {
    const Grid g = run_grid(c, start, t, j2000, 2);
    EXPECT_GT(expect_scalar_theory(c, start, t, j2000, g), 300000) << "j2000 " << j2000;
    const Grid r_only = run_grid(c, start, t, j2000, 2, false);
    EXPECT_EQ(0, std::memcmp(r_only.r.data(), g.r.data(), g.r.size() * sizeof(double)));
    EXPECT_EQ(r_only.err, g.err);
  }
}

TEST(PropagateGrid, ThreadsDoNotChangeAByte) {
  const Catalog c = sgp4_ver();
  const double start = latest_epoch_seconds_since_j2000(c.objects);
  const std::vector<double> t = hourly(12);
  const Grid one = run_grid(c, start, t, true, 1), three = run_grid(c, start, t, true, 3);
  EXPECT_EQ(0, std::memcmp(one.r.data(), three.r.data(), one.r.size() * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(one.v.data(), three.v.data(), one.v.size() * sizeof(double)));
  EXPECT_EQ(one.err, three.err);
}

TEST(PropagateGrid, StartFromIsoUtcText) {
  const Catalog c = sgp4_ver();
  EXPECT_EQ(start_j2000_s_from_utc("", c), latest_epoch_seconds_since_j2000(c.objects));
  EXPECT_EQ(start_j2000_s_from_utc("2000-01-01T12:00:00Z", c), 0.0);
  EXPECT_EQ(start_j2000_s_from_utc("2000-01-01 12:00:01.5", c), 1.5);
  EXPECT_THROW((void)start_j2000_s_from_utc("yesterday", c), std::invalid_argument);
  EXPECT_THROW((void)start_j2000_s_from_utc("2000-13-01T00:00:00Z", c), std::invalid_argument);
}

TEST(PropagateGrid, BadInputsNamed) {
  const Catalog c = sgp4_ver();
  const std::vector<double> t = {0.0, std::nan(""), 60.0};
  StateGridRequest req;
  req.t_s = t.data();
  req.n_times = t.size();
  try {
    check_state_grid_request(c, req);
    FAIL() << "NaN instant accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("t_s[1]"), std::string::npos) << e.what();
  }
  req.n_times = 1;
  req.threads = -1;
  EXPECT_THROW(check_state_grid_request(c, req), std::invalid_argument);
  req.threads = 0;
  req.start_j2000_s = INFINITY;
  EXPECT_THROW(check_state_grid_request(c, req), std::invalid_argument);
  EXPECT_THROW((void)frame_is_j2000("gcrf"), std::invalid_argument);
  const Catalog none = read_tle("1 00005U garbage\n", "bad.tle");
  try {
    check_state_grid_request(none, req);
    FAIL() << "empty catalog accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "no valid element set in the file (1 bad entries)");
  }
  EXPECT_FALSE(frame_is_j2000("teme"));
  EXPECT_TRUE(frame_is_j2000("eci"));
}

}  // namespace
}  // namespace evade::sgp4
