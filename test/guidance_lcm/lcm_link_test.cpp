// Two-process tests over real LCM (UDP multicast) inside a private network namespace
// (`unshare -rn`, loopback only, ttl=0: no packet can leave this machine):
//  - NODE-LS-1: paper 000 seed0 (1 m/s^2, detection 10 s before the closest approach) run by
//    `evade sim` with evade_guidance_node as a separate process in lockstep gives the same
//    miss as the in-process run to 1 um (in fact bit for bit: the doubles cross LCM exactly).
//  - NODE-LS-2: the same HIL run recorded with lcm-logger and played back into the node
//    (file:// provider, lockstep) reproduces the recorded commands byte for byte.
// Skipped (GTEST_SKIP, with the reason) only if unshare is not permitted on this machine.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>

#include "evade/evade_arm_t.hpp"
#include "evade/evade_thrust_cmd_t.hpp"
#include "evade/guidance_lcm/channels.hpp"

namespace {

const char* kPaperMissM = "50.0021";  // paper 000 Table 2, 10 s, 1 m/s^2

std::string make_temp_dir() {
  const char* base = std::getenv("TMPDIR");
  std::string tmpl = std::string(base ? base : "/tmp") + "/evade_glcm_XXXXXX";
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  if (mkdtemp(buf.data()) == nullptr) return "";
  return std::string(buf.data());
}

bool unshare_permitted() {
  return std::system("unshare -rn sh -c 'ip link set lo up && ip link set lo multicast on && "
                     "ip route add 224.0.0.0/4 dev lo' >/dev/null 2>&1") == 0;
}

int run(const std::string& cmd) { return std::system(cmd.c_str()); }

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  nlohmann::json j;
  f >> j;
  return j;
}

// Writes the namespace script: optional logger, node in lockstep, sim over LCM.
std::string write_script(const std::string& dir, bool record, int realtime_factor = 10) {
  const std::string p = dir + "/run.sh";
  std::ofstream s(p);
  s << "set -e\n"
       "ip link set lo up; ip link set lo multicast on; ip route add 224.0.0.0/4 dev lo\n"
       // A lockstep run is a burst (~10^4 messages/s): give every socket a receive buffer
       // up to the kernel's rmem_max so lcm-logger does not lose datagrams.
       "URL='udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304'\n"
       "D='" << dir << "'\n";
  if (record) {
    // lcm-logger 1.3.1 does not accept the short -l: use --lcm-url=.
    s << "lcm-logger -f -q --lcm-url=\"$URL\" \"$D/hil.lcmlog\" &\nLOG=$!\nsleep 0.5\n";
  }
  s << "'" << EVADE_NODE_PATH << "' --lcm-url \"$URL\" --lockstep --scenario seed0 "
       "--max-accel-mps2 1 --idle-exit-s 20 --stats-json > \"$D/node.json\" 2> \"$D/node.err\" &\n"
       "NODE=$!\n"
       // The sim only once the node's banner says every input is subscribed: LCM's udpm
       // receiver drops a datagram on a channel not yet subscribed (GUIDANCE_NODE.md "Known
       // pitfalls"). Bounded: 500 polls of 20 ms.
       "i=0; until grep -q 'evade_guidance_node: lockstep' \"$D/node.err\"; do\n"
       "  i=$((i+1)); [ $i -lt 500 ] || { echo 'no node banner' >&2; exit 3; }; sleep 0.02; done\n"
       << (record ? "EVADE_SIM_LCM_REALTIME_FACTOR=" + std::to_string(realtime_factor) + " " : "") << "'" << EVADE_CLI_PATH << "' sim --scenario seed0 --accel 1 --detect 10 --lcm \"$URL\" "
       "--lcm-timeout-s 10 --json > \"$D/sim_lcm.json\"\n"
       "kill -TERM $NODE; wait $NODE\n";
  if (record) s << "sleep 0.3\nkill -INT $LOG; wait $LOG || true\n";
  return p;
}

std::vector<std::vector<std::uint8_t>> commands_in_log(const std::string& path, int* other) {
  std::vector<std::vector<std::uint8_t>> out;
  lcm::LogFile log(path, "r");
  if (!log.good()) return out;
  *other = 0;
  while (const lcm::LogEvent* e = log.readNextEvent()) {
    if (e->channel == evade::guidance_lcm::kChanCmd) {
      const auto* b = static_cast<const std::uint8_t*>(e->data);
      out.emplace_back(b, b + e->datalen);
    } else {
      ++*other;
    }
  }
  return out;
}

