// The bounded input queue drops the oldest message when full (docs/GUIDANCE_NODE.md NODE-IN-3).
#include <gtest/gtest.h>

#include <cstdint>

#include "evade/guidance_lcm/internal/input_queue.hpp"

namespace evade::guidance_lcm {
namespace {

TEST(InputQueue, DropsOldestWhenFull) {
  InputQueue q(3);
  for (std::uint8_t i = 0; i < 5; ++i) {
    const bool kept = q.push(Input::kAngles, 0, 0, &i, 1);
    EXPECT_EQ(kept, i < 3);
  }
  ASSERT_EQ(q.size(), 3u);
  for (std::uint8_t want = 2; want < 5; ++want) {
    EXPECT_EQ(q.front().data[0], want);
    q.pop();
  }
  EXPECT_TRUE(q.empty());
}

}  // namespace
}  // namespace evade::guidance_lcm
