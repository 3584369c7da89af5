// udpm_latency_stages: where the measurement -> command time over udpm goes, stage by stage
// (docs/PERFORMANCE.md "Measurement -> command latency over LCM"). Two processes exactly as
// node_bench's BM_MeasToCmdUdpm: a client publishes nav, angles and a lockstep tick, the node
// (evade::guidance_lcm::GuidanceNode in the loop of evade_guidance_node --lockstep:
// wait_for_tick, then run_cycle) answers with a command. Every stage is stamped with
// CLOCK_REALTIME, one clock for both processes on this machine:
//   c0  client: before encoding nav            c1  client: tick published (3 sendmsg done)
//   n2  kernel stamp of the tick at the node's socket (SO_TIMESTAMP, LCM's rbuf->recv_utime)
//   n3  node: LCM's receive thread has the tick (its recvmsg returned)
//   n4  node: main thread dispatches the tick (lcm_handle -> handler)
//   n5  node: the command's sendmsg starts (cycle done: drain, validate, law, encode)
//   n6  node: the command's sendmsg returned
//   c7  kernel stamp of the command at the client's socket
//   c8  client: LCM's receive thread has the command     c9  client: handler dispatched
// n3, n5, n6, c8 come from recvmsg/sendmsg defined in this executable, which LCM's shared
// library calls instead of libc's (the calls go straight to the kernel with syscall(2)).
//   udpm_latency_stages node URL OUT_URL CSV              (exits after 3 s without a tick)
//   udpm_latency_stages client URL OUT_URL N WAIT CSV     WAIT = handle | select | spin
//   udpm_latency_stages report NODE_CSV CLIENT_CSV
// OUT_URL: where the node publishes (and the client listens); "-" = URL.
#include <sys/select.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <lcm/lcm.h>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"

namespace {

std::int64_t now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// Channels whose datagrams the interposed calls stamp (set once before LCM starts).
const char* g_recv_chan = nullptr;
const char* g_send_chan = nullptr;
std::atomic<std::int64_t> g_recv_ns{0};
std::int64_t g_send_begin_ns = 0, g_send_end_ns = 0;  // main thread only

}  // namespace

// LCM's receive thread reads each datagram with recvmsg: stamp the watched channel's arrival
// in user space. An LCM short datagram is an 8-byte header, then the channel name.
extern "C" ssize_t recvmsg(int fd, struct msghdr* msg, int flags) {
  const long n = syscall(SYS_recvmsg, fd, msg, flags);
  if (n > 8 && g_recv_chan != nullptr && msg->msg_iovlen >= 1) {
    const char* b = static_cast<const char*>(msg->msg_iov[0].iov_base);
    if (std::strncmp(b + 8, g_recv_chan, static_cast<std::size_t>(n - 8)) == 0)
      g_recv_ns.store(now_ns(), std::memory_order_release);
  }
  return n;
}

// LCM publishes a short message as sendmsg(header, channel, payload).
extern "C" ssize_t sendmsg(int fd, const struct msghdr* msg, int flags) {
  const bool watched = g_send_chan != nullptr && msg->msg_iovlen >= 2 &&
                       std::strcmp(static_cast<const char*>(msg->msg_iov[1].iov_base),
                                   g_send_chan) == 0;
  if (watched) g_send_begin_ns = now_ns();
  const long n = syscall(SYS_sendmsg, fd, msg, flags);
  if (watched) g_send_end_ns = now_ns();
  return n;
}

namespace {

using namespace evade;
using namespace evade::guidance_lcm;

struct LcmDeleter {
  void operator()(lcm_t* l) const { lcm_destroy(l); }
};
using LcmPtr = std::unique_ptr<lcm_t, LcmDeleter>;

// ---- node ---------------------------------------------------------------------------------

struct TickStamp {
  std::int64_t tick_utime = 0, kernel_us = 0, disp_ns = 0;
  static void on_tick(const lcm_recv_buf_t* rbuf, const char*, void* user) {
    auto* self = static_cast<TickStamp*>(user);
    evade_sim_clock_t tick{};
    if (tick.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) <= 0) return;
    self->disp_ns = now_ns();
    self->tick_utime = tick.utime;
    self->kernel_us = rbuf->recv_utime;
  }
};

