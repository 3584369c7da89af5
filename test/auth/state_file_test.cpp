// The node's authenticated state file, version 2 (docs/SECURITY.md AUTH-4, KEY-2; issue 40
// "replay state that cannot be lost silently"), each test in a fresh private directory: init
// then load gives the same states and ARSNs; the file is the documented text with its MAC under
// the derived subkey; new keys are standby (command) or active (sensor); records of unloaded
// keys survive saves and keep a retired key retired; init refuses anything at the path and a
// key that is not a loaded command key. Load's refusals: state_file_load_refusals_test.cpp;
// save, the directory and the constructors: state_file_save_test.cpp.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "auth_file_test_support.hpp"
#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"
#include "evade/auth/mac.hpp"
#include "evade/auth/state_file.hpp"
#include "state_file_test_fixture.hpp"

namespace evade::auth {
namespace {

using namespace test;  // the shared fixtures and helpers of test/auth

TEST_F(AuthStateFile, InitThenLoadGivesTheSameStatesAndArsns) {
  KeyRing r = ring();
  StateFile f = file();
  f.init(&r, 1, 1000);
  EXPECT_EQ(state(r, 1), KeyState::kActive);
  EXPECT_EQ(state(r, 2), KeyState::kStandby);
  EXPECT_EQ(state(r, 3), KeyState::kActive);
  EXPECT_EQ(arsn(r, 1), 1000);
  EXPECT_EQ(arsn(r, 2), 1000);
  EXPECT_EQ(f.writes(), 1);
  KeyRing fresh = ring();
  StateFile(state_, tel_).load(&fresh);
  for (std::int32_t id : {1, 2, 3}) {
    EXPECT_EQ(state(fresh, id), state(r, id)) << id;
    EXPECT_EQ(arsn(fresh, id), arsn(r, id)) << id;
  }
  // The ground rotates: key 2 active with a new ARSN, key 1 retired; then a restart.
  ASSERT_EQ(r.activate(2), KeyCmdResult::kDone);
  ASSERT_TRUE(r.commit(2, ArsnSlot::kCommand, 123456789012LL));
  ASSERT_EQ(r.retire(1), KeyCmdResult::kDone);
  ASSERT_EQ(f.save(r), 0);
  EXPECT_EQ(f.writes(), 2);
  KeyRing after = ring();
  StateFile g = file();
  g.load(&after);
  EXPECT_EQ(g.writes(), 2);
  EXPECT_EQ(state(after, 1), KeyState::kRetired);
  EXPECT_EQ(state(after, 2), KeyState::kActive);
  EXPECT_EQ(arsn(after, 2), 123456789012LL);
  EXPECT_EQ(arsn(after, 1), 1000);
  EXPECT_EQ(mode_of(state_), 0600U);
  EXPECT_FALSE(exists(state_ + ".tmp"));
}

TEST_F(AuthStateFile, FileIsTheDocumentedTextWithItsMacUnderTheDerivedSubkey) {
  (void)initialized();
  const std::string body = head(1) + key_line(1, "active", 1000) + key_line(2, "standby", 1000) +
                           key_line(3, "active", 0);
  EXPECT_EQ(read_bytes(state_), sign(body));
  // Not a MAC under the telemetry key itself: the subkey is a key of its own.
  const Mac direct = hmac_sha256(tel_.key.data(), tel_.key.size(), reinterpret_cast<const std::uint8_t*>(body.data()), body.size());
  EXPECT_EQ(read_bytes(state_).find(to_hex(direct.data(), direct.size())), std::string::npos);
  EXPECT_EQ(read_bytes(state_).find(to_hex(tel_.key)), std::string::npos) << "the telemetry key is in the file";
}

TEST_F(AuthStateFile, WriteCounterCountsEverySaveAcrossRestarts) {
  KeyRing r = initialized();
  for (int k = 0; k < 5; ++k) {
    StateFile f = file();
    f.load(&r);
    EXPECT_EQ(f.writes(), 1 + 2 * k);
    ASSERT_EQ(f.save(r), 0);
    ASSERT_EQ(f.save(r), 0);
    EXPECT_EQ(f.writes(), 3 + 2 * k);
  }
}

// ---- what load applies ----

TEST_F(AuthStateFile, NewKeysAreStandbyCommandKeysAndActiveSensorKeys) {
  (void)initialized({1, 3});
  KeyRing r = ring({1, 2, 3, 4, 5});
  for (std::size_t i = 0; i < r.size(); ++i) (void)r.restore(r.entry(i).id, KeyState::kActive, 77);  // whatever came before
  StateFile f = file();
  f.load(&r);
  EXPECT_EQ(state(r, 1), KeyState::kActive);
  EXPECT_EQ(arsn(r, 1), 1000);
  EXPECT_EQ(state(r, 2), KeyState::kStandby);
  EXPECT_EQ(arsn(r, 2), 0);
  EXPECT_EQ(state(r, 4), KeyState::kStandby);
  EXPECT_EQ(state(r, 5), KeyState::kActive);
  EXPECT_EQ(r.active_command_keys(), 1);
}

// A retired key whose file is left out for a while, then loaded again, is still retired, with
// its ARSN: its record survived every save in between.
TEST_F(AuthStateFile, RecordsOfUnloadedKeysSurviveSavesAndARetiredKeyStaysRetired) {
  KeyRing r = initialized({1, 2, 3});
  {
    StateFile f = file();
    f.load(&r);
    ASSERT_TRUE(r.commit(2, ArsnSlot::kCommand, 2000));  // (a standby key's ARSN, for the check)
    ASSERT_EQ(r.retire(2), KeyCmdResult::kDone);
    ASSERT_EQ(f.save(r), 0);
  }
  for (int restart = 0; restart < 3; ++restart) {  // key 2 not loaded
    KeyRing without = ring({1, 3});
    StateFile f = file();
    f.load(&without);
    ASSERT_TRUE(without.commit(1, ArsnSlot::kCommand, 3000 + restart));
    ASSERT_EQ(f.save(without), 0);
  }
  EXPECT_NE(read_bytes(state_).find(key_line(2, "retired", 2000)), std::string::npos);
  KeyRing again = ring({1, 2, 3});
  file().load(&again);
  EXPECT_EQ(state(again, 2), KeyState::kRetired);
  EXPECT_EQ(arsn(again, 2), 2000);
  EXPECT_EQ(arsn(again, 1), 3002);
  EXPECT_EQ(again.activate(2), KeyCmdResult::kRetired);
}

// ---- init ----

TEST_F(AuthStateFile, InitRefusesAnythingAtThePath) {
  const std::string target = write_file("target", "precious\n");
  std::vector<std::string> made;
  ASSERT_EQ(::symlink(target.c_str(), state_.c_str()), 0);
  made.push_back("a symlink to a file");
  for (int k = 0; k < 4; ++k) {
    KeyRing r = ring();
    const std::string text = runtime_error_text([&] { file().init(&r, 1, 0); });
    EXPECT_NE(text.find("already exists: --auth-init is only for a node's very first start"), std::string::npos)
        << made.back() << ": " << text;
    EXPECT_EQ(state(r, 1), KeyState::kStandby) << "a refused init changed the ring";
    EXPECT_EQ(read_bytes(target), "precious\n");
    ASSERT_EQ(::unlink(state_.c_str()) == 0 || ::rmdir(state_.c_str()) == 0, true);
    if (k == 0) {
      ASSERT_EQ(::symlink(path("nowhere").c_str(), state_.c_str()), 0);
      made.push_back("a dangling symlink");
    } else if (k == 1) {
      write_file("node.state", "anything\n");
      made.push_back("a file");
    } else if (k == 2) {
      ASSERT_EQ(::mkdir(state_.c_str(), 0700), 0);
      made.push_back("a directory");
    }
  }
  EXPECT_FALSE(exists(path("nowhere")));
  (void)initialized();
  KeyRing r = ring();
  EXPECT_THROW(file().init(&r, 1, 0), std::runtime_error) << "a second init over a written file";
}

TEST_F(AuthStateFile, InitRefusesAKeyThatIsNotALoadedCommandKeyAndANegativeFloor) {
  for (std::int32_t id : {3, 9, kTel, 0}) {
    KeyRing r = ring();
    const std::string text = runtime_error_text([&] { file().init(&r, id, 0); });
    EXPECT_NE(text.find("is not a loaded command key"), std::string::npos) << id << ": " << text;
  }
  KeyRing r = ring();
  EXPECT_NE(runtime_error_text([&] { file().init(&r, 1, -1); }).find("ARSN floor"), std::string::npos);
  EXPECT_FALSE(exists(state_));
}

TEST_F(AuthStateFile, InitMakesOnlyItsKeyActiveAndStartsEveryCommandArsnAtTheFloor) {
  KeyRing r = ring({1, 2, 3, 4});
  (void)r.restore(4, KeyState::kActive, 5);
  StateFile f = file();
  f.init(&r, 2, 777);
  EXPECT_EQ(r.active_command_keys(), 1);
  EXPECT_EQ(state(r, 2), KeyState::kActive);
  EXPECT_EQ(state(r, 4), KeyState::kStandby);
  for (std::int32_t id : {1, 2, 4}) EXPECT_EQ(arsn(r, id), 777) << id;
  EXPECT_EQ(arsn(r, 3), 0);
}

}  // namespace
}  // namespace evade::auth
