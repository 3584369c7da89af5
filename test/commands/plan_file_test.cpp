// The burn-plan file (sim/plan_file.hpp): written and read back bit-exact, and every bad
// field refused at the edge with its name (unknown keys, NaN/Inf, wrong frame, unordered
// times, ECI frame without ECI Δv, impulse count, format, plan id, not JSON).
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "evade/commands/plan_file.hpp"

namespace evade::commands {
namespace {

PlanFile two_burns() {
  PlanFile f;
  f.plan.plan_id = 12;
  f.plan.source = static_cast<int>(PlanSource::kFormation);
  f.plan.n_impulses = 2;
  f.plan.impulses[0].t_s = 43200.0;
  f.plan.impulses[0].dv_rsw_mps = Vec3(6.185096601363325e-07, 0.005807829668618343, -2e-19);
  f.plan.impulses[0].dv_eci_valid = true;
  f.plan.impulses[0].dv_eci_mps = Vec3(-0.0020016051686138456, 0.004852642205381031, 1.0 / 3.0);
  f.plan.impulses[1].t_s = 151200.1;
  f.plan.impulses[1].dv_rsw_mps = Vec3(3.68e-06, -0.00580302819471926, 0.1);
  f.frame = guidance::PlanFrame::kRsw;
  return f;
}

// The reference text with one substitution applied (from -> to, which must occur).
std::string edited(const std::string& from, const std::string& to) {
  std::string t = plan_file_json(two_burns());
  const std::size_t at = t.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) t.replace(at, from.size(), to);
  return t;
}

void expect_refused(const std::string& text, const std::string& field) {
  try {
    (void)parse_plan_file(text, "p.json");
    ADD_FAILURE() << "accepted, expected an error naming " << field << ":\n" << text;
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("plan file 'p.json': "), std::string::npos) << what;
    EXPECT_NE(what.find(field), std::string::npos) << what;
  }
}

TEST(PlanFile, WrittenAndReadBackBitExact) {
  const PlanFile f = two_burns();
  const std::string path = ::testing::TempDir() + "plan_file_test.json";
  write_plan_file(path, f);
  const PlanFile g = read_plan_file(path);
  std::remove(path.c_str());
  EXPECT_EQ(g.plan.plan_id, 12);
  EXPECT_EQ(g.plan.source, static_cast<int>(PlanSource::kFormation));
  EXPECT_EQ(g.frame, guidance::PlanFrame::kRsw);
  ASSERT_EQ(g.plan.n_impulses, 2);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(g.plan.impulses[i].t_s, f.plan.impulses[i].t_s);
    EXPECT_EQ(g.plan.impulses[i].dv_rsw_mps, f.plan.impulses[i].dv_rsw_mps);
    EXPECT_EQ(g.plan.impulses[i].dv_eci_valid, f.plan.impulses[i].dv_eci_valid);
    EXPECT_EQ(g.plan.impulses[i].dv_eci_mps, f.plan.impulses[i].dv_eci_mps);
  }
  EXPECT_FALSE(g.plan.observability.valid);
}

TEST(PlanFile, EveryPlannerSourceRoundTrips) {
  for (const PlanSource src : {PlanSource::kUnknown, PlanSource::kThreatArea, PlanSource::kFormation,
                               PlanSource::kObservability, PlanSource::kCollisionAvoidance}) {
    PlanFile f = two_burns();
    f.plan.source = static_cast<int>(src);
    EXPECT_EQ(parse_plan_file(plan_file_json(f), "p.json").plan.source, static_cast<int>(src));
  }
}

TEST(PlanFile, EachBadFieldIsRefusedNamingIt) {
  expect_refused(edited("\"plan_id\"", "\"plan_ident\""), "plan_ident is not a known key");
  expect_refused(edited("\"t_s\": 43200.0", "\"t_s\": 43200.0, \"dt_s\": 1"),
                 "impulses[0].dt_s is not a known key");
  expect_refused(edited("\"t_s\": 43200.0", "\"t_s\": \"nan\""), "impulses[0].t_s");
  expect_refused(edited("\"t_s\": 43200.0", "\"t_s\": 1e999"), "not valid JSON");
  expect_refused(edited("\"t_s\": 43200.0", "\"t_s\": 2e9"), "impulses[0].t_s");
  expect_refused(edited("-0.00580302819471926", "null"), "impulses[1].dv_rsw_mps[1]");
  expect_refused(edited("\"frame\": \"rsw\"", "\"frame\": \"ned\""), "frame = \"ned\"");
  expect_refused(edited("\"frame\": \"rsw\"", "\"frame\": \"eci\""), "impulses[1].dv_eci_mps is missing");
  expect_refused(edited("\"t_s\": 151200.1", "\"t_s\": 43200.0"),
                 "impulses[1].t_s = 43200.000000: impulse times must be strictly increasing");
  expect_refused(edited("evade.burn_plan.v1", "evade.burn_plan.v2"), "format");
  expect_refused(edited("\"plan_id\": 12", "\"plan_id\": -1"), "plan_id");
  expect_refused(edited("\"source\": \"formation\"", "\"source\": \"magic\""), "source");
  expect_refused(edited("],\n      \"t_s\": 43200.0", "]"), "impulses[0].t_s is missing");
  expect_refused("{\"format\": \"evade.burn_plan.v1\", \"plan_id\": 1, \"source\": \"unknown\", "
                 "\"frame\": \"rsw\", \"impulses\": []}",
                 "impulses must be a list of 1..8");
  expect_refused("[1, 2", "not valid JSON");
}

TEST(PlanFile, AFileThatCannotBeOpenedIsNamed) {
  try {
    (void)read_plan_file("/nonexistent/dir/plan.json");
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'/nonexistent/dir/plan.json': cannot be opened"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace evade::commands
