// The node's udpm input URL gets its receive buffer unless the URL sets one (docs/GUIDANCE_NODE.md
// NODE-IN-6).
#include <gtest/gtest.h>

#include <string>

#include "evade/guidance_lcm/lcm_url.hpp"

namespace evade::guidance_lcm {
namespace {

// NODE-IN-6: a udpm:// input gets the node's receive buffer unless the URL sets one.
TEST(LcmUrl, UdpmGetsTheReceiveBufferOthersUnchanged) {
  EXPECT_EQ(lcm_url_with_recv_buf("", nullptr, 8388608),
            "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608");
  EXPECT_EQ(lcm_url_with_recv_buf("", "udpm://239.1.2.3:7000", 1024),
            "udpm://239.1.2.3:7000?recv_buf_size=1024");
  EXPECT_EQ(lcm_url_with_recv_buf("udpm://239.1.2.3:7000?recv_buf_size=5", nullptr, 1024),
            "udpm://239.1.2.3:7000?recv_buf_size=5");
  EXPECT_EQ(lcm_url_with_recv_buf("memq://", nullptr, 1024), "memq://");
  EXPECT_EQ(lcm_url_with_recv_buf("file:///x.log?speed=0", nullptr, 1024), "file:///x.log?speed=0");
}

}  // namespace
}  // namespace evade::guidance_lcm
