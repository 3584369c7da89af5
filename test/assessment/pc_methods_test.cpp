// The Pc methods' table (pc_methods.hpp): one row per method with names of its own, every
// plane method computed by plane_pc_values in table order, an escalation that ends with a
// step without checks (the last resort), and a CCSDS code for every method the escalation
// can recommend.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "evade/assessment/pc_2d.hpp"
#include "evade/assessment/pc_methods.hpp"

namespace evade::assessment {
namespace {

TEST(PcMethods, EveryRowHasNamesOfItsOwnAndIsFoundByThem) {
  std::set<std::string> names, labels;
  for (const PcMethodRow& r : pc_methods()) {
    EXPECT_TRUE(names.insert(r.name).second) << r.name;
    EXPECT_TRUE(labels.insert(r.label).second) << r.label;
    EXPECT_EQ(&pc_method(r.id), &r);
    EXPECT_EQ(pc_method_named(r.name), &r);
    EXPECT_TRUE(r.from_plane != nullptr || r.escalate != nullptr) << r.name << " is never computed";
  }
  EXPECT_EQ(pc_method_named("patera"), nullptr);
}

TEST(PcMethods, TheEscalationEndsWithALastResortAndEveryStepHasACcsdsCode) {
  const PcMethodRow* last = nullptr;
  for (const PcMethodRow& r : pc_methods()) {
    if (r.escalate == nullptr) continue;
    EXPECT_NE(r.cdm_code, nullptr) << r.name << " can be recommended but has no CDM code";
    last = &r;
  }
  ASSERT_NE(last, nullptr);
  EXPECT_EQ(last->check_noun, nullptr) << "the last step must be accepted without checks";
  EXPECT_FALSE(last->needs_six_by_six) << "the last resort must run on every input";
  EXPECT_EQ(std::string(pc_methods().front().name), "2d") << "the escalation starts with 2D";
}

TEST(PcMethods, PlaneValuesAreThePlaneMethodsInTableOrderWithTheirFigures) {
  const PrincipalEncounter pe{10.0, 0.0, 25.0, 50.0};  // Chan 2008 case 1 geometry
  const std::vector<PcValue> v = plane_pc_values(pe, 5.0, 1e-8);
  const std::vector<PcValue> u = undefined_plane_pc_values();
  std::size_t k = 0;
  for (const PcMethodRow& r : pc_methods()) {
    if (r.from_plane == nullptr) continue;
    ASSERT_LT(k, v.size());
    EXPECT_EQ(v[k].method, r.id);
    EXPECT_EQ(u[k].method, r.id);
    EXPECT_TRUE(std::isnan(u[k].pc));
    std::size_t figures = 0;
    for (const char* f : r.figures) figures += f != nullptr ? 1 : 0;
    EXPECT_EQ(v[k].figures.size(), figures) << r.name;
    EXPECT_EQ(u[k].figures.size(), figures) << r.name;
    ++k;
  }
  EXPECT_EQ(k, v.size());
  EXPECT_EQ(pc_of(v, PcMethod::k2d), pc_2d(pe, 5.0, 1e-8).pc);
  EXPECT_EQ(pc_of(v, PcMethod::kChan), pc_chan(pe, 5.0));
  EXPECT_TRUE(std::isnan(pc_of(v, PcMethod::kMc))) << "not a plane method";
}

}  // namespace
}  // namespace evade::assessment
