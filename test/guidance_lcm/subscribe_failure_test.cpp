// The guidance node when LCM refuses a subscription, and the node's life cycle of
// subscriptions (docs/GUIDANCE_NODE.md NODE-IN-1). LCM refuses one when its provider cannot
// set up the channel (udpm: the multicast join fails), which no in-process provider can be
// made to do on demand, so this executable is linked with -Wl,--wrap=lcm_subscribe and
// --wrap=lcm_unsubscribe: the node's calls go through the wrappers below, which pass every
// call on to LCM and record it, and refuse the one channel a test names. The node must
// throw naming that channel and leave no subscription behind (LCM would otherwise call back
// into a node that does not exist); a node that constructs unsubscribes all on destruction.
#include <gtest/gtest.h>

#include <lcm/lcm.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "evade/evade_arm_t.hpp"
#include "evade/evade_angles_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"

extern "C" {
lcm_subscription_t* __real_lcm_subscribe(lcm_t* lcm, const char* channel,
                                         lcm_msg_handler_t handler, void* user);
int __real_lcm_unsubscribe(lcm_t* lcm, lcm_subscription_t* sub);
int __real_lcm_subscription_set_queue_capacity(lcm_subscription_t* sub, int num_messages);
int __real_lcm_publish(lcm_t* lcm, const char* channel, const void* data, unsigned int datalen);
}

namespace {

const char* g_refused_channel = nullptr;            // the channel LCM refuses, if any
std::vector<lcm_subscription_t*> g_live;            // subscriptions made and not yet undone
std::vector<std::string> g_subscribed_channels;     // every channel subscribed, in order
std::vector<std::pair<lcm_subscription_t*, std::string>> g_channel_of;  // live sub -> channel
const char* g_refused_queue_channel = nullptr;      // the channel whose queue LCM refuses to size
bool g_refuse_publish = false;                      // LCM refuses every publish
int g_publish_refusals = 0;                         // publishes refused

}  // namespace

extern "C" lcm_subscription_t* __wrap_lcm_subscribe(lcm_t* lcm, const char* channel,
                                                    lcm_msg_handler_t handler, void* user) {
  if (g_refused_channel != nullptr && std::strcmp(channel, g_refused_channel) == 0)
    return nullptr;
  lcm_subscription_t* s = __real_lcm_subscribe(lcm, channel, handler, user);
  if (s != nullptr) {
    g_live.push_back(s);
    g_subscribed_channels.emplace_back(channel);
    g_channel_of.emplace_back(s, channel);
  }
  return s;
}

extern "C" int __wrap_lcm_subscription_set_queue_capacity(lcm_subscription_t* sub, int n) {
  for (const auto& sc : g_channel_of)
    if (sc.first == sub && g_refused_queue_channel != nullptr && sc.second == g_refused_queue_channel)
      return -1;
  return __real_lcm_subscription_set_queue_capacity(sub, n);
}

extern "C" int __wrap_lcm_publish(lcm_t* lcm, const char* channel, const void* data,
                                  unsigned int datalen) {
  if (g_refuse_publish) {
    ++g_publish_refusals;
    return -1;
  }
  return __real_lcm_publish(lcm, channel, data, datalen);
}

extern "C" int __wrap_lcm_unsubscribe(lcm_t* lcm, lcm_subscription_t* sub) {
  const auto it = std::find(g_live.begin(), g_live.end(), sub);
  if (it != g_live.end()) g_live.erase(it);
  return __real_lcm_unsubscribe(lcm, sub);
}