TEST(LcmLink, Seed0OverLcmMatchesInProcessToOneMicrometre) {
  if (!unshare_permitted()) {
    GTEST_SKIP() << "unshare -rn is not permitted here (no user namespaces): the two-process "
                    "LCM test runs only inside a private network namespace";
  }
  const std::string dir = make_temp_dir();
  ASSERT_FALSE(dir.empty());
  ASSERT_EQ(run(std::string("'") + EVADE_CLI_PATH +
                "' sim --scenario seed0 --accel 1 --detect 10 --json > '" + dir +
                "/sim_inproc.json'"),
            0);
  ASSERT_EQ(run("unshare -rn sh '" + write_script(dir, false) + "'"), 0);
  const nlohmann::json inproc = read_json(dir + "/sim_inproc.json");
  const nlohmann::json lcm = read_json(dir + "/sim_lcm.json");
  const nlohmann::json node = read_json(dir + "/node.json");
  const double miss_in = inproc["miss_m"].get<double>();
  const double miss_lcm = lcm["miss_m"].get<double>();
  std::printf("seed0, 1 m/s^2, 10 s: miss in-process %.6f m, over LCM %.6f m, paper %s m\n",
              miss_in, miss_lcm, kPaperMissM);
  EXPECT_EQ(lcm["guidance"], "lcm");
  // 1 um: the requirement. The doubles cross LCM bit-exactly and the node runs the same law
  // on the same inputs, so the difference is in fact zero.
  EXPECT_NEAR(miss_lcm, miss_in, 1e-6);
  EXPECT_EQ(lcm["cycles"], inproc["cycles"]);
  EXPECT_EQ(node["cycles"], lcm["cycles"]) << "one node cycle per sim tick";
  const auto& in = node["inputs"];
  EXPECT_EQ(in["received"].get<long>(),
            in["consumed"].get<long>() + in["rejected"].get<long>() + in["stale"].get<long>() +
                in["superseded"].get<long>() + in["dropped"].get<long>());
  EXPECT_EQ(in["rejected"].get<long>(), 0);
  run("rm -rf '" + dir + "'");
}

TEST(LcmLink, RecordedHilRunReplaysToIdenticalCommands) {
  if (!unshare_permitted()) {
    GTEST_SKIP() << "unshare -rn is not permitted here (no user namespaces): the record/replay "
                    "test records a two-process run inside a private network namespace";
  }
  const std::string dir = make_temp_dir();
  ASSERT_FALSE(dir.empty());
  // Recording: lcm-logger is a separate UDP receiver; on a loaded machine it can be starved
  // and lose datagrams (UDP gives no back-pressure). A complete recording is a precondition
  // of the replay check, not the property under test, so an incomplete one is re-recorded
  // more slowly (10x, 4x, then 1x real time). The replay check below stays exact.
  long sim_cycles = -1;
  std::size_t recorded = 0;
  for (int factor : {10, 4, 1}) {
    ASSERT_EQ(run("unshare -rn sh '" + write_script(dir, true, factor) + "'"), 0);
    int other = 0;
    recorded = commands_in_log(dir + "/hil.lcmlog", &other).size();
    sim_cycles = read_json(dir + "/sim_lcm.json")["cycles"].get<long>();
    if (static_cast<long>(recorded) == sim_cycles) break;
    std::printf("lcm-logger recorded %zu of %ld commands at %dx real time: re-recording slower\n",
                recorded, sim_cycles, factor);
  }
  // Replay: the node reads the recorded inputs from the log (file://, as fast as possible)
  // and writes its commands to a second log.
  ASSERT_EQ(run(std::string("'") + EVADE_NODE_PATH + "' --lcm-url 'file://" + dir +
                "/hil.lcmlog?speed=0' --out-lcm-url 'file://" + dir +
                "/replay.lcmlog?mode=w' --lockstep --scenario seed0 --max-accel-mps2 1 --quiet"),
            0);
  int other_hil = 0;
  int other_replay = 0;
  const auto hil = commands_in_log(dir + "/hil.lcmlog", &other_hil);
  const auto replay = commands_in_log(dir + "/replay.lcmlog", &other_replay);
  const nlohmann::json sim = read_json(dir + "/sim_lcm.json");
  ASSERT_EQ(static_cast<long>(hil.size()), sim["cycles"].get<long>())
      << "lcm-logger lost datagrams even at 1x real time";
  EXPECT_GT(other_hil, 3 * static_cast<int>(hil.size()) - 1)
      << "nav, angles, clock and status recorded too";
  ASSERT_EQ(replay.size(), hil.size());
  int differing = 0;
  for (std::size_t i = 0; i < hil.size(); ++i) differing += (hil[i] != replay[i]) ? 1 : 0;
  EXPECT_EQ(differing, 0) << "replayed commands must equal the recorded ones byte for byte";
  // And the commands are real: the run evaded.
  int thrusting = 0;
  for (const auto& b : replay) {
    evade::evade_thrust_cmd_t m{};
    ASSERT_EQ(m.decode(b.data(), 0, static_cast<int>(b.size())), static_cast<int>(b.size()));
    thrusting += m.accel_mps2 > 0.0 ? 1 : 0;
    if (std::getenv("EVADE_DEBUG")) std::printf("cmd seq %ld utime %ld mode %d accel %g\n", (long)m.seq, (long)m.utime, m.mode, m.accel_mps2);
  }
  EXPECT_GT(thrusting, 400);
  if (std::getenv("EVADE_DEBUG")) std::printf("kept %s\n", dir.c_str());
  else run("rm -rf '" + dir + "'");
}

}  // namespace

