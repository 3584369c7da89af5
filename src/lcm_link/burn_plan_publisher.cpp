// publish_burn_plan (burn_plan_publisher.hpp): to_lcm, encode into a buffer, lcm_publish.
#include "evade/lcm_link/burn_plan_publisher.hpp"

#include <chrono>
#include <memory>
#include <stdexcept>
#include <vector>

#include "evade/evade_burn_plan_t.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"

namespace evade::lcm_link {
namespace {

std::int64_t wall_clock_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

std::int64_t publish_burn_plan(lcm_t* lcm, const std::string& channel, const BurnPlan& plan,
                               std::int64_t seq, const PlanStamp& stamp) {
  if (lcm == nullptr) throw std::invalid_argument("publish_burn_plan: lcm is null");
  if (channel.empty()) throw std::invalid_argument("publish_burn_plan: channel is empty");
  const std::int64_t utime = stamp.utime != 0 ? stamp.utime : wall_clock_us();
  const std::int64_t epoch = stamp.epoch_utime != 0 ? stamp.epoch_utime : utime;
  evade_burn_plan_t m{};
  guidance_lcm::to_lcm(plan, utime, seq, epoch, stamp.frame, &m);
  if (stamp.key.id != 0 && stamp.arsn <= 0) {
    throw std::invalid_argument("publish_burn_plan: a signed plan needs its ARSN (the ground's "
                                "counter, docs/SECURITY.md ARSN-2)");
  }
  std::vector<std::uint8_t> buf(static_cast<std::size_t>(m.getEncodedSize()));
  const int n = stamp.key.id != 0
                    ? guidance_lcm::encode_signed(&m, channel.c_str(), stamp.key, stamp.arsn,
                                                  buf.data(), static_cast<int>(buf.size()))
                    : m.encode(buf.data(), 0, static_cast<int>(buf.size()));
  if (n < 0)
    throw std::runtime_error("LCM encode of evade_burn_plan_t for channel '" + channel +
                             "' failed");
  if (lcm_publish(lcm, channel.c_str(), buf.data(), static_cast<unsigned>(n)) != 0)
    throw std::runtime_error("LCM publish on channel '" + channel + "' failed");
  return utime;
}

std::int64_t publish_burn_plan(lcm_t* lcm, const std::string& channel, const BurnPlan& plan,
                               std::int64_t seq) {
  return publish_burn_plan(lcm, channel, plan, seq, PlanStamp{});
}

std::int64_t publish_burn_plan(const std::string& lcm_url, const std::string& channel,
                               const BurnPlan& plan, std::int64_t seq, const PlanStamp& stamp) {
  std::unique_ptr<lcm_t, void (*)(lcm_t*)> lcm(
      lcm_create(lcm_url.empty() ? nullptr : lcm_url.c_str()), &lcm_destroy);
  if (lcm == nullptr)
    throw std::runtime_error("LCM initialization failed for url '" + lcm_url + "'");
  return publish_burn_plan(lcm.get(), channel, plan, seq, stamp);
}

}  // namespace evade::lcm_link