int run_node(const std::string& url, const std::string& out_url, const std::string& csv) {
  g_recv_chan = kChanClock;
  g_send_chan = kChanCmd;
  LcmPtr in(lcm_create(url.c_str()));
  LcmPtr out(out_url == "-" ? nullptr : lcm_create(out_url.c_str()));
  if (!in || (out_url != "-" && !out)) return 1;
  NodeConfig cfg;
  cfg.lockstep = true;
  cfg.guidance.stale_limit_s = 60.0;
  GuidanceNode node(in.get(), cfg, out.get());
  TickStamp ts;
  lcm_subscribe(in.get(), kChanClock, &TickStamp::on_tick, &ts);  // after the node's own
  std::ofstream f(csv);
  f << "tick_utime,n2_kernel_us,n3_recv_ns,n4_disp_ns,n5_send_ns,n6_sent_ns\n";
  std::int64_t idle_since = now_ns();
  while (now_ns() - idle_since < 3000000000LL) {
    std::int64_t tick_utime = 0;
    const int rc = node.wait_for_tick(100, &tick_utime);
    if (rc < 0) return 1;
    if (rc == 0) continue;
    node.run_cycle(tick_utime);
    f << ts.tick_utime << ',' << ts.kernel_us << ',' << g_recv_ns.load() << ',' << ts.disp_ns
      << ',' << g_send_begin_ns << ',' << g_send_end_ns << '\n';
    idle_since = now_ns();
  }
  return 0;
}

// ---- client -------------------------------------------------------------------------------

// As node_bench.cpp: a closing encounter so the law tracks and evades every cycle.
void inputs_at(std::int64_t t_us, std::int64_t seq, evade_nav_state_t* nav, evade_angles_t* a) {
  const double t = 1e-6 * static_cast<double>(t_us % 5000000);
  const Vec3 rel = Vec3(0.0, 10000.0, 2000.0) + Vec3(0.0, -1000.0, -150.0) * t;
  const guidance::LosAngles ang = guidance::los_angles_from_unit(rel.normalized());
  *nav = evade_nav_state_t{};
  nav->utime = t_us;
  nav->seq = seq;
  nav->valid = true;
  nav->r_eci_m[0] = 7.0e6;
  nav->r_eci_m[1] = 7546.0 * t;
  nav->v_eci_mps[1] = 7546.0;
  *a = evade_angles_t{};
  a->utime = t_us;
  a->seq = seq;
  a->valid = true;
  a->elevation_rad = ang.elevation_rad;
  a->azimuth_rad = ang.azimuth_rad;
  a->sigma_angle_rad = 1e-4;
}

struct CmdStamp {
  std::int64_t want_utime = -1, kernel_us = 0, disp_ns = 0;
  bool got = false;
  static void on_cmd(const lcm_recv_buf_t* rbuf, const char*, void* user) {
    auto* self = static_cast<CmdStamp*>(user);
    evade_thrust_cmd_t m{};
    if (m.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) <= 0 ||
        m.utime != self->want_utime)
      return;
    self->disp_ns = now_ns();
    self->kernel_us = rbuf->recv_utime;
    self->got = true;
  }
};

// One wait for the command: lcm_handle_timeout (what node_bench does), select() on LCM's fd
// then lcm_handle, or spinning on lcm_handle_timeout(0). False after 1 s without it.
bool wait_cmd(lcm_t* lcm, const std::string& how, const CmdStamp& w) {
  const std::int64_t end = now_ns() + 1000000000LL;
  while (!w.got && now_ns() < end) {
    if (how == "handle") {
      if (lcm_handle_timeout(lcm, 1000) < 0) return false;
    } else if (how == "spin") {
      if (lcm_handle_timeout(lcm, 0) < 0) return false;
    } else {
      const int fd = lcm_get_fileno(lcm);
      fd_set fds;
      FD_ZERO(&fds);
      FD_SET(fd, &fds);
      timeval tv{1, 0};
      if (select(fd + 1, &fds, nullptr, nullptr, &tv) > 0 && lcm_handle(lcm) != 0) return false;
    }
  }
  return w.got;
}

int run_client(const std::string& url, const std::string& out_url, long n, const std::string& how,
               const std::string& csv) {
  g_recv_chan = kChanCmd;
  LcmPtr pub(lcm_create(url.c_str()));
  LcmPtr sub_lcm(out_url == "-" ? nullptr : lcm_create(out_url.c_str()));
  lcm_t* rx = out_url == "-" ? pub.get() : sub_lcm.get();
  if (!pub || rx == nullptr) return 1;
  CmdStamp w;
  lcm_subscribe(rx, kChanCmd, &CmdStamp::on_cmd, &w);
  std::ofstream f(csv);
  f << "utime,c0_ns,c1_ns,c7_kernel_us,c8_recv_ns,c9_disp_ns\n";
  std::uint8_t buf[512];
  std::int64_t t = 1000000;
  long timeouts = 0;
  for (long i = 1; i <= n; ++i, t += 20000) {
    evade_nav_state_t nav;
    evade_angles_t a;
    inputs_at(t, i, &nav, &a);
    evade_sim_clock_t tick{};
    tick.utime = t;
    tick.seq = i;
    w.want_utime = t;
    w.got = false;
    const std::int64_t c0 = now_ns();
    int len = nav.encode(buf, 0, sizeof(buf));
    lcm_publish(pub.get(), kChanNav, buf, static_cast<unsigned>(len));
    len = a.encode(buf, 0, sizeof(buf));
    lcm_publish(pub.get(), kChanAngles, buf, static_cast<unsigned>(len));
    len = tick.encode(buf, 0, sizeof(buf));
    lcm_publish(pub.get(), kChanClock, buf, static_cast<unsigned>(len));
    const std::int64_t c1 = now_ns();
    if (!wait_cmd(rx, how, w)) {
      ++timeouts;
      continue;
    }
    f << t << ',' << c0 << ',' << c1 << ',' << w.kernel_us << ',' << g_recv_ns.load() << ','
      << w.disp_ns << '\n';
  }
  std::fprintf(stderr, "udpm_latency_stages: %ld round trips, %ld timeouts\n", n, timeouts);
  return timeouts == 0 ? 0 : 1;
}

