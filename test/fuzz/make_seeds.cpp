// Writes the seed corpus of the binary fuzz harnesses (the LCM input harnesses and the
// plan-validation harness) into test/fuzz/corpus/<harness>/: messages encoded with the
// lcm-gen types in the framing of lcm_input_harness.hpp, meaningful cases (valid and newer,
// duplicate, out of order, NaN, out of range, wrong type, truncated, several per cycle).
// Usage: fuzz_make_seeds CORPUS_DIR   (run from the repository root: build/test/fuzz/...)
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "guidance_lcm/node_harness.hpp"

namespace {

using evade::evade_angles_t;
using evade::evade_arm_t;
using evade::evade_burn_plan_t;
using evade::evade_nav_state_t;
using evade::evade_sim_clock_t;

using Bytes = std::vector<std::uint8_t>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::int64_t t_of(int cycle) { return 1000000 + cycle * 20000; }

template <typename Msg>
Bytes encode(const Msg& m) {
  Bytes b(static_cast<std::size_t>(m.getEncodedSize()));
  m.encode(b.data(), 0, static_cast<int>(b.size()));
  return b;
}

// Commands (plans, arm) carry the test command key's id and a fresh ARSN; their records set
// kSign, so that the harness puts a valid MAC on whatever bytes the fuzzer makes of them
// (lcm_input_harness.hpp): the mutations reach past the authentication into the decoder.
// A duplicated record duplicates the ARSN: a replay.
constexpr int kSign = 0x08;
std::int64_t g_arsn = 0;
template <typename Msg>
Bytes encode_cmd(Msg m) {
  m.auth.key_id = evade::guidance_lcm::test::test_command_key().id;
  m.auth.arsn = ++g_arsn;
  return encode(m);
}

// One record: advance cycles, then the bytes.
void record(Bytes* out, int advance, const Bytes& msg) {
  out->push_back(static_cast<std::uint8_t>(advance));
  out->push_back(static_cast<std::uint8_t>(msg.size() & 0xff));
  out->push_back(static_cast<std::uint8_t>(msg.size() >> 8));
  out->insert(out->end(), msg.begin(), msg.end());
}

void write(const std::filesystem::path& dir, const std::string& name, const Bytes& b) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary)
      .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

evade_angles_t angles(int cycle, std::int64_t seq) {
  evade::guidance_lcm::test::Encounter enc;
  evade_angles_t a{};
  enc.angles_at(t_of(cycle), &a);
  a.seq = seq;
  return a;
}

evade_nav_state_t nav(int cycle, std::int64_t seq) {
  evade::guidance_lcm::test::Encounter enc;
  evade_nav_state_t n{};
  enc.nav_at(t_of(cycle), &n);
  n.seq = seq;
  return n;
}

// Good traffic in the harness has seq = cycle + 1; the first record lands at cycle 4 + advance.
void angles_seeds(const std::filesystem::path& d) {
  Bytes b;
  record(&b, 2, encode(angles(6, 100)));  // newer seq, valid: accepted
  write(d, "valid-newer-seq", b);
  b.clear();
  record(&b, 2, encode(angles(6, 7)));  // equal to the good one of this cycle: duplicate
  write(d, "duplicate-seq", b);
  b.clear();
  evade_angles_t a = angles(6, 100);
  a.elevation_rad = kNaN;
  record(&b, 2, encode(a));
  a = angles(7, 101);
  a.azimuth_rad = 7.0;
  record(&b, 1, encode(a));
  a = angles(8, 102);
  a.sigma_angle_rad = -1.0;
  record(&b, 1, encode(a));
  write(d, "nan-and-out-of-range", b);
  b.clear();
  a = angles(6, 100);
  a.has_rates = true;
  a.elevation_rate_radps = 1e-3;
  a.azimuth_rate_radps = -2e-3;
  a.sigma_rate_radps = 1e-5;
  a.has_range = true;
  a.range_m = 9000.0;
  a.range_rate_mps = -1000.0;
  a.sigma_range_m = 1.0;
  a.sigma_range_rate_mps = 0.1;
  record(&b, 2, encode(a));
  write(d, "rates-and-range", b);
  b.clear();
  Bytes trunc = encode(angles(6, 100));
  trunc.resize(trunc.size() / 2);
  record(&b, 2, trunc);
  record(&b, 1, encode(nav(7, 200)));  // wrong type on this channel
  write(d, "truncated-and-wrong-type", b);
  b.clear();
  record(&b, 2, encode(angles(6, 5000)));     // seq jump: rejected, restart candidate
  record(&b, 1, encode(angles(7, 5001)));     // continues it, newer in time: restart
  write(d, "seq-restart", b);
  b.clear();
  a = angles(6, 100);
  a.utime = t_of(20);  // from the future
  record(&b, 2, encode(a));
  a = angles(7, 101);
  a.utime = t_of(-40);  // stale
  record(&b, 1, encode(a));
  write(d, "future-and-stale-utime", b);
}

