// One signed ground command's transmissions and the node's answers (include/evade/lcm_link/
// internal/uplink_session.hpp).
#include "evade/lcm_link/internal/uplink_session.hpp"

#include <time.h>

#include <cctype>

#include "evade/autonomy/responder.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/guidance_lcm/input_accounting.hpp"

namespace evade::lcm_link {
namespace {

using Ack = evade_cmd_ack_t;

const char* key_cmd_result_name(int code) {
  switch (code) {
    case evade_guidance_status_t::KEY_CMD_DONE: return "done";
    case evade_guidance_status_t::KEY_CMD_UNKNOWN_KEY: return "unknown_key";
    case evade_guidance_status_t::KEY_CMD_RETIRED: return "retired";
    case evade_guidance_status_t::KEY_CMD_LAST_KEY: return "last_key";
    case evade_guidance_status_t::KEY_CMD_BAD_OP: return "bad_op";
    default: return "none";
  }
}

// evade_cmd_ack_t's CONJ_* in order (docs/AUTONOMY.md AUT-1).
const char* conjunction_detail_name(int code) {
  static constexpr const char* kNames[] = {"tracked",      "replaced",     "not_newer",
                                           "table_full",   "bad_id",       "not_finite",
                                           "out_of_range", "asymmetric",   "bad_window",
                                           "tca_not_ahead", "already_tracked"};
  static_assert(sizeof(kNames) / sizeof(kNames[0]) == Ack::CONJ_ALREADY_TRACKED + 1,
                "one name per CONJ_* code");
  return code >= 0 && code <= Ack::CONJ_ALREADY_TRACKED ? kNames[code] : "unknown";
}

std::string lower(std::string s) {  // "BURN_IN_PAST" -> "burn_in_past"
  std::transform(s.begin(), s.end(), s.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  return s;
}

}  // namespace

double uplink_mono_s() {
  timespec ts{};
  (void)clock_gettime(CLOCK_MONOTONIC, &ts);  // CLOCK_MONOTONIC always exists
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::int64_t uplink_realtime_us() {
  timespec ts{};
  (void)clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

std::int64_t uplink_utime(const UplinkOptions& o) {
  return o.clock_utime ? o.clock_utime() : uplink_realtime_us();
}

std::string refusal_name(const Ack& a) {
  if (a.detail != 0 && a.command == Ack::COMMAND_PLAN)
    return lower(guidance::plan_reject_name(static_cast<guidance::PlanReject>(a.detail)));
  if (a.detail != 0 && a.command == Ack::COMMAND_KEY_CMD) return key_cmd_result_name(a.detail);
  if (a.command == Ack::COMMAND_CONJUNCTION) return conjunction_detail_name(a.detail);
  if (a.detail != 0 && a.command == Ack::COMMAND_CAM_DECISION)
    return autonomy::decision_result_name(static_cast<autonomy::DecisionResult>(a.detail));
  return guidance_lcm::reason_name(static_cast<guidance_lcm::Reason>(a.reason));
}

UplinkSession::UplinkSession(const UplinkOptions& o, const GroundKeys& keys, ArsnSource* arsn)
    : o_(o), keys_(keys), arsn_(arsn), watch_(std::make_unique<TelemetryWatch>()) {
  if (!(o.timeout_s > 0.0) || !(o.retransmit_s > 0.0)) {
    throw std::invalid_argument("uplink: the timeout and the retransmission interval must be > 0 s");
  }
  if (arsn_ == nullptr) throw std::invalid_argument("uplink: no ARSN counter");
  lcm_.reset(lcm_create(o.lcm_url.empty() ? nullptr : o.lcm_url.c_str()));
  if (lcm_ == nullptr) throw std::runtime_error("LCM initialization failed for url '" + o.lcm_url + "'");
  watch_->key = keys.telemetry;
  ack_sub_ = lcm_subscribe(lcm_.get(), o.ack_channel.c_str(), &TelemetryWatch::on_ack, watch_.get());
  st_sub_ = lcm_subscribe(lcm_.get(), o.status_channel.c_str(), &TelemetryWatch::on_status,
                          watch_.get());
  prop_sub_ = lcm_subscribe(lcm_.get(), o.proposal_channel.c_str(), &TelemetryWatch::on_proposal,
                            watch_.get());
  if (ack_sub_ == nullptr || st_sub_ == nullptr || prop_sub_ == nullptr) {
    throw std::runtime_error("cannot subscribe to " + o.ack_channel + ", " + o.status_channel +
                             " and " + o.proposal_channel);
  }
  t0_ = uplink_mono_s();
}

UplinkSession::~UplinkSession() {
  (void)lcm_unsubscribe(lcm_.get(), ack_sub_);  // closing the instance releases them anyway
  (void)lcm_unsubscribe(lcm_.get(), st_sub_);
  (void)lcm_unsubscribe(lcm_.get(), prop_sub_);
}

double UplinkSession::left_s() const { return t0_ + o_.timeout_s - uplink_mono_s(); }

bool UplinkSession::wait_status(evade_guidance_status_t* out) {
  while (left_s() > 0.0 && !watch_->have_status) handle(left_s());
  if (!watch_->have_status) return false;
  *out = watch_->status;
  return true;
}

bool UplinkSession::wait_proposal(std::int64_t event_id, evade_cam_proposal_t* out) {
  watch_->proposal_event = event_id;
  watch_->have_proposal = false;
  while (left_s() > 0.0 && !watch_->have_proposal) handle(left_s());
  if (!watch_->have_proposal) return false;
  *out = watch_->proposal;
  return true;
}

void UplinkSession::handle(double wait_s) {
  if (lcm_handle_timeout(lcm_.get(), static_cast<int>(std::max(1.0, wait_s * 1e3))) < 0) {
    throw std::runtime_error("LCM receive failed on '" + o_.lcm_url + "'");
  }
}

void UplinkSession::publish(const char* channel, const std::uint8_t* data, int n) {
  if (lcm_publish(lcm_.get(), channel, data, static_cast<unsigned>(n)) != 0) {
    throw std::runtime_error("LCM refused to send the command");
  }
}

void UplinkSession::finish(UplinkResult* r) const {
  r->acks_verified = watch_->acks_verified;
  r->status_verified = watch_->status_verified;
  r->ignored = watch_->ignored;
  if (r->ack_s != 0.0) return;
  r->outcome = AckOutcome::kTimeout;
  r->reason = "no acknowledgement";
  r->note = "no answer verified under telemetry key " + std::to_string(keys_.telemetry.id) +
            " (the node may be down, not hold command key " + std::to_string(keys_.command.id) +
            ", or sign with another telemetry key)";
}

const UplinkSession::Sent* UplinkSession::find_sent(std::int64_t arsn) const {
  for (const Sent& s : sent_) {
    if (s.arsn == arsn) return &s;
  }
  return nullptr;
}

// A verified status whose ARSN of our key is above our counter: the counter is behind.
void UplinkSession::look_at_status() {
  if (!watch_->have_status) return;
  watch_->have_status = false;
  const evade_guidance_status_t& s = watch_->status;
  for (int i = 0; i < s.auth_n_keys && i < 8; ++i) {
    if (s.auth_key_id[i] != keys_.command.id) continue;
    const std::int64_t node = s.auth_key_arsn[i];
    if (node > arsn_->last() && find_sent(node) == nullptr) arsn_->raise_to(node);
  }
}

// True when the counter was raised and the command must go again at once.
bool UplinkSession::look_at_acks(UplinkResult* r) {
  bool resend = false;
  for (std::size_t i = 0; i < watch_->n_acks && r->ack_s == 0.0; ++i) {
    const Ack& a = watch_->acks[i];
    const Sent* s = a.cmd_key_id == keys_.command.id ? find_sent(a.cmd_arsn) : nullptr;
    if (s == nullptr || !std::equal(s->mac.begin(), s->mac.end(),
                                    reinterpret_cast<const std::uint8_t*>(a.cmd_mac))) {
      ++r->unmatched;
      continue;
    }
    resend = answer(a, r) || resend;
  }
  watch_->n_acks = 0;
  return resend;
}

// One verified answer to one of our transmissions. True: resend with a raised counter.
bool UplinkSession::answer(const Ack& a, UplinkResult* r) {
  r->node_arsn = a.node_arsn;
  const bool behind = a.outcome == Ack::OUTCOME_REFUSED && a.reason == Ack::REASON_REPLAYED_ARSN;
  if (behind && find_sent(a.node_arsn) != nullptr) return false;  // another copy got there
  if (behind && r->arsn_recoveries < kMaxArsnRecoveries) {
    arsn_->raise_to(a.node_arsn);
    ++r->arsn_recoveries;
    return true;
  }
  r->ack_s = std::max(uplink_mono_s() - t0_, 1e-9);
  r->arsn = a.cmd_arsn;
  r->code = a.reason;
  r->detail = a.detail;
  if (r->plan_id == 0) r->plan_id = a.plan_id;
  const bool ok = a.outcome != Ack::OUTCOME_REFUSED;
  r->outcome = ok ? AckOutcome::kAccepted : AckOutcome::kRejected;
  r->reason = a.outcome == Ack::OUTCOME_ALREADY_IN_FORCE ? "already in force"
              : ok                                       ? "accepted"
                                                         : refusal_name(a);
  if (a.reason == Ack::REASON_FROM_FUTURE) {
    r->note = "this host's clock is ahead of the node's by about " +
              std::to_string((r->first_utime - a.utime) / 1000000) + " s";
  }
  return false;
}

}  // namespace evade::lcm_link
