// Signed commands with acknowledgement and retransmission (include/evade/lcm_link/
// command_uplink.hpp).
#include "evade/lcm_link/command_uplink.hpp"

#include <time.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include <lcm/lcm.h>

#include "evade/auth/key_file.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/lcm_link/internal/status_watch.hpp"

namespace evade::lcm_link {
namespace {

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

// Verdict of a status for the command in flight: -1 not yet, else the outcome's code.
using AckCheck = std::function<int(const evade_guidance_status_t&, UplinkResult*)>;
// Encodes and publishes one (newly signed) transmission; false when LCM refuses.
using Transmit = std::function<bool(lcm_t*)>;

UplinkResult run_uplink(const UplinkOptions& o, const Transmit& transmit, const AckCheck& ack) {
  if (!(o.timeout_s > 0.0) || !(o.retransmit_s > 0.0)) {
    throw std::invalid_argument("uplink: the timeout and the retransmission interval must be > 0 s");
  }
  std::unique_ptr<lcm_t, void (*)(lcm_t*)> lcm(
      lcm_create(o.lcm_url.empty() ? nullptr : o.lcm_url.c_str()), &lcm_destroy);
  if (lcm == nullptr) throw std::runtime_error("LCM initialization failed for url '" + o.lcm_url + "'");
  StatusWatch watch;
  lcm_subscription_t* sub =
      lcm_subscribe(lcm.get(), o.status_channel.c_str(), &StatusWatch::on_status, &watch);
  if (sub == nullptr) throw std::runtime_error("cannot subscribe to " + o.status_channel);
  UplinkResult r;
  r.first_utime = realtime_us();
  const double t0 = mono_s();
  double next_send = t0;
  // Bounded: each pass waits for a status or until the next transmission, and the loop ends at
  // the timeout (or at the first acknowledgement).
  while (mono_s() - t0 < o.timeout_s) {
    if (mono_s() >= next_send) {
      if (!transmit(lcm.get())) throw std::runtime_error("LCM refused to send the command");
      ++r.transmissions;
      next_send += o.retransmit_s;
    }
    const double wait_s = std::min(next_send, t0 + o.timeout_s) - mono_s();
    watch.have = false;
    if (lcm_handle_timeout(lcm.get(), static_cast<int>(std::max(1.0, wait_s * 1e3))) < 0) break;
    if (watch.have && ack(watch.last, &r) >= 0) {  // a status received after a transmission
      r.ack_s = mono_s() - t0;
      break;
    }
  }
  (void)lcm_unsubscribe(lcm.get(), sub);  // closing the instance next releases it anyway
  if (r.ack_s == 0.0) {
    r.outcome = AckOutcome::kTimeout;
    r.reason = "no acknowledgement";
  }
  return r;
}

template <typename Msg>
bool send_signed(lcm_t* lcm, const char* channel, Msg m, const guidance_lcm::SigningKey& key,
                 guidance_lcm::ArsnClock* arsn) {
  std::vector<std::uint8_t> buf(static_cast<std::size_t>(m.getEncodedSize()));
  const int n = guidance_lcm::encode_signed(&m, channel, key, arsn->next(), buf.data(),
                                            static_cast<int>(buf.size()));
  return n > 0 && lcm_publish(lcm, channel, buf.data(), static_cast<unsigned>(n)) == 0;
}

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
                         std::int64_t seq, const PlanStamp& stamp,
                         const guidance_lcm::SigningKey& key) {
  if (channel.empty()) throw std::invalid_argument("uplink_plan: channel is empty");
  const std::int64_t utime = stamp.utime != 0 ? stamp.utime : realtime_us();
  evade_burn_plan_t m{};
  guidance_lcm::to_lcm(plan, utime, seq, stamp.epoch_utime != 0 ? stamp.epoch_utime : utime,
                       stamp.frame, &m);
  guidance_lcm::ArsnClock arsn;
  const Transmit tx = [&](lcm_t* l) { return send_signed(l, channel.c_str(), m, key, &arsn); };
  const AckCheck ack = [seq](const evade_guidance_status_t& s, UplinkResult* r) {
    if (s.plan_ack_id != seq) return -1;
    r->code = s.plan_ack_result;
    r->outcome = s.plan_ack_result == 0 ? AckOutcome::kAccepted : AckOutcome::kRejected;
    r->reason = s.plan_ack_result == 0
                    ? "accepted"
                    : guidance::plan_reject_name(static_cast<guidance::PlanReject>(s.plan_ack_result));
    return r->code;
  };
  return run_uplink(o, tx, ack);
}

UplinkResult uplink_arm(const UplinkOptions& o, bool armed, const guidance_lcm::SigningKey& key) {
  evade_arm_t m{};
  m.utime = realtime_us();
  m.seq = m.utime;  // unique per command; the signed arm's order is its ARSN
  m.armed = armed ? 1 : 0;
  guidance_lcm::ArsnClock arsn;
  const Transmit tx = [&](lcm_t* l) {
    m.utime = realtime_us();
    return send_signed(l, guidance_lcm::kChanArm, m, key, &arsn);
  };
  const AckCheck ack = [armed](const evade_guidance_status_t& s, UplinkResult* r) {
    if ((s.armed != 0) != armed) return -1;
    r->outcome = AckOutcome::kAccepted;
    r->reason = armed ? "armed" : "disarmed";
    return 0;
  };
  return run_uplink(o, tx, ack);
}

UplinkResult uplink_key_cmd(const UplinkOptions& o, std::int8_t op, std::int32_t target_key_id,
                            const guidance_lcm::SigningKey& key) {
  evade_key_cmd_t m{};
  m.utime = realtime_us();
  m.seq = m.utime;  // unique per command: the acknowledgement names it
  m.op = op;
  m.key_id = target_key_id;
  const std::int64_t seq = m.seq;
  guidance_lcm::ArsnClock arsn;
  const Transmit tx = [&](lcm_t* l) { return send_signed(l, guidance_lcm::kChanKeyCmd, m, key, &arsn); };
  const AckCheck ack = [seq](const evade_guidance_status_t& s, UplinkResult* r) {
    if (s.key_cmd_last_seq != seq) return -1;
    r->code = s.key_cmd_last_result;
    r->outcome = s.key_cmd_last_result == evade_guidance_status_t::KEY_CMD_DONE
                     ? AckOutcome::kAccepted
                     : AckOutcome::kRejected;
    r->reason = key_cmd_result_name(s.key_cmd_last_result);
    return r->code;
  };
  return run_uplink(o, tx, ack);
}

nlohmann::json to_json(const UplinkResult& r, std::int32_t key_id) {
  return {{"outcome", outcome_name(r.outcome)},
          {"code", r.code},
          {"reason", r.reason},
          {"key_id", key_id},
          {"transmissions", r.transmissions},
          {"ack_s", r.outcome == AckOutcome::kTimeout ? nlohmann::json(nullptr)
                                                      : nlohmann::json(r.ack_s)},
          {"exit_code", exit_code(r)}};
}

}  // namespace evade::lcm_link