namespace {

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// Bad flags: exit 2 with the flag, value and range named (NODE-RT-2).
TEST(NodeCli, BadFlagsExitTwoNamingTheFlag) {
  const std::string dir = make_temp_dir();
  ASSERT_FALSE(dir.empty());
  const int rc = run(std::string("'") + EVADE_NODE_PATH +
                     "' --lcm-url memq:// --rate-hz nan 2> '" + dir + "/err.txt'");
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  EXPECT_NE(slurp(dir + "/err.txt").find("--rate-hz"), std::string::npos);
  const int rc2 = run(std::string("'") + EVADE_NODE_PATH +
                      "' --lcm-url memq:// --max-accel-mps2 -1 2> '" + dir + "/err2.txt'");
  ASSERT_TRUE(WIFEXITED(rc2));
  EXPECT_EQ(WEXITSTATUS(rc2), 2);
  EXPECT_NE(slurp(dir + "/err2.txt").find("(0, 100]"), std::string::npos);
  run("rm -rf '" + dir + "'");
}

// The end of a file:// log is the end of input in the fixed-rate mode too: exit 0 (it
// used to exit 1 with "LCM receive error") after consuming the log's messages.
TEST(NodeCli, EndOfLogExitsCleanlyInFixedRateMode) {
  const std::string dir = make_temp_dir();
  ASSERT_FALSE(dir.empty());
  {
    lcm::LCM log("file://" + dir + "/in.lcmlog?mode=w");
    ASSERT_TRUE(log.good());
    for (int k = 1; k <= 20; ++k) {
      evade::evade_arm_t arm{};
      arm.utime = 1000 * k;
      arm.seq = k;
      arm.armed = true;
      ASSERT_EQ(log.publish(evade::guidance_lcm::kChanArm, &arm), 0);
    }
  }
  const int rc = run(std::string("'") + EVADE_NODE_PATH + "' --lcm-url 'file://" + dir +
                     "/in.lcmlog?speed=0' --rate-hz 100 --stats-json > '" + dir +
                     "/out.json' 2> '" + dir + "/err.txt'");
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 0) << slurp(dir + "/err.txt");
  const nlohmann::json j = read_json(dir + "/out.json");
  EXPECT_EQ(j["exit_reason"], "end of LCM input");
  EXPECT_EQ(j["inputs"]["received"].get<long>(), 20);
  run("rm -rf '" + dir + "'");
}

// SIGTERM ends the fixed-rate loop cleanly: exit 0 and the summary (NODE-RT-4).
TEST(NodeCli, SigtermExitsCleanly) {
  const std::string dir = make_temp_dir();
  ASSERT_FALSE(dir.empty());
  const int rc = run("sh -c \"'" + std::string(EVADE_NODE_PATH) +
                     "' --lcm-url memq:// --rate-hz 100 --stats-json > '" + dir +
                     "/out.json' 2> '" + dir + "/err.txt' & p=\\$!; sleep 0.5; kill -TERM \\$p; "
                     "wait \\$p\"");
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 0);
  const nlohmann::json j = read_json(dir + "/out.json");
  EXPECT_EQ(j["exit_reason"], "signal");
  EXPECT_GT(j["cycles"].get<long>(), 10);
  run("rm -rf '" + dir + "'");
}

// --realtime without the privilege (an unprivileged user namespace cannot get SCHED_FIFO
// on the host) says so on stderr and the node still runs (NODE-RT-4).
TEST(NodeCli, RealtimeRefusedIsReportedAndNodeContinues) {
  const std::string dir = make_temp_dir();
  ASSERT_FALSE(dir.empty());
  const bool userns = std::system("unshare -r true >/dev/null 2>&1") == 0;
  const std::string prefix = userns ? "unshare -r " : "";
  const int rc = run(prefix + "'" + EVADE_NODE_PATH +
                     "' --lcm-url memq:// --rate-hz 200 --max-cycles 20 --realtime 2> '" + dir +
                     "/err.txt'");
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 0);
  const std::string err = slurp(dir + "/err.txt");
  EXPECT_NE(err.find("after 20 cycles"), std::string::npos) << err;
  if (err.find("refused") != std::string::npos) {
    EXPECT_NE(err.find("continuing"), std::string::npos) << err;
  } else {
    std::printf("note: SCHED_FIFO and mlockall were granted here; refusal path not exercised\n");
  }
  run("rm -rf '" + dir + "'");
}

}  // namespace
