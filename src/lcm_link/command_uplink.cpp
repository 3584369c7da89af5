// Signed commands with acknowledgement and retransmission (include/evade/lcm_link/
// command_uplink.hpp): each transmission signed with the next ARSN of the ground's counter, the
// node's signed answer matched to the transmission it names, the counter raised when the node
// says it is behind.
#include "evade/lcm_link/command_uplink.hpp"

#include <time.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <stdexcept>
#include <vector>

#include <lcm/lcm.h>

#include "evade/auth/key_file.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/input_accounting.hpp"
#include "evade/lcm_link/internal/telemetry_watch.hpp"

namespace evade::lcm_link {
namespace {

using Ack = evade_cmd_ack_t;

double mono_s() {
  timespec ts{};
  (void)clock_gettime(CLOCK_MONOTONIC, &ts);  // CLOCK_MONOTONIC always exists
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::int64_t realtime_us() {
  timespec ts{};
  (void)clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

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

// The name of a refusal: the detail when there is one (the plan's or the key command's own
// reason), else the node's input reason.
std::string refusal_name(const Ack& a) {
  if (a.detail != 0 && a.command == Ack::COMMAND_PLAN) {  // "BURN_IN_PAST" -> "burn_in_past"
    std::string name = guidance::plan_reject_name(static_cast<guidance::PlanReject>(a.detail));
    std::transform(name.begin(), name.end(), name.begin(),
                   [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
    return name;
  }
  if (a.detail != 0 && a.command == Ack::COMMAND_KEY_CMD) return key_cmd_result_name(a.detail);
  return guidance_lcm::reason_name(static_cast<guidance_lcm::Reason>(a.reason));
}

struct Sent {
  std::int64_t arsn;
  auth::Mac mac;
};

struct LcmDeleter {
  void operator()(lcm_t* l) const { lcm_destroy(l); }
};

// One command's transmissions and the node's answers to them.
class Uplink {
 public:
  Uplink(const UplinkOptions& o, const GroundKeys& keys, ArsnSource* arsn)
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
    if (ack_sub_ == nullptr || st_sub_ == nullptr) {
      throw std::runtime_error("cannot subscribe to " + o.ack_channel + " and " + o.status_channel);
    }
    t0_ = mono_s();
  }
  ~Uplink() {
    (void)lcm_unsubscribe(lcm_.get(), ack_sub_);  // closing the instance releases it anyway
    (void)lcm_unsubscribe(lcm_.get(), st_sub_);
  }
  Uplink(const Uplink&) = delete;
  Uplink& operator=(const Uplink&) = delete;

  double left_s() const { return t0_ + o_.timeout_s - mono_s(); }

  /// Waits (within the timeout) for a verified status; false if none came.
  bool wait_status(evade_guidance_status_t* out) {
    while (left_s() > 0.0 && !watch_->have_status) handle(left_s());
    if (!watch_->have_status) return false;
    *out = watch_->status;
    return true;
  }

  template <typename Msg>
  UplinkResult run(const char* channel, Msg m) {
    UplinkResult r;
    double next_send = mono_s();
    // Bounded: each pass waits for telemetry or until the next transmission, and the loop ends
    // at the timeout (or at the answer).
    while (left_s() > 0.0 && r.ack_s == 0.0) {
      if (mono_s() >= next_send) {
        transmit(channel, &m, &r);
        next_send = mono_s() + o_.retransmit_s;
      }
      handle(std::min(next_send - mono_s(), left_s()));
      look_at_status();
      if (look_at_acks(&r)) next_send = mono_s();  // the counter was behind: send at once
    }
    r.acks_verified = watch_->acks_verified;
    r.status_verified = watch_->status_verified;
    r.ignored = watch_->ignored;
    if (r.ack_s == 0.0) {
      r.outcome = AckOutcome::kTimeout;
      r.reason = "no acknowledgement";
      r.note = "no answer verified under telemetry key " + std::to_string(keys_.telemetry.id) +
               " (the node may be down, not hold command key " + std::to_string(keys_.command.id) +
               ", or sign with another telemetry key)";
    }
    return r;
  }

 private:
  void handle(double wait_s) {
    if (lcm_handle_timeout(lcm_.get(), static_cast<int>(std::max(1.0, wait_s * 1e3))) < 0) {
      throw std::runtime_error("LCM receive failed on '" + o_.lcm_url + "'");
    }
  }

  template <typename Msg>
  void transmit(const char* channel, Msg* m, UplinkResult* r) {
    const std::int64_t a = arsn_->next();  // on disk before it is used
    std::vector<std::uint8_t> buf(static_cast<std::size_t>(m->getEncodedSize()));
    const int n = guidance_lcm::encode_signed(m, channel, keys_.command, a, buf.data(),
                                              static_cast<int>(buf.size()));
    if (n < 0) throw std::runtime_error(std::string("cannot encode the command for ") + channel);
    Sent s{a, {}};
    std::copy(buf.end() - static_cast<long>(auth::kMacBytes), buf.end(), s.mac.begin());
    sent_.push_back(s);
    if (lcm_publish(lcm_.get(), channel, buf.data(), static_cast<unsigned>(n)) != 0) {
      throw std::runtime_error("LCM refused to send the command");
    }
    if (r->transmissions == 0) r->first_utime = realtime_us();
    ++r->transmissions;
  }

  const Sent* find_sent(std::int64_t arsn) const {
    for (const Sent& s : sent_) {
      if (s.arsn == arsn) return &s;
    }
    return nullptr;
  }

  // A verified status whose ARSN of our key is above our counter: the counter is behind.
  void look_at_status() {
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
  bool look_at_acks(UplinkResult* r) {
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
  bool answer(const Ack& a, UplinkResult* r) {
    r->node_arsn = a.node_arsn;
    const bool behind = a.outcome == Ack::OUTCOME_REFUSED &&
                        a.reason == Ack::REASON_REPLAYED_ARSN;
    if (behind && find_sent(a.node_arsn) != nullptr) return false;  // another copy got there
    if (behind && r->arsn_recoveries < kMaxArsnRecoveries) {
      arsn_->raise_to(a.node_arsn);
      ++r->arsn_recoveries;
      return true;
    }
    r->ack_s = std::max(mono_s() - t0_, 1e-9);
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

  UplinkOptions o_;
  GroundKeys keys_;
  ArsnSource* arsn_;
  std::unique_ptr<TelemetryWatch> watch_;
  std::unique_ptr<lcm_t, LcmDeleter> lcm_;
  lcm_subscription_t* ack_sub_ = nullptr;
  lcm_subscription_t* st_sub_ = nullptr;
  std::vector<Sent> sent_;
  double t0_ = 0.0;
};

}  // namespace

guidance_lcm::SigningKey load_command_key(const std::string& key_file, std::int32_t key_id) {
  return load_signing_key(key_file, key_id, auth::KeyRole::kCommand);
}

guidance_lcm::SigningKey load_signing_key(const std::string& key_file, std::int32_t key_id,
                                          auth::KeyRole role) {
  std::vector<auth::KeyRecord> keys;
  try {
    keys = auth::read_key_file(key_file);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // a refused key file is bad input (exit 2)
  }
  const auth::KeyRecord* pick = nullptr;
  int n_role = 0;
  for (const auth::KeyRecord& k : keys) {
    if (k.role != role) continue;
    ++n_role;
    if (key_id == 0 || k.id == key_id) pick = &k;
  }
  const std::string role_text = auth::role_name(role);
  if (pick == nullptr || (key_id == 0 && n_role > 1)) {
    throw std::invalid_argument("key file '" + key_file + "': " +
                             (key_id == 0 ? "holds no single " + role_text + " key; give --key-id"
                                          : "no " + role_text + " key with id " + std::to_string(key_id)));
  }
  guidance_lcm::SigningKey k;
  k.id = pick->id;
  k.key = pick->key;
  for (auth::KeyRecord& r : keys) auth::wipe(r.key.data(), r.key.size());
  return k;
}

int exit_code(const UplinkResult& r) noexcept {
  switch (r.outcome) {
    case AckOutcome::kAccepted: return 0;
    case AckOutcome::kRejected: return 3;
    case AckOutcome::kTimeout: break;
  }
  return 4;
}

const char* outcome_name(AckOutcome o) noexcept {
  switch (o) {
    case AckOutcome::kAccepted: return "accepted";
    case AckOutcome::kRejected: return "rejected";
    case AckOutcome::kTimeout: break;
  }
  return "timeout";
}

UplinkResult uplink_plan(const UplinkOptions& o, const std::string& channel, const BurnPlan& plan,
                         std::int64_t seq, const PlanStamp& stamp, const GroundKeys& keys,
                         ArsnSource* arsn) {
  if (channel.empty()) throw std::invalid_argument("uplink_plan: channel is empty");
  Uplink up(o, keys, arsn);
  if (seq == 0) {  // one above the plan in force, from the node's verified status
    evade_guidance_status_t s{};
    if (!up.wait_status(&s)) {
      UplinkResult r;
      r.reason = "no verified status";
      r.note = "no status verified under telemetry key " + std::to_string(keys.telemetry.id) +
               " to take the next plan id from; give --seq N";
      return r;
    }
    seq = s.plan_id + 1;
  }
  const std::int64_t utime = stamp.utime != 0 ? stamp.utime : realtime_us();
  evade_burn_plan_t m{};
  guidance_lcm::to_lcm(plan, utime, seq, stamp.epoch_utime != 0 ? stamp.epoch_utime : utime,
                       stamp.frame, &m);
  UplinkResult r = up.run(channel.c_str(), m);
  r.plan_id = seq;
  return r;
}

UplinkResult uplink_arm(const UplinkOptions& o, bool armed, const GroundKeys& keys,
                        ArsnSource* arsn) {
  Uplink up(o, keys, arsn);
  evade_arm_t m{};
  m.utime = realtime_us();  // informational: an arm is ordered by its ARSN (docs/SECURITY.md)
  m.seq = arsn->last() + 1;  // unique per command: the ARSN of its first transmission
  m.armed = armed ? 1 : 0;
  return up.run(guidance_lcm::kChanArm, m);
}

UplinkResult uplink_key_cmd(const UplinkOptions& o, std::int8_t op, std::int32_t target_key_id,
                            const GroundKeys& keys, ArsnSource* arsn) {
  Uplink up(o, keys, arsn);
  evade_key_cmd_t m{};
  m.utime = realtime_us();
  m.seq = arsn->last() + 1;  // unique per command: the ARSN of its first transmission
  m.op = op;
  m.key_id = target_key_id;
  return up.run(guidance_lcm::kChanKeyCmd, m);
}

nlohmann::json to_json(const UplinkResult& r, std::int32_t key_id) {
  nlohmann::json j = {{"outcome", outcome_name(r.outcome)},
                      {"code", r.code},
                      {"detail", r.detail},
                      {"reason", r.reason},
                      {"key_id", key_id},
                      {"transmissions", r.transmissions},
                      {"ack_s", r.outcome == AckOutcome::kTimeout ? nlohmann::json(nullptr)
                                                                  : nlohmann::json(r.ack_s)},
                      {"arsn", r.arsn},
                      {"node_arsn", r.node_arsn},
                      {"arsn_recoveries", r.arsn_recoveries},
                      {"telemetry", {{"acks_verified", r.acks_verified},
                                     {"status_verified", r.status_verified},
                                     {"ignored", r.ignored},
                                     {"unmatched", r.unmatched}}},
                      {"exit_code", exit_code(r)}};
  if (!r.note.empty()) j["note"] = r.note;
  return j;
}

}  // namespace evade::lcm_link
