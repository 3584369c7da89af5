// A conjunction HIL run (conjunction_hil.hpp; docs/AUTONOMY.md AUT-11): the simulator lockstep
// against the node over LCM, the ground's commands one at a time on a thread of their own
// while the simulator keeps ticking (the node reads and answers commands only in its cycles,
// which the ticks drive), each stamped with the tick time (the node's clock in lockstep), and
// every verified proposal the node publishes recorded (lcm_link::ProposalRecorder).
#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <string>

#include "evade/hil/conjunction_hil.hpp"
#include "evade/lcm_link/proposal_watch.hpp"
#include "evade/lcm_link/sim_lcm_endpoint.hpp"

namespace evade::hil {
namespace {

// The newest recorded proposal of event_id in state "proposed"; 0 when there is none yet.
std::int64_t proposed_id(const lcm_link::ProposalRecorder& rec, std::int64_t event_id) {
  std::int64_t id = 0;
  for (const lcm_link::ProposalRecorder::Change& ch : rec.changes()) {
    const nlohmann::json& p = ch.proposal;
    if (p.at("event_id").get<std::int64_t>() == event_id && p.at("state") == "proposed")
      id = p.at("proposal_id").get<std::int64_t>();
  }
  return id;
}

// The ground's commands in order: each conjunction at its sending time, then (veto run) the
// veto of the node's proposal as soon as a verified one is seen. One command at a time.
class GroundScript {
 public:
  GroundScript(const ConjunctionHilCase& c, lcm_link::UplinkOptions o, const lcm_link::GroundKeys& keys,
               lcm_link::ArsnSource* arsn, const lcm_link::ProposalRecorder& rec)
      : c_(c), o_(std::move(o)), keys_(keys), arsn_(arsn), rec_(rec) {}

  void on_cycle(double t_s) {
    if (running_.valid()) {
      if (running_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
      collect(t_s);
    }
    if (next_cdm_ < c_.cdms.size()) {
      const HilCdm& cdm = c_.cdms[next_cdm_];
      if (t_s < cdm.t_send_s) return;
      ++next_cdm_;
      start("conjunction v" + std::to_string(cdm.uplink.event.version) + " (" + cdm.file_name + ")", t_s,
            [this, e = cdm.uplink.event] { return lcm_link::uplink_conjunction(o_, e, keys_, arsn_); });
      current_.version = cdm.uplink.event.version;
      return;
    }
    if (!c_.veto || vetoed_) return;
    autonomy::DecisionCommand d;
    d.kind = autonomy::DecisionCommand::Kind::kVeto;
    d.event_id = c_.cdms.front().uplink.event.event_id;
    d.proposal_id = proposed_id(rec_, d.event_id);
    if (d.proposal_id == 0) return;
    vetoed_ = true;
    start("veto of proposal " + std::to_string(d.proposal_id), t_s,
          [this, d] { return lcm_link::uplink_cam_decision(o_, d, keys_, arsn_); });
  }

  // The command still running at the end (its own timeout bounds the wait).
  void finish(double t_s) {
    if (running_.valid()) collect(t_s);
  }
  std::vector<HilUplink> done;

 private:
  template <typename F>
  void start(std::string what, double t_s, F f) {
    current_ = HilUplink{};
    current_.what = std::move(what);
    current_.t_sent_s = t_s;
    running_ = std::async(std::launch::async, f);
  }
  void collect(double t_s) {
    current_.result = running_.get();  // rethrows the command's exception
    current_.t_answered_s = t_s;
    if (current_.result.outcome == lcm_link::AckOutcome::kTimeout)
      throw std::runtime_error("the node did not answer the ground's " + current_.what);
    done.push_back(current_);
  }

  const ConjunctionHilCase& c_;
  lcm_link::UplinkOptions o_;
  lcm_link::GroundKeys keys_;
  lcm_link::ArsnSource* arsn_;
  const lcm_link::ProposalRecorder& rec_;
  std::size_t next_cdm_ = 0;
  bool vetoed_ = false;
  std::future<lcm_link::UplinkResult> running_;
  HilUplink current_;
};

}  // namespace

ConjunctionHilRun run_conjunction_hil(const ConjunctionHilCase& c, const HilLinkOptions& o,
                                      const lcm_link::GroundKeys& keys, lcm_link::ArsnSource* arsn) {
  lcm_link::ProposalRecorder rec(o.lcm_url, o.uplink.proposal_channel, keys.telemetry);
  guidance_lcm::SigningKey sensor_key;
  if (!o.sensor_key_file.empty())
    sensor_key = lcm_link::load_signing_key(o.sensor_key_file, o.sensor_key_id, auth::KeyRole::kSensor);
  const std::unique_ptr<sim::GuidanceEndpoint> ep =
      lcm_link::make_lcm_endpoint(o.lcm_url, true, o.lcm_timeout_s, sensor_key);
  std::atomic<std::int64_t> clock{c.sim.utime0_us};
  lcm_link::UplinkOptions up = o.uplink;
  up.lcm_url = o.lcm_url;
  up.clock_utime = [&clock] { return clock.load(); };
  GroundScript ground(c, up, keys, arsn, rec);
  const auto wall0 = std::chrono::steady_clock::now();
  double t_now_s = 0.0;
  const auto hook = [&](long, std::int64_t utime) {
    clock.store(utime);
    t_now_s = 1e-6 * static_cast<double>(utime - c.sim.utime0_us);
    ground.on_cycle(t_now_s);
  };
  ConjunctionHilRun r;
  r.sim = sim::run_plan_simulation(c.sim, *ep, hook);
  ground.finish(t_now_s);
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  r.uplinks = ground.done;
  for (const lcm_link::ProposalRecorder::Change& ch : rec.changes())
    r.proposals.push_back({1e-6 * static_cast<double>(ch.utime - c.sim.utime0_us), ch.proposal});
  r.proposals_verified = rec.verified();
  r.proposals_ignored = rec.ignored();
  return r;
}

}  // namespace evade::hil
