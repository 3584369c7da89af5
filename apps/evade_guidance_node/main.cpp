// evade_guidance_node: the paper-000 close-range evasion guidance (guidance_law.hpp) as a
// real-time LCM node. Inputs evade_angles_t / evade_nav_state_t / evade_arm_t (and, with
// --lockstep, evade_sim_clock_t); outputs one evade_thrust_cmd_t per cycle and
// evade_guidance_status_t. Design and requirement IDs: docs/GUIDANCE_NODE.md.
// Exit codes: 0 normal stop (signal, --max-cycles, end of input) or --help/--version,
// 1 runtime failure, 2 bad input (flags or config, with the key, value and allowed range).
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>
#include <lcm/lcm.h>
#include <nlohmann/json.hpp>

#include "evade/auth/key_file.hpp"
#include "evade/autonomy/response.hpp"
#include "evade/config/scenario.hpp"
#include "evade/core/quantile.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"
#include "evade/guidance_lcm/lcm_url.hpp"
#include "node_loop.hpp"
#include "node_options.hpp"
#include "planning_worker.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_signal(int) { g_stop = 1; }

// Diagnostics go to stderr; a failed print there has no recovery (there is nowhere else to
// report it), so the results of these std::fprintf(stderr, ...) are discarded explicitly.

struct LcmDeleter {
  void operator()(lcm_t* l) const {
    if (l != nullptr) lcm_destroy(l);
  }
};
using LcmPtr = std::unique_ptr<lcm_t, LcmDeleter>;

LcmPtr open_lcm(const std::string& url) {
  LcmPtr l(lcm_create(url.empty() ? nullptr : url.c_str()));
  if (!l) throw std::runtime_error("cannot open LCM provider '" + url + "'");
  return l;
}

// The kernel caps SO_RCVBUF at net.core.rmem_max: say so when that is below the request, so
// that an operator knows bursts may be dropped before the node can count them (NODE-IN-6).
void warn_if_receive_buffer_capped(const std::string& url, int requested_bytes) {
  if (url.rfind("udpm://", 0) != 0) return;
  std::FILE* f = std::fopen("/proc/sys/net/core/rmem_max", "r");
  if (f == nullptr) return;
  char line[32] = {};
  const bool read = std::fgets(line, sizeof line, f) != nullptr;
  (void)std::fclose(f);  // opened read-only: nothing was written that a close failure could lose
  if (!read) return;
  char* end = nullptr;
  errno = 0;
  const long rmem_max = std::strtol(line, &end, 10);
  if (end == line || errno != 0) return;  // not a number: no warning rather than a wrong one
  if (rmem_max < requested_bytes) {
    (void)std::fprintf(stderr, "evade_guidance_node: warning: the kernel caps the UDP receive "
                       "buffer at %ld B (net.core.rmem_max) below the %d B requested "
                       "(node.recv_buf_bytes); a burst larger than it may be dropped by the "
                       "kernel, uncounted. Raise it with `sysctl -w net.core.rmem_max=%d`.\n",
                       rmem_max, requested_bytes, requested_bytes);
  }
}

void print_banner(const evade::node::NodeOptions& o, const evade::guidance_lcm::NodeConfig& c) {
  (void)std::fprintf(stderr,
                     "evade_guidance_node: %s at %.6g Hz, %s, max accel %.6g m/s^2, stale "
                     "%.6g s, %s\n", o.lockstep ? "lockstep" : "fixed rate", c.guidance.rate_hz,
                     o.lcm_url.empty() ? "default LCM URL" : o.lcm_url.c_str(),
                     c.guidance.max_accel_mps2, c.guidance.stale_limit_s,
                     c.guidance.armed ? "armed" : "disarmed");
}