void nav_seeds(const std::filesystem::path& d) {
  Bytes b;
  record(&b, 2, encode(nav(6, 100)));
  write(d, "valid-newer-seq", b);
  b.clear();
  evade_nav_state_t n = nav(6, 100);
  n.valid = false;
  record(&b, 2, encode(n));
  write(d, "nav-invalid-flag", b);
  b.clear();
  n = nav(6, 100);
  n.r_eci_m[0] = 2e9;
  record(&b, 2, encode(n));
  n = nav(7, 101);
  n.v_eci_mps[2] = kNaN;
  record(&b, 1, encode(n));
  write(d, "out-of-range-and-nan", b);
  b.clear();
  record(&b, 2, encode(nav(6, 3)));  // out of order
  write(d, "out-of-order-seq", b);
}

void arm_seeds(const std::filesystem::path& d) {
  Bytes b;
  evade_arm_t m{};
  m.utime = t_of(6);
  m.seq = 1;
  m.armed = false;
  record(&b, 2 | kSign, encode_cmd(m));
  m.utime = t_of(12);
  m.seq = 2;
  m.armed = true;
  record(&b, 6 | kSign, encode_cmd(m));
  write(d, "disarm-then-arm", b);
  b.clear();
  m.utime = t_of(6);
  m.seq = 1;
  m.armed = false;
  const Bytes once = encode_cmd(m);
  record(&b, 2 | kSign, once);
  record(&b, 1 | kSign, once);  // the same bytes again: a replayed ARSN
  write(d, "disarm-replayed", b);
  b.clear();
  record(&b, 2, encode_cmd(m));  // not re-signed: its zero MAC is refused (bad_mac)
  write(d, "disarm-bad-mac", b);
}

void key_cmd_seeds(const std::filesystem::path& d) {
  Bytes b;
  evade::evade_key_cmd_t m{};
  m.utime = t_of(6);
  m.seq = 1;
  m.op = evade::evade_key_cmd_t::OP_ACTIVATE;
  m.key_id = 1;
  record(&b, 2 | kSign, encode_cmd(m));
  m.seq = 2;
  m.op = evade::evade_key_cmd_t::OP_RETIRE;  // the only command key: refused (last key)
  record(&b, 1 | kSign, encode_cmd(m));
  m.seq = 3;
  m.key_id = 2;  // the sensor key: not a command key
  record(&b, 1 | kSign, encode_cmd(m));
  write(d, "activate-retire", b);
  b.clear();
  m.op = 7;  // unknown op
  record(&b, 2 | kSign, encode_cmd(m));
  write(d, "bad-op", b);
}

evade_burn_plan_t plan_msg(int cycle, std::int64_t id, int n, double dv_mps,
                           evade::guidance::PlanFrame frame) {
  evade::BurnPlan p;
  p.plan_id = id;
  p.n_impulses = n;
  for (int i = 0; i < n; ++i) {
    auto& b = p.impulses[static_cast<std::size_t>(i)];
    b.t_s = 0.2 + 0.3 * i;
    b.dv_rsw_mps = evade::Vec3(0.0, dv_mps, 0.0);
    b.dv_eci_valid = true;
    b.dv_eci_mps = evade::Vec3(0.0, 0.0, dv_mps);
  }
  evade_burn_plan_t m{};
  evade::guidance_lcm::to_lcm(p, t_of(cycle), id, t_of(cycle), frame, &m);
  return m;
}

