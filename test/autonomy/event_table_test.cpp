// The tracked conjunctions (docs/AUTONOMY.md AUT-1): at least 4 at once (8 slots), a newer
// version replaces the older one and says which it was, the same or an older version is
// refused, a full table of live events refuses a new one and takes it once one is over.
#include <gtest/gtest.h>

#include <cstdint>

#include "evade/autonomy/event_table.hpp"

namespace evade::autonomy {
namespace {

ConjunctionEvent event(std::int64_t id, std::int32_t version, std::int64_t tca_us) {
  ConjunctionEvent e;
  e.event_id = id;
  e.version = version;
  e.tca_us = tca_us;
  return e;
}

TEST(EventTable, TracksEightEventsAndRefusesANinthWhileTheyAreLive) {
  EventTable t;
  for (std::int64_t id = 1; id <= 8; ++id) {
    EXPECT_EQ(t.insert(event(id, 1, 1000 + id), 0), InsertResult::kNew);
  }
  EXPECT_EQ(t.size(), 8U);
  EXPECT_EQ(t.insert(event(9, 1, 5000), 0), InsertResult::kTableFull);
  std::size_t slot = kMaxEvents;
  EXPECT_EQ(t.insert(event(9, 1, 5000), 1002, &slot), InsertResult::kNew) << "event 1 is over";
  EXPECT_EQ(t.slot(slot).event.event_id, 9);
  EXPECT_EQ(t.find(1), kMaxEvents);
  EXPECT_EQ(t.expire(1005), 3U);  // TCAs 1002, 1003 and 1004 are before 1005
  EXPECT_EQ(t.size(), 5U);
}

TEST(EventTable, ANewerVersionSupersedesAndTheSameOrOlderIsRefused) {
  EventTable t;
  std::size_t s1 = kMaxEvents, s2 = kMaxEvents;
  ASSERT_EQ(t.insert(event(7, 2, 100), 0, &s1), InsertResult::kNew);
  EXPECT_EQ(t.insert(event(7, 2, 100), 0), InsertResult::kSameVersion) << "a retransmission";
  EXPECT_EQ(t.insert(event(7, 2, 101), 0), InsertResult::kNotNewer) << "the same version altered";
  EXPECT_EQ(t.insert(event(7, 1, 100), 0), InsertResult::kNotNewer);
  ASSERT_EQ(t.insert(event(7, 5, 90), 0, &s2), InsertResult::kNewVersion);
  EXPECT_EQ(s1, s2);
  EXPECT_EQ(t.slot(s2).event.version, 5);
  EXPECT_EQ(t.slot(s2).superseded_version, 2);
  EXPECT_EQ(t.slot(s2).event.tca_us, 90);
  EXPECT_EQ(t.size(), 1U);
}

}  // namespace
}  // namespace evade::autonomy