void warn_about_auth(const evade::guidance_lcm::NodeConfig& c,
                     const evade::guidance_lcm::NodeSecurity& sec) {
  bool command_keys = false;
  for (std::size_t i = 0; i < sec.keys.size(); ++i) {
    command_keys = command_keys || sec.keys.entry(i).role == evade::auth::KeyRole::kCommand;
  }
  if ((c.auth.plan_required || c.auth.arm_required) && !command_keys) {
    (void)std::fprintf(stderr, "evade_guidance_node: no command key loaded (--keys): every plan "
                       "and arm command will be refused (docs/SECURITY.md)\n");
  }
  if (!c.auth.nav_required || !c.auth.angles_required || !c.auth.clock_required) {
    (void)std::fprintf(stderr, "evade_guidance_node: warning: sensor authentication is off "
                       "(--auth-sensors): any process that can reach the bus can feed the nav, "
                       "angles%s the law steers by; on a shared network run with "
                       "--auth-sensors required and sign the sensors (docs/SECURITY.md AUTH-3)\n",
                       c.lockstep ? " and the sim clock" : "");
  }
}

void print_summary(const evade::guidance_lcm::GuidanceNode& n, const char* why) {
  const auto& c = n.counts();
  const auto& cs = n.compute_stats();
  (void)std::fprintf(stderr,
                     "evade_guidance_node: stopped (%s) after %lld cycles; inputs %lld = consumed "
                     "%lld + rejected %lld + stale %lld + superseded %lld + dropped %lld + auth_failed "
                     "%lld + replayed %lld; seq gaps "
                     "%lld; watchdog cycles %lld; overruns %lld; cycle p50 %.1f us p99 %.1f us max "
                     "%.1f us\n",
                     why, static_cast<long long>(n.cycles()), static_cast<long long>(c.received),
                     static_cast<long long>(c.consumed), static_cast<long long>(c.rejected),
                     static_cast<long long>(c.stale), static_cast<long long>(c.superseded),
                     static_cast<long long>(c.dropped), static_cast<long long>(c.auth_failed),
                     static_cast<long long>(c.replayed), static_cast<long long>(c.seq_gaps),
                     static_cast<long long>(n.watchdog_cycles()),
                     static_cast<long long>(cs.overruns()), cs.quantile(0.5), cs.quantile(0.99),
                     cs.max_us());
}

nlohmann::json inputs_json(const evade::guidance_lcm::GuidanceNode& n) {
  const evade::guidance_lcm::InputCounts& c = n.counts();
  nlohmann::json j = {{"received", c.received},     {"consumed", c.consumed},
                      {"rejected", c.rejected},     {"stale", c.stale},
                      {"superseded", c.superseded}, {"dropped", c.dropped},
                      {"auth_failed", c.auth_failed}, {"replayed", c.replayed},
                      {"seq_gaps", c.seq_gaps},
                      {"identity", c.accounted() == c.received}};
  nlohmann::json reasons = nlohmann::json::object();
  for (int r = 1; r < static_cast<int>(evade::guidance_lcm::Reason::kCount); ++r) {
    if (c.by_reason[r] != 0)
      reasons[evade::guidance_lcm::reason_name(static_cast<evade::guidance_lcm::Reason>(r))] =
          c.by_reason[r];
  }
  j["by_reason"] = reasons;
  nlohmann::json per_input = nlohmann::json::object();
  for (const evade::guidance_lcm::InputRow& row : evade::guidance_lcm::kInputRows) {
    per_input[row.name] = n.received(row.input);
  }
  j["received_by_input"] = per_input;
  return j;
}