void burn_plan_seeds(const std::filesystem::path& d) {
  using evade::guidance::PlanFrame;
  Bytes b;
  record(&b, 2 | kSign, encode_cmd(plan_msg(6, 1, 2, 0.05, PlanFrame::kRsw)));
  write(d, "two-impulses-rsw", b);
  b.clear();
  record(&b, 2 | kSign, encode_cmd(plan_msg(6, 1, 1, 0.1, PlanFrame::kEci)));
  record(&b, 1 | kSign, encode_cmd(plan_msg(7, 1, 1, 0.1, PlanFrame::kEci)));  // not newer
  record(&b, 1 | kSign, encode_cmd(plan_msg(8, 2, 3, 0.02, PlanFrame::kEci)));  // supersedes
  write(d, "eci-not-newer-superseded", b);
  b.clear();
  evade_burn_plan_t m = plan_msg(6, 1, 2, 0.05, PlanFrame::kRsw);
  m.impulse_t_s[1] = m.impulse_t_s[0];  // not ordered
  record(&b, 2 | kSign, encode_cmd(m));
  m = plan_msg(7, 2, 1, 500.0, PlanFrame::kRsw);  // over budget
  record(&b, 1 | kSign, encode_cmd(m));
  m = plan_msg(8, 3, 1, 0.05, PlanFrame::kRsw);
  m.impulse_t_s[0] = -1.0;  // in the past
  record(&b, 1 | kSign, encode_cmd(m));
  write(d, "rejections", b);
}

void sim_clock_seeds(const std::filesystem::path& d) {
  Bytes b;
  for (int k = 0; k < 6; ++k) {
    evade_sim_clock_t t{};
    t.utime = t_of(4 + k);
    t.seq = k + 1;
    record(&b, k == 0 ? 0 : 1, encode(t));
  }
  write(d, "regular-ticks", b);
  b.clear();
  evade_sim_clock_t t{};
  t.utime = t_of(4);
  t.seq = 1;
  record(&b, 0, encode(t));
  record(&b, 1, encode(t));  // replayed tick
  t.utime = -5;
  t.seq = 2;
  record(&b, 1, encode(t));  // negative utime
  write(d, "replayed-and-negative", b);
}

template <typename T>
void put(Bytes* b, T v) {
  const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
  b->insert(b->end(), p, p + sizeof(T));
}

// plan_validation.cpp's layout: now, armed, dv_used, id, epoch, frame, n, 8 x impulse.
Bytes plan_struct(std::int64_t now, bool armed, double dv_used, std::uint8_t frame, int n,
                  double t0_s, double dt_s, double dv_mps) {
  Bytes b;
  put<std::int64_t>(&b, now);
  put<std::uint8_t>(&b, armed ? 1 : 0);
  put<double>(&b, dv_used);
  put<std::int64_t>(&b, 1);
  put<std::int64_t>(&b, now);
  put<std::uint8_t>(&b, frame);
  put<std::int8_t>(&b, static_cast<std::int8_t>(n));
  for (int i = 0; i < 8; ++i) {
    put<double>(&b, t0_s + dt_s * i);
    put<double>(&b, 0.0);
    put<double>(&b, dv_mps);
    put<double>(&b, 0.0);
    put<std::uint8_t>(&b, 1);
    put<double>(&b, dv_mps);
    put<double>(&b, 0.0);
    put<double>(&b, 0.0);
  }
  return b;
}

void plan_validation_seeds(const std::filesystem::path& d) {
  write(d, "rsw-three-burns", plan_struct(1000000, true, 0.0, 0, 3, 1.0, 2.0, 0.5));
  write(d, "eci-eight-burns", plan_struct(1000000, true, 10.0, 1, 8, 0.5, 1.0, 0.1));
  write(d, "disarmed", plan_struct(1000000, false, 0.0, 0, 1, 1.0, 1.0, 0.5));
  write(d, "over-budget", plan_struct(1000000, true, 99.0, 0, 2, 1.0, 5.0, 3.0));
  write(d, "overlapping", plan_struct(1000000, true, 0.0, 0, 2, 1.0, 0.01, 1.0));
  write(d, "long-burn", plan_struct(1000000, true, 0.0, 0, 1, 400.0, 1.0, 90.0));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_make_seeds CORPUS_DIR\n");
    return 2;
  }
  const std::filesystem::path root(argv[1]);
  angles_seeds(root / "lcm_angles");
  nav_seeds(root / "lcm_nav");
  arm_seeds(root / "lcm_arm");
  burn_plan_seeds(root / "lcm_burn_plan");
  key_cmd_seeds(root / "lcm_key_cmd");
  sim_clock_seeds(root / "lcm_sim_clock");
  plan_validation_seeds(root / "plan_validation");
  std::printf("seeds written under %s\n", root.string().c_str());
  return 0;
}
