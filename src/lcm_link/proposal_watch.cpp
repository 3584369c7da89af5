// The node's signed proposals as the ground reads them (include/evade/lcm_link/
// proposal_watch.hpp).
#include "evade/lcm_link/proposal_watch.hpp"

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <tuple>

#include <lcm/lcm.h>

#include "evade/autonomy/response.hpp"
#include "evade/lcm_link/internal/telemetry_watch.hpp"
#include "evade/lcm_link/internal/uplink_session.hpp"

namespace evade::lcm_link {
namespace {

template <int N>
nlohmann::json array_of(const double (&a)[N]) {
  nlohmann::json j = nlohmann::json::array();
  for (int i = 0; i < N; ++i) j.push_back(a[i]);
  return j;
}

nlohmann::json proposal_json(const evade_cam_proposal_t& p) {
  return {{"event_id", p.event_id},
          {"version", p.version},
          {"proposal_id", p.proposal_id},
          {"state", autonomy::response_state_name(static_cast<autonomy::ResponseState>(p.state))},
          {"reason", autonomy::response_reason_name(static_cast<autonomy::ResponseReason>(p.reason))},
          {"autonomy", autonomy::policy_name(static_cast<autonomy::Policy>(p.autonomy))},
          {"pc", p.pc},
          {"miss_m", p.miss_m},
          {"burn_utime", p.burn_utime},
          {"dv_rsw_mps", array_of(p.dv_rsw_mps)},
          {"dv_eci_mps", array_of(p.dv_eci_mps)},
          {"post_pc", p.post_pc},
          {"post_miss_m", p.post_miss_m},
          {"veto_deadline_utime", p.veto_deadline_utime},
          {"plan_id", p.plan_id}};
}

struct LcmClose {
  void operator()(lcm_t* l) const { lcm_destroy(l); }
};

}  // namespace

ProposalWatchResult watch_proposal(const std::string& lcm_url, const std::string& channel,
                                   const guidance_lcm::SigningKey& telemetry, std::int64_t event_id,
                                   double timeout_s) {
  std::unique_ptr<lcm_t, LcmClose> lcm(lcm_create(lcm_url.empty() ? nullptr : lcm_url.c_str()));
  if (lcm == nullptr) throw std::runtime_error("LCM initialization failed for url '" + lcm_url + "'");
  auto watch = std::make_unique<TelemetryWatch>();
  watch->key = telemetry;
  watch->proposal_event = event_id;
  lcm_subscription_t* sub =
      lcm_subscribe(lcm.get(), channel.c_str(), &TelemetryWatch::on_proposal, watch.get());
  if (sub == nullptr) throw std::runtime_error("cannot subscribe to " + channel);
  const double end = uplink_mono_s() + timeout_s;
  // Bounded by the timeout: each pass waits at most what is left of it.
  while (!watch->have_proposal && uplink_mono_s() < end) {
    const double left_ms = std::max(1.0, (end - uplink_mono_s()) * 1e3);
    if (lcm_handle_timeout(lcm.get(), static_cast<int>(left_ms)) < 0) break;
  }
  (void)lcm_unsubscribe(lcm.get(), sub);  // closing the instance releases it anyway
  ProposalWatchResult r;
  r.verified = watch->proposals_verified;
  r.ignored = watch->ignored;
  if (watch->have_proposal) r.proposal = proposal_json(watch->proposal);
  return r;
}

struct ProposalRecorder::Impl {
  using Key = std::tuple<std::int32_t, std::int64_t, std::int8_t, std::int16_t>;
  guidance_lcm::SigningKey key;
  struct Close {
    void operator()(lcm_t* l) const { lcm_destroy(l); }
  };
  std::unique_ptr<lcm_t, Close> lcm;
  mutable std::mutex mu;
  std::vector<Change> changes;
  std::map<std::int64_t, Key> last;  // per event: version, proposal, state, reason
  int verified = 0, ignored = 0, dropped = 0;
  std::atomic<bool> stop{false};
  std::thread thread;

  // Inside LCM's C dispatch: nothing here throws but the allocation of a change (bounded).
  static void on_message(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept {
    auto* self = static_cast<Impl*>(user);
    evade_cam_proposal_t m{};
    const bool ok = decode_verified(self->key, rbuf, channel, &m);
    std::lock_guard<std::mutex> lock(self->mu);
    if (!ok) {
      ++self->ignored;
      return;
    }
    ++self->verified;
    const Key k{m.version, m.proposal_id, m.state, m.reason};
    const auto it = self->last.find(m.event_id);
    if (it != self->last.end() && it->second == k) return;
    if (self->changes.size() >= kMaxChanges) {
      ++self->dropped;
      return;
    }
    try {
      self->changes.push_back({m.utime, proposal_json(m)});
      self->last[m.event_id] = k;
    } catch (...) {
      ++self->dropped;
    }
  }
  void run() const noexcept {
    // Bounded per pass (100 ms); ends when the recorder is destroyed or LCM fails.
    while (!stop.load())
      if (lcm_handle_timeout(lcm.get(), 100) < 0) break;
  }
};

ProposalRecorder::ProposalRecorder(const std::string& lcm_url, const std::string& channel,
                                   const guidance_lcm::SigningKey& telemetry)
    : impl_(std::make_unique<Impl>()) {
  impl_->key = telemetry;
  impl_->lcm.reset(lcm_create(lcm_url.empty() ? nullptr : lcm_url.c_str()));
  if (impl_->lcm == nullptr) throw std::runtime_error("LCM initialization failed for url '" + lcm_url + "'");
  if (lcm_subscribe(impl_->lcm.get(), channel.c_str(), &Impl::on_message, impl_.get()) == nullptr)
    throw std::runtime_error("cannot subscribe to " + channel);
  impl_->thread = std::thread([this] { impl_->run(); });
}

ProposalRecorder::~ProposalRecorder() {
  impl_->stop.store(true);
  impl_->thread.join();
}

std::vector<ProposalRecorder::Change> ProposalRecorder::changes() const {
  std::lock_guard<std::mutex> lock(impl_->mu);
  return impl_->changes;
}
int ProposalRecorder::verified() const {
  std::lock_guard<std::mutex> lock(impl_->mu);
  return impl_->verified;
}
int ProposalRecorder::ignored() const {
  std::lock_guard<std::mutex> lock(impl_->mu);
  return impl_->ignored;
}
int ProposalRecorder::dropped() const {
  std::lock_guard<std::mutex> lock(impl_->mu);
  return impl_->dropped;
}

}  // namespace evade::lcm_link
