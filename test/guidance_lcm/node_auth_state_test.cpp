// The node's anti-replay state cannot be lost silently (docs/SECURITY.md AUTH-4; issue 40 rows
// 5, 6 and 11, seen from the library): a command takes effect only once its ARSN is on disk, a
// restart refuses its replay, key states come from the state file and never from the order of
// the keys, and a node with a state path starts only from a valid file (or writes one afresh
// with --auth-init, which refuses to overwrite one). A write never follows what is planted at
// the temporary name.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "command_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

NodeSecurity with_state(const std::string& path, std::int32_t init_key) {
  NodeSecurity sec = test_security();
  sec.state_path = path;
  sec.init_active_key = init_key;
  return sec;
}

std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

void write_all(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << text;
}

std::string start_error(const NodeSecurity& sec) {
  try {
    Rig rig(NodeConfig{}, 16, sec);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// AUTH-4: with a state file, a command takes effect only after the ARSN it advanced is on
// disk (persist_auth_state between cycles), and a restarted node refuses its replay.
TEST(NodeAuthState, ArsnSurvivesARestart) {
  TempDir dir;
  ASSERT_FALSE(dir.path.empty());
  const std::string path = dir.path + "/state";
  const std::vector<std::uint8_t> b = signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 1000);
  {
    Rig rig(NodeConfig{}, 100000, with_state(path, 1));
    send(rig, kChanPlan, b);
    nav_cycle(rig, 0);
    EXPECT_EQ(rig.node.last_status().plan_n_accepted, 0) << "waits for the state on disk";
    ASSERT_EQ(rig.node.persist_auth_state(), 0);
    nav_cycle(rig, 1);
    EXPECT_EQ(rig.node.last_status().plan_n_accepted, 1);
  }
  Rig rig(NodeConfig{}, 100000, with_state(path, 0));  // restart from the same state file
  send(rig, kChanPlan, b);
  nav_cycle(rig, 2);
  EXPECT_EQ(rig.node.persist_auth_state(), 0);
  EXPECT_EQ(thrust_cycles(rig, 3, 100), 0);
  EXPECT_EQ(reason(rig, Reason::kReplayedArsn), 1);
  send(rig, kChanPlan, signed_bytes(plan_msg(2, 3.0), kChanPlan, test_command_key(), 1001));
  nav_cycle(rig, 100);
  EXPECT_EQ(rig.node.persist_auth_state(), 0);
  EXPECT_EQ(thrust_cycles(rig, 101, 200), 5);
  expect_accounted(rig);
}

// Issue 40 row 5: deleted, cut to its header, one key's line removed, group/other writable: the
// node does not start, and says why. --auth-init refuses to overwrite an existing file.
TEST(NodeAuthState, NodeStartsOnlyFromAValidStateFile) {
  TempDir dir;
  ASSERT_FALSE(dir.path.empty());
  const std::string path = dir.path + "/state";
  EXPECT_NE(start_error(with_state(path, 0)).find("does not exist"), std::string::npos);
  { Rig first(NodeConfig{}, 16, with_state(path, 1)); }  // first start: writes the file
  EXPECT_EQ(start_error(with_state(path, 0)), "");
  EXPECT_NE(start_error(with_state(path, 1)), "") << "--auth-init must not overwrite the state";
  const std::string good = read_all(path);
  ASSERT_FALSE(good.empty());
  write_all(path, good.substr(0, good.find('\n') + 1));  // cut to its header line
  EXPECT_NE(start_error(with_state(path, 0)), "");
  std::string no_key = good;
  const std::size_t k = no_key.find("\nkey ");
  ASSERT_NE(k, std::string::npos);
  no_key.erase(k + 1, no_key.find('\n', k + 1) - k);  // one key's line removed
  write_all(path, no_key);
  EXPECT_NE(start_error(with_state(path, 0)), "");
  write_all(path, good);
  ASSERT_EQ(chmod(path.c_str(), 0666), 0);
  EXPECT_NE(start_error(with_state(path, 0)).find("chmod 600"), std::string::npos);
  ASSERT_EQ(chmod(path.c_str(), 0600), 0);
  EXPECT_EQ(start_error(with_state(path, 0)), "");
  ASSERT_EQ(unlink(path.c_str()), 0);
  EXPECT_NE(start_error(with_state(path, 0)).find("does not exist"), std::string::npos);
}

// Issue 40 row 6: a symlink planted at the temporary name is removed, never followed: its
// target is untouched by the state write, and the write succeeds.
TEST(NodeAuthState, WriteNeverFollowsWhatIsPlantedAtTheTemporaryName) {
  TempDir dir;
  ASSERT_FALSE(dir.path.empty());
  const std::string path = dir.path + "/state";
  const std::string target = dir.path + "/target";
  write_all(target, "precious\n");
  Rig rig(NodeConfig{}, 100000, with_state(path, 1));
  ASSERT_EQ(symlink(target.c_str(), (path + ".tmp").c_str()), 0);
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, test_command_key(), 7));
  nav_cycle(rig, 0);
  EXPECT_EQ(rig.node.persist_auth_state(), 0);
  EXPECT_EQ(read_all(target), "precious\n");
  nav_cycle(rig, 1);
  EXPECT_EQ(rig.node.last_status().plan_n_accepted, 1);
}

// Issue 40 row 11: a new command key listed first at a restart starts standby (key states come
// from the state file, never from the order of --keys); the ground activates it by command.
TEST(NodeAuthState, NewCommandKeyAtARestartIsStandbyWhateverItsPlace) {
  TempDir dir;
  ASSERT_FALSE(dir.path.empty());
  const std::string path = dir.path + "/state";
  { Rig first(NodeConfig{}, 16, with_state(path, 1)); }
  NodeSecurity sec;  // the new key 4 listed first, as command keys come from load_into: standby
  const SigningKey k4 = test_key(4, 0x44);
  ASSERT_EQ(sec.keys.add(k4.id, auth::KeyRole::kCommand, k4.key, auth::KeyState::kStandby), nullptr);
  const NodeSecurity base = test_security();
  for (const auth::KeyEntry* e : {base.keys.find(1), base.keys.find(2), base.keys.find(3)}) {
    ASSERT_EQ(sec.keys.add(e->id, e->role, e->key,
                           e->role == auth::KeyRole::kCommand ? auth::KeyState::kStandby
                                                              : auth::KeyState::kActive),
              nullptr);
  }
  sec.state_path = path;
  Rig rig(NodeConfig{}, 100000, sec);
  EXPECT_EQ(rig.node.keys().find(4)->state, auth::KeyState::kStandby);
  EXPECT_EQ(rig.node.keys().find(1)->state, auth::KeyState::kActive);
  send(rig, kChanPlan, signed_bytes(plan_msg(1), kChanPlan, k4, 3));
  nav_cycle(rig, 0);
  EXPECT_EQ(reason(rig, Reason::kStandbyKey), 1);
  expect_accounted(rig);
}

}  // namespace
}  // namespace evade::guidance_lcm::test
