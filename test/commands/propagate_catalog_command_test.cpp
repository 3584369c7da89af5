// `evade propagate --tle/--omm` as a library call: Vallado et al. 2006 ("Revisiting
// Spacetrack Report #3") verification object 00005 at its epoch, the span/step/frame checks,
// the JSON keys the CLI prints, the text summary, and every state within the four-lane bound
// of the grid call's (sgp4::propagate_grid, which takes the four-lane path where the command
// takes the scalar theory) on the whole SGP4-VER set, with the same errors.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/commands/propagate_catalog_stream.hpp"
#include "evade/sgp4/propagate_grid.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::commands {

using sgp4::Sgp4Error;
using sgp4::Catalog;
using sgp4::read_tle;
namespace {

// Object 00005 of SGP4-VER.TLE (the verification set of Vallado et al. 2006).
const char* kTle =
    "1 00005U 58002B   00179.78495062  .00000023  00000-0  28098-4 0  4753\n"
    "2 00005  34.2682 348.7242 1859667 331.7664  19.3264 10.82419157413667\n";

PropagateCatalogRequest request(double span_s, double step_s, const std::string& frame) {
  PropagateCatalogRequest req;
  req.catalog = read_tle(kTle, "test.tle");
  req.span_s = span_s;
  req.step_s = step_s;
  req.frame = frame;
  return req;
}

TEST(PropagateCatalogCommand, Object00005AtEpochMatchesThePublishedState) {
  const PropagateCatalogResult r = run_propagate_catalog(request(720.0, 360.0, "teme"));
  ASSERT_EQ(r.objects.size(), 1u);
  const CatalogTrack& t = r.objects[0];
  EXPECT_EQ(t.id, 5);
  ASSERT_EQ(t.states.size(), 3u);
  EXPECT_EQ(t.states[2].t_s, 720.0);
  // tcppver.out of Vallado et al. 2006, t = 0: r = (7022.46529266, -1400.08296755,
  // 0.03995155) km, v = (1.893841015, 6.405893759, 4.534807250) km/s, TEME.
  EXPECT_NEAR(t.states[0].r_m.x(), 7022465.29266, 1e-2);
  EXPECT_NEAR(t.states[0].r_m.y(), -1400082.96755, 1e-2);
  EXPECT_NEAR(t.states[0].r_m.z(), 39.95155, 1e-2);
  EXPECT_NEAR(t.states[0].v_mps.x(), 1893.841015, 1e-5);
  EXPECT_NEAR(t.states[0].v_mps.y(), 6405.893759, 1e-5);
  EXPECT_NEAR(t.states[0].v_mps.z(), 4534.807250, 1e-5);
  EXPECT_EQ(t.error, Sgp4Error::kNone);
  const std::string text = to_text(stream_propagate_catalog(
      request(720.0, 360.0, "teme"), StateFormat::kNone, 1, [](const char*, std::size_t) {}));
  EXPECT_NE(text.find("1 objects (0 bad entries), frame TEME, from 2000-06-27 18:50:19"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(" UTC\n"), std::string::npos) << text;
  EXPECT_NE(text.find("3 states, at t = 720 s"), std::string::npos) << text;
}

TEST(PropagateCatalogCommand, J2000FrameRotatesTheSameStates) {
  const PropagateCatalogResult teme = run_propagate_catalog(request(0.0, 60.0, "teme"));
  const PropagateCatalogResult eci = run_propagate_catalog(request(0.0, 60.0, "eci"));
  EXPECT_TRUE(eci.j2000);
  const CatalogState& a = teme.objects[0].states[0];
  const CatalogState& b = eci.objects[0].states[0];
  EXPECT_NEAR(a.r_m.norm(), b.r_m.norm(), 1e-6);  // a rotation (precession and nutation)
  EXPECT_GT((a.r_m - b.r_m).norm(), 1.0);
}

TEST(PropagateCatalogCommand, JsonHasTheKeysTheCliPrints) {
  const nlohmann::json j = to_json(run_propagate_catalog(request(60.0, 60.0, "eci")));
  for (const char* key : {"start_utc", "frame", "bad_entries", "issues", "objects"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["frame"], "J2000");
  const nlohmann::json& obj = j["objects"][0];
  for (const char* key : {"id", "name", "epoch_utc", "states"}) EXPECT_TRUE(obj.contains(key)) << key;
  EXPECT_FALSE(obj.contains("sgp4_error"));
  const nlohmann::json& s = obj["states"][1];
  EXPECT_EQ(s["t_s"], 60.0);
  EXPECT_EQ(s["r_m"].size(), 3u);
  EXPECT_EQ(s["v_mps"].size(), 3u);
}

TEST(PropagateCatalogCommand, BadFlagsAndEmptyCatalogsAreRefused) {
  EXPECT_THROW(run_propagate_catalog(request(-1.0, 60.0, "teme")), std::invalid_argument);
  EXPECT_THROW(run_propagate_catalog(request(600.0, 0.0, "teme")), std::invalid_argument);
  EXPECT_THROW(run_propagate_catalog(request(1e6, 1.0, "teme")), std::invalid_argument);  // 1e6 steps
  try {
    run_propagate_catalog(request(60.0, 60.0, "gcrs"));
    ADD_FAILURE() << "accepted gcrs";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "--frame = 'gcrs' is invalid: expected teme or eci");
  }
  PropagateCatalogRequest empty = request(60.0, 60.0, "teme");
  empty.catalog = read_tle("1 00005U garbage\n2 00005 garbage\n", "bad.tle");
  try {
    run_propagate_catalog(empty);
    ADD_FAILURE() << "accepted an empty catalog";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no valid element set in the file (1 bad entries)"),
              std::string::npos)
        << e.what();
  }
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
              int threads) {
  Grid g;
  const std::size_t states = c.objects.size() * t_s.size();
  g.r.resize(3 * states);
  g.v.resize(3 * states);
  g.err.resize(states);
  sgp4::StateGridRequest req;
  req.start_j2000_s = start_j2000_s;
  req.t_s = t_s.data();
  req.n_times = t_s.size();
  req.j2000 = j2000;
  req.threads = threads;
  sgp4::propagate_grid(c, req, {g.r.data(), g.v.data(), g.err.data()});
  return g;
}

std::vector<double> hourly(int hours) {
  std::vector<double> t;
  for (int k = 0; k <= hours; ++k) t.push_back(3600.0 * k);
  return t;
}

// Every state `evade propagate` prints (up to a track's first SGP4 error) is the grid's within
// the four-lane bound (sgp4.hpp: kSgp4X4PositionErrorRel |r| near Earth,
// kSgp4X4DeepPositionErrorRel |r| in deep space; velocities within sgp4_x4_test.cpp's
// 1e-6 m/s), in both frames; at the instant the command stopped, the grid has the same error.
TEST(PropagateCatalogCommand, EqualsTheGridCallOnSgp4Ver) {
  for (const char* frame : {"teme", "eci"}) {
    PropagateCatalogRequest cmd;
    cmd.catalog = sgp4_ver();
    cmd.span_s = 86400.0;
    cmd.step_s = 3600.0;
    cmd.frame = frame;
    const PropagateCatalogResult r = run_propagate_catalog(cmd);
    const std::vector<double> t = hourly(24);
    const Grid g = run_grid(cmd.catalog, r.start_j2000_s, t, sgp4::frame_is_j2000(frame), 2);
    ASSERT_EQ(r.objects.size(), cmd.catalog.objects.size());
    std::vector<bool> deep;
    for (const sgp4::MeanElements& m : cmd.catalog.objects) deep.push_back(sgp4::Sgp4Propagator(m).deep_space());
    int errors = 0;
    for (std::size_t i = 0; i < r.objects.size(); ++i) {
      const CatalogTrack& tr = r.objects[i];
      for (std::size_t k = 0; k < tr.states.size(); ++k) {
        const std::size_t s = i * t.size() + k;
        const Eigen::Vector3d& r_m = tr.states[k].r_m;
        const double rel = deep[i] ? sgp4::kSgp4X4DeepPositionErrorRel : sgp4::kSgp4X4PositionErrorRel;
        ASSERT_LE((Eigen::Vector3d(g.r[3 * s], g.r[3 * s + 1], g.r[3 * s + 2]) - r_m).norm(), rel * r_m.norm())
            << tr.id << " k " << k;
        ASSERT_LE((Eigen::Vector3d(g.v[3 * s], g.v[3 * s + 1], g.v[3 * s + 2]) - tr.states[k].v_mps).norm(), 1e-6)
            << tr.id << " k " << k;
      }
      if (tr.error != Sgp4Error::kNone) {
        ++errors;
        EXPECT_EQ(g.err[i * t.size() + tr.states.size()], static_cast<std::int32_t>(tr.error)) << tr.id;
      }
    }
    EXPECT_GT(errors, 0) << "SGP4-VER holds element sets that fail: the error path is tested";
  }
}

}  // namespace
}  // namespace evade::commands