// ---- report -------------------------------------------------------------------------------

std::vector<std::vector<std::int64_t>> read_csv(const std::string& path) {
  std::vector<std::vector<std::int64_t>> rows;
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  while (std::getline(f, line)) {
    std::vector<std::int64_t> r;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) r.push_back(std::stoll(c));
    rows.push_back(r);
  }
  return rows;
}

void print_stage(const char* name, std::vector<double> v) {
  if (v.empty()) return;
  std::sort(v.begin(), v.end());
  auto q = [&](double p) { return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))]; };
  std::printf("| %s | %.1f | %.1f | %.1f |\n", name, q(0.5), q(0.99), v.back());
}

int report(const std::string& node_csv, const std::string& client_csv) {
  std::map<std::int64_t, std::vector<std::int64_t>> node;
  for (auto& r : read_csv(node_csv))
    if (r.size() == 6) node[r[0]] = r;
  // Stage durations in µs; kernel stamps are µs, the rest ns.
  std::vector<std::vector<double>> st(10);
  for (auto& c : read_csv(client_csv)) {
    auto it = node.find(c[0]);
    if (c.size() != 6 || it == node.end()) continue;
    const auto& nd = it->second;
    const double c0 = c[1] * 1e-3, c1 = c[2] * 1e-3, c7 = static_cast<double>(c[3]),
                 c8 = c[4] * 1e-3, c9 = c[5] * 1e-3, n2 = static_cast<double>(nd[1]),
                 n3 = nd[2] * 1e-3, n4 = nd[3] * 1e-3, n5 = nd[4] * 1e-3, n6 = nd[5] * 1e-3;
    const double v[9] = {c1 - c0, c1 - n2, n3 - c1, n4 - n3, n5 - n4, n6 - n5, c8 - n6, c9 - c8,
                         c9 - c0};
    for (int k = 0; k < 9; ++k) st[static_cast<std::size_t>(k)].push_back(v[k]);
    st[9].push_back(c8 - c7);
  }
  std::printf("%zu round trips joined\n\n| stage | p50 µs | p99 µs | max µs |\n|---|---|---|---|\n",
              st[0].size());
  const char* names[10] = {
      "A client: encode + publish nav, angles, tick (3 sendmsg, loopback delivery included)",
      "(check) tick's sendmsg returned - its SO_TIMESTAMP at the node",
      "B tick sent -> node's LCM receive thread has it (wake-up + recvmsg)",
      "C node receive thread -> main thread dispatches the tick (notify pipe + wake-up)",
      "D node cycle: drain, validate, law step, encode (dispatch -> command sendmsg)",
      "E node: command sendmsg (loopback delivery to the client's socket included)",
      "F command sent -> client's LCM receive thread has it (wake-up + recvmsg)",
      "G client receive thread -> main thread dispatches the command",
      "total: client start -> command dispatched",
      "(check) client recvmsg return - the command's SO_TIMESTAMP"};
  for (int k = 0; k < 10; ++k) print_stage(names[k], st[static_cast<std::size_t>(k)]);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string role = argc > 1 ? argv[1] : "";
  if (role == "node" && argc == 5) return run_node(argv[2], argv[3], argv[4]);
  if (role == "client" && argc == 7) {
    const long n = std::atol(argv[4]);
    const std::string how = argv[5];
    if (n > 0 && (how == "handle" || how == "select" || how == "spin"))
      return run_client(argv[2], argv[3], n, how, argv[6]);
  }
  if (role == "report" && argc == 4) return report(argv[2], argv[3]);
  std::fprintf(stderr, "usage: udpm_latency_stages node URL OUT_URL CSV | client URL OUT_URL N "
                       "handle|select|spin CSV | report NODE_CSV CLIENT_CSV\n");
  return 2;
}