// docs/SECURITY.md "What an operator watches": the policy, each key's state (never its
// bytes) and the authentication counters.
nlohmann::json auth_json(const evade::guidance_lcm::GuidanceNode& n) {
  using evade::auth::KeyState;
  const auto& a = n.config().auth;
  nlohmann::json keys = nlohmann::json::array();
  for (std::size_t i = 0; i < n.keys().size(); ++i) {
    const auto& e = n.keys().entry(i);
    const char* st = e.state == KeyState::kActive    ? "active"
                     : e.state == KeyState::kStandby ? "standby"
                                                     : "retired";
    nlohmann::json k = {{"id", e.id}, {"role", evade::auth::role_name(e.role)}, {"state", st}};
    if (e.role == evade::auth::KeyRole::kCommand) {
      k["command_arsn"] = e.arsn[static_cast<std::size_t>(evade::auth::ArsnSlot::kCommand)];
    }
    keys.push_back(k);
  }
  const auto& c = n.counts();
  using evade::guidance_lcm::Reason;
  nlohmann::json reasons = nlohmann::json::object();
  for (Reason r : {Reason::kUnsigned, Reason::kUnknownKey, Reason::kBadMac, Reason::kStandbyKey,
                   Reason::kRetiredKey, Reason::kWrongKeyRole, Reason::kTooShortForTrailer,
                   Reason::kReplayedArsn, Reason::kVerifyBudget, Reason::kNotPersisted,
                   Reason::kInboxFull}) {
    reasons[evade::guidance_lcm::reason_name(r)] = c.by_reason[static_cast<int>(r)];
  }
  nlohmann::json required = nlohmann::json::object();
  for (const evade::guidance_lcm::InputRow& row : evade::guidance_lcm::kInputRows) {
    required[row.name] = evade::guidance_lcm::input_required(row, a) ? "required" : "off";
  }
  return {{"required", required},
          {"keys", keys},
          {"active_command_keys", n.keys().active_command_keys()},
          {"auth_failed", c.auth_failed},
          {"replayed", c.replayed},
          {"by_reason", reasons},
          {"state_persist_failures", n.auth_persist_failures()},
          {"telemetry_key", n.keys().telemetry_key() != nullptr ? n.keys().telemetry_key()->id : 0},
          {"acks_published", n.acks_published()},
          {"acks_unsent", n.acks_unsent()}};
}

nlohmann::json stats_json(const evade::guidance_lcm::GuidanceNode& n, bool lockstep,
                          const evade::node::LoopResult& res) {
  const auto& cs = n.compute_stats();
  const auto& ws = n.wakeup_stats();
  nlohmann::json j;
  j["mode"] = lockstep ? "lockstep" : "fixed_rate";
  j["rate_hz"] = n.config().guidance.rate_hz;
  j["cycles"] = n.cycles();
  j["overruns"] = cs.overruns();
  if (lockstep) j["cycles_over_period"] = res.over_period;  // no deadline there: not overruns
  j["inputs"] = inputs_json(n);
  j["watchdog_cycles"] = n.watchdog_cycles();
  j["compute_us"] = {{"p50_last_1024", cs.quantile(0.5)},
                     {"p99_last_1024", cs.quantile(0.99)},
                     {"max", cs.max_us()}};
  if (!res.wakeup_us.empty()) {
    j["wakeup_latency_us"] = {{"samples", res.wakeup_us.size()},
                              {"p50", evade::nearest_rank_quantile(res.wakeup_us, 0.5)},
                              {"p99", evade::nearest_rank_quantile(res.wakeup_us, 0.99)},
                              {"p999", evade::nearest_rank_quantile(res.wakeup_us, 0.999)},
                              {"max", evade::nearest_rank_quantile(res.wakeup_us, 1.0)}};
  } else {
    j["wakeup_latency_us"] = {{"p50_last_1024", ws.quantile(0.5)},
                              {"p99_last_1024", ws.quantile(0.99)},
                              {"max", ws.max_us()}};
  }
  j["auth"] = auth_json(n);
  const auto& ps = n.plan_executor().status();
  j["dv_used_mps"] = n.law().status().dv_used_mps;
  j["plan"] = {{"accepted", ps.accepted},
               {"dv_total_mps", ps.dv_total_mps},
               {"ack_id", n.last_status().plan_ack_id},
               {"ack_result", n.last_status().plan_ack_result}};
  const evade::autonomy::ResponderCounters& ac = n.responder().counters();
  j["autonomy"] = {{"policy", evade::autonomy::policy_name(n.responder().policy())},
                   {"events_tracked", ac.events_tracked},
                   {"events_replaced", ac.events_replaced},
                   {"events_again", ac.events_again},
                   {"events_refused", ac.events_bad + ac.events_not_newer + ac.events_table_full},
                   {"decisions_applied", ac.decisions_applied},
                   {"decisions_again", ac.decisions_again},
                   {"decisions_refused", ac.decisions_refused},
                   {"proposals", ac.proposals},
                   {"burns_loaded", ac.schedules},
                   {"burns_cancelled", ac.cancels},
                   {"planning_jobs", ac.jobs},
                   {"planning_us_last", n.last_planning_us()},
                   {"planning_us_max", n.max_planning_us()}};
  j["exit_reason"] = res.why;
  return j;
}