namespace evade::guidance_lcm {
namespace {

struct LcmDeleter {
  void operator()(lcm_t* l) const { lcm_destroy(l); }
};

class NodeSubscriptions : public ::testing::Test {
 protected:
  void SetUp() override {
    g_refused_channel = nullptr;
    g_refused_queue_channel = nullptr;
    g_refuse_publish = false;
    g_publish_refusals = 0;
    g_live.clear();
    g_subscribed_channels.clear();
    g_channel_of.clear();
  }
  void TearDown() override {
    g_refused_channel = nullptr;
    g_refused_queue_channel = nullptr;
    g_refuse_publish = false;
  }
  std::unique_ptr<lcm_t, LcmDeleter> lcm_{lcm_create("memq://")};
};

// Constructs a node with `channel` refused; returns the exception's text ("" if none).
std::string refusal_text(lcm_t* lcm, const char* channel, bool lockstep) {
  g_refused_channel = channel;
  NodeConfig cfg;
  cfg.lockstep = lockstep;
  try {
    GuidanceNode node(lcm, cfg);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST_F(NodeSubscriptions, EachRefusedChannelThrowsNamingItAndLeavesNoSubscription) {
  ASSERT_NE(lcm_, nullptr);
  // In the node's subscription order: the refusal comes after 0 to 4 accepted subscriptions.
  for (const char* channel : {kChanAngles, kChanNav, kChanArm, kChanClock, kChanPlan}) {
    g_live.clear();
    g_subscribed_channels.clear();
    const std::string why = refusal_text(lcm_.get(), channel, /*lockstep=*/true);
    EXPECT_EQ(why, std::string("GuidanceNode: cannot subscribe to ") + channel);
    EXPECT_TRUE(g_live.empty()) << g_live.size() << " subscription(s) left behind after "
                                << channel << " was refused";
    EXPECT_EQ(std::count(g_subscribed_channels.begin(), g_subscribed_channels.end(), channel), 0);
  }
}

TEST_F(NodeSubscriptions, RefusedSubscriptionLeavesTheLcmUsableByTheNextNode) {
  ASSERT_NE(lcm_, nullptr);
  ASSERT_FALSE(refusal_text(lcm_.get(), kChanPlan, /*lockstep=*/false).empty());
  g_refused_channel = nullptr;
  GuidanceNode node(lcm_.get(), NodeConfig{});
  // One message on each input channel reaches the new node only: the failed node's
  // subscriptions are gone (with them left behind, LCM would call into freed memory).
  evade_arm_t arm{};
  arm.utime = 1000000;
  arm.seq = 1;
  arm.armed = true;
  std::vector<std::uint8_t> buf(static_cast<std::size_t>(arm.getEncodedSize()));
  ASSERT_EQ(arm.encode(buf.data(), 0, static_cast<int>(buf.size())), static_cast<int>(buf.size()));
  for (const char* channel : {kChanAngles, kChanNav, kChanArm})
    ASSERT_EQ(lcm_publish(lcm_.get(), channel, buf.data(), static_cast<unsigned>(buf.size())), 0);
  EXPECT_EQ(node.drain(), 3);
  EXPECT_EQ(node.counts().received, 3);
}

TEST_F(NodeSubscriptions, NodeSubscribesItsChannelsAndUnsubscribesAllWhenDestroyed) {
  ASSERT_NE(lcm_, nullptr);
  for (bool lockstep : {false, true}) {
    g_live.clear();
    g_subscribed_channels.clear();
    {
      NodeConfig cfg;
      cfg.lockstep = lockstep;
      GuidanceNode node(lcm_.get(), cfg);
      std::vector<std::string> expected = {kChanAngles, kChanNav};
      if (lockstep) expected.emplace_back(kChanClock);
      expected.emplace_back(kChanPlan);
      expected.emplace_back(kChanArm);
      expected.emplace_back(kChanKeyCmd);
      expected.emplace_back(kChanConjunction);
      expected.emplace_back(kChanCamDecision);
      EXPECT_EQ(g_subscribed_channels, expected);
      EXPECT_EQ(g_live.size(), expected.size());
    }
    EXPECT_TRUE(g_live.empty()) << g_live.size() << " subscription(s) outlived the node";
  }
}

TEST_F(NodeSubscriptions, NullLcmOrBadConfigThrowsInvalidArgumentAndSubscribesNothing) {
  EXPECT_THROW(GuidanceNode(nullptr, NodeConfig{}), std::invalid_argument);
  NodeConfig bad;
  bad.queue_capacity = 0;
  try {
    GuidanceNode node(lcm_.get(), bad);
    ADD_FAILURE() << "a zero queue capacity was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("queue_capacity"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(g_subscribed_channels.empty());
}

}  // namespace
}  // namespace evade::guidance_lcm

namespace evade::guidance_lcm {
namespace {

// An input channel whose LCM queue cannot be deepened would drop bursts before the node's
// accounting sees them: the node refuses to start, naming the channel, and leaves no
// subscription behind (the plan channel keeps LCM's default queue and is never sized).
TEST_F(NodeSubscriptions, RefusedQueueSizeThrowsNamingTheChannelAndLeavesNoSubscription) {
  ASSERT_NE(lcm_, nullptr);
  for (const char* channel : {kChanAngles, kChanNav, kChanArm, kChanClock}) {
    g_live.clear();
    g_channel_of.clear();
    g_refused_queue_channel = channel;
    NodeConfig cfg;
    cfg.lockstep = true;
    std::string why;
    try {
      GuidanceNode node(lcm_.get(), cfg);
    } catch (const std::runtime_error& e) {
      why = e.what();
    }
    EXPECT_EQ(why, std::string("GuidanceNode: cannot size the LCM queue of ") + channel);
    EXPECT_TRUE(g_live.empty()) << g_live.size() << " subscription(s) left behind";
  }
}

// A command or status LCM refuses to send is counted; the loop goes on (the next cycle's
// command supersedes it) and sends again once LCM accepts.
TEST_F(NodeSubscriptions, RefusedPublishIsCountedAndTheLoopGoesOn) {
  ASSERT_NE(lcm_, nullptr);
  GuidanceNode node(lcm_.get(), NodeConfig{});
  g_refuse_publish = true;
  std::int64_t t_us = 1'000'000;
  for (int k = 0; k < 25; ++k, t_us += 20'000) (void)node.run_cycle(t_us);
  EXPECT_GE(g_publish_refusals, 25);  // 25 commands, and the status messages due
  EXPECT_EQ(node.publish_failures(), g_publish_refusals);
  EXPECT_EQ(node.cycles(), 25);
  g_refuse_publish = false;
  const int refused = g_publish_refusals;
  for (int k = 0; k < 5; ++k, t_us += 20'000) (void)node.run_cycle(t_us);
  EXPECT_EQ(node.publish_failures(), refused);
  EXPECT_EQ(node.cycles(), 30);
}

}  // namespace
}  // namespace evade::guidance_lcm