// SIGINT and SIGTERM set g_stop (the loops' clean stop). Throws if the kernel refuses, since
// the node could then not be stopped cleanly.
void install_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  if (sigemptyset(&sa.sa_mask) != 0 || sigaction(SIGINT, &sa, nullptr) != 0 ||
      sigaction(SIGTERM, &sa, nullptr) != 0)
    throw std::runtime_error("cannot install the SIGINT/SIGTERM handlers");
}

// Opens LCM, runs the loop until it stops, reports. Returns the exit code.
int run_node(const evade::node::NodeOptions& opts, const evade::guidance_lcm::NodeConfig& cfg,
             const evade::guidance_lcm::NodeSecurity& sec) {
  using namespace evade;
  const std::string in_url = guidance_lcm::lcm_url_with_recv_buf(
      opts.lcm_url, std::getenv("LCM_DEFAULT_URL"), static_cast<std::size_t>(cfg.recv_buf_bytes));
  warn_if_receive_buffer_capped(in_url, cfg.recv_buf_bytes);
  LcmPtr in = open_lcm(in_url);
  LcmPtr out;
  if (!opts.out_lcm_url.empty()) out = open_lcm(opts.out_lcm_url);
  warn_about_auth(cfg, sec);
  guidance_lcm::GuidanceNode nodecore(in.get(), cfg, out.get(), sec);
  install_signal_handlers();
  node::PlanningWorker worker(nodecore);  // before SCHED_FIFO: the worker stays below the cycle
  // try_realtime says on stderr what was refused; the node runs on without it, by design.
  if (opts.realtime) (void)node::try_realtime(opts.rt_priority);
  if (!opts.quiet) print_banner(opts, cfg);
  node::LoopLimits lim;
  lim.max_cycles = opts.max_cycles;
  lim.idle_exit_s = opts.idle_exit_s;
  lim.progress = !opts.quiet;
  lim.input_is_log = opts.lcm_url.rfind("file://", 0) == 0;
  const node::LoopResult res =
      opts.lockstep ? node::run_lockstep(nodecore, cfg.guidance.rate_hz, lim, &g_stop)
                    : node::run_fixed_rate(nodecore, cfg.guidance.rate_hz, lim, &g_stop);
  nodecore.stop();  // what is still queued is counted (NODE-IN-1) before the report
  if (!opts.quiet) print_summary(nodecore, res.why);
  if (opts.stats_json &&
      std::printf("%s\n", stats_json(nodecore, opts.lockstep, res).dump(2).c_str()) < 0)
    throw std::runtime_error("cannot write the --stats-json report to stdout");
  return res.exit_code;
}

int node_main(int argc, char** argv) {
  using namespace evade;
  node::NodeOptions opts;
  CLI::App app{"evade_guidance_node: paper-000 close-range evasion guidance over LCM",
               "evade_guidance_node"};
  app.set_version_flag("--version", std::string("evade_guidance_node ") + EVADE_VERSION);
  node::add_options(app, opts);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  guidance_lcm::NodeConfig cfg;
  guidance_lcm::NodeSecurity sec;
  try {  // a bad key file or auth state is bad input too: exit 2, naming the file
    cfg = node::make_node_config(opts);
    sec = node::make_node_security(opts, cfg);
  } catch (const std::exception& e) {
    (void)std::fprintf(stderr, "evade_guidance_node: invalid input: %s\n", e.what());
    return 2;
  }
  try {
    return run_node(opts, cfg, sec);
  } catch (const std::invalid_argument& e) {
    (void)std::fprintf(stderr, "evade_guidance_node: invalid input: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    (void)std::fprintf(stderr, "evade_guidance_node: failed: %s\n", e.what());
    return 1;
  }
}

}  // namespace

// Nothing escapes main: an exception from the option parser's setup (e.g. std::bad_alloc) is
// reported and is a runtime failure (exit 1), not std::terminate.
int main(int argc, char** argv) {
  try {
    return node_main(argc, argv);
  } catch (const std::exception& e) {
    (void)std::fprintf(stderr, "evade_guidance_node: failed: %s\n", e.what());
  } catch (...) {
    (void)std::fprintf(stderr, "evade_guidance_node: failed: unknown exception\n");
  }
  return 1;
}
