// The state file's load refusals (docs/SECURITY.md AUTH-4), each test in a fresh private
// directory: load refuses a missing file (naming --auth-init), a symbolic link, a directory or
// FIFO, another user's file, group/other permission bits, version 1, foreign text, a file cut at
// any length or with any byte changed, another telemetry key, every malformed line of an
// authentic file, a loaded key with another check value or role, and a result with no active
// command key, and changes nothing in the ring when it refuses.
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

TEST_F(AuthStateFile, LoadRefusesAMissingFileNamingAuthInit) {
  const std::string text = load_error();
  EXPECT_NE(text.find("'" + state_ + "' does not exist: a node with command keys starts only from its "
                      "state file; on its very first start give --auth-init KEY_ID (docs/SECURITY.md)"),
            std::string::npos) << text;
}

// The deletion attack: a node that had retired key 1 and accepted ARSN 5000 loses its file.
TEST_F(AuthStateFile, ADeletedFileIsRefusedNotAFirstStart) {
  KeyRing r = initialized();
  StateFile f = file();
  f.load(&r);
  ASSERT_EQ(r.activate(2), KeyCmdResult::kDone);
  ASSERT_EQ(r.retire(1), KeyCmdResult::kDone);
  ASSERT_TRUE(r.commit(2, ArsnSlot::kCommand, 5000));
  ASSERT_EQ(f.save(r), 0);
  ASSERT_EQ(::unlink(state_.c_str()), 0);
  EXPECT_NE(load_error().find("does not exist"), std::string::npos);
}

TEST_F(AuthStateFile, LoadRefusesASymbolicLinkEvenToAnAuthenticFile) {
  (void)initialized();
  const std::string real = path("real.state");
  ASSERT_EQ(::rename(state_.c_str(), real.c_str()), 0);
  ASSERT_EQ(::symlink(real.c_str(), state_.c_str()), 0);
  EXPECT_NE(load_error().find("is a symbolic link: refused"), std::string::npos);
}

TEST_F(AuthStateFile, LoadRefusesADirectoryAndAFifo) {
  ASSERT_EQ(::mkdir(state_.c_str(), 0700), 0);
  EXPECT_NE(load_error().find("is not a regular file"), std::string::npos);
  ASSERT_EQ(::rmdir(state_.c_str()), 0);
  ASSERT_EQ(::mkfifo(state_.c_str(), 0600), 0);
  EXPECT_NE(load_error().find("is not a regular file"), std::string::npos);
}

TEST_F(AuthStateFile, LoadRefusesAFileOwnedByAnotherUser) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give a file to another user";
  (void)initialized();
  ASSERT_EQ(::chown(state_.c_str(), 65534, 65534), 0);
  EXPECT_NE(load_error().find("is owned by uid 65534"), std::string::npos);
}

TEST_F(AuthStateFile, LoadRefusesGroupOrOtherPermissionBits) {
  (void)initialized();
  for (unsigned mode : {0666U, 0644U, 0640U, 0604U, 0620U, 0602U}) {
    ASSERT_EQ(::chmod(state_.c_str(), mode), 0);
    const std::string text = load_error();
    EXPECT_NE(text.find("chmod 600 it"), std::string::npos) << std::oct << mode << ": " << text;
  }
  ASSERT_EQ(::chmod(state_.c_str(), 0400), 0);  // owner only: fine
  KeyRing r = ring();
  EXPECT_NO_THROW(file().load(&r));
}

TEST_F(AuthStateFile, LoadRefusesAnUnauthenticatedVersion1File) {
  write_file("node.state", "evade-auth-state 1\nkey 1 active 4\nkey 2 standby 0\n");
  const std::string text = load_error();
  EXPECT_NE(text.find("is an unauthenticated version-1 file"), std::string::npos) << text;
}

TEST_F(AuthStateFile, LoadRefusesAnotherVersionAndForeignText) {
  write_file("node.state", sign("evade-auth-state 3\nwrites 1\n"));
  EXPECT_NE(load_error().find("another version of the format, not 2"), std::string::npos);
  for (const char* text : {"", "\n", "hello\n", "evade-auth-state 2", "evade-auth-state 22\n", "EVADE-AUTH-STATE 2\n"}) {
    write_file("node.state", text);
    const std::string e = load_error();
    EXPECT_TRUE(e.find("not an evade auth state file") != std::string::npos ||
                e.find("another version") != std::string::npos || e.find("does not verify") != std::string::npos)
        << text << ": " << e;
  }
}

// Cut at every length: to nothing, to its header, after any line (a key's record removed from
// the end), in the middle of the MAC: never a start.
TEST_F(AuthStateFile, LoadRefusesTheFileCutAtAnyLength) {
  (void)initialized();
  const std::string full = read_bytes(state_);
  for (std::size_t n = 0; n < full.size(); ++n) {
    write_file("node.state", full.substr(0, n));
    const std::string text = load_error();
    EXPECT_FALSE(text.empty()) << "cut to " << n << " bytes";
  }
  // A key's line removed, the rest intact.
  const std::string line2 = key_line(2, "standby", 1000);
  std::string removed = full;
  removed.erase(removed.find(line2), line2.size());
  write_file("node.state", removed);
  EXPECT_NE(load_error().find("does not verify: it was changed, cut, or written under another telemetry key"),
            std::string::npos);
}

TEST_F(AuthStateFile, LoadRefusesAnyChangedByte) {
  (void)initialized();
  const std::string full = read_bytes(state_);
  for (std::size_t i = 0; i < full.size(); ++i) {
    for (unsigned char flip : {0x01U, 0x20U}) {
      std::string changed = full;
      changed[i] = static_cast<char>(static_cast<unsigned char>(changed[i]) ^ flip);
      write_file("node.state", changed);
      EXPECT_FALSE(load_error().empty()) << "byte " << i << " ^ " << unsigned{flip};
    }
  }
  write_file("node.state", full + "key 4 command active 99999 0011223344556677\n");  // after the MAC
  EXPECT_NE(load_error().find("does not verify"), std::string::npos);
}

TEST_F(AuthStateFile, LoadRefusesAFileWrittenUnderAnotherTelemetryKey) {
  (void)initialized();
  KeyEntry other = tel_;  // the same id, another key
  other.key = generate_key(kTel, KeyRole::kTelemetry).key;
  KeyRing r2;  // the node's ring and file object both hold the other key
  ASSERT_EQ(r2.add(1, KeyRole::kCommand, keys_.at(1), KeyState::kStandby), nullptr);
  ASSERT_EQ(r2.add(kTel, KeyRole::kTelemetry, other.key, KeyState::kActive), nullptr);
  const std::string text = runtime_error_text([&] { StateFile(state_, other).load(&r2); });
  EXPECT_NE(text.find("does not verify"), std::string::npos) << text;
}

// An authentic file (the test signs it) whose telemetry line names another key id or check value.
TEST_F(AuthStateFile, LoadRefusesAnAuthenticFileForAnotherTelemetryKey) {
  const std::string keys = key_line(1, "active", 7);
  write_file("node.state", sign("evade-auth-state 2\nwrites 1\ntelemetry 51 " + kcv(tel_.key) + "\n" + keys));
  EXPECT_NE(load_error().find("was written for telemetry key 51, not for the node's telemetry key 50"),
            std::string::npos);
  write_file("node.state", sign("evade-auth-state 2\nwrites 1\ntelemetry 50 0011223344556677\n" + keys));
  EXPECT_NE(load_error().find("telemetry key 50 with another check value"), std::string::npos);
}

TEST_F(AuthStateFile, LoadRefusesEveryMalformedLineOfAnAuthenticFile) {
  const std::string t = "telemetry 50 " + kcv(tel_.key) + "\n";
  const std::string k1 = key_line(1, "active", 7);
  const std::string c = kcv(keys_.at(2));
  struct Case {
    std::string body;
    const char* expect;
  };
  std::vector<Case> cases = {
      {"evade-auth-state 2\n", "line 2: missing"},
      {"evade-auth-state 2\nwrites 1\n", "line 3: missing"},
      {"evade-auth-state 2\nwrites -1\n" + t + k1, "line 2: expected 'writes <n>'"},
      {"evade-auth-state 2\nwrites  1\n" + t + k1, "line 2: expected 'writes <n>'"},
      {"evade-auth-state 2\nwritten 1\n" + t + k1, "line 2: expected 'writes <n>'"},
      {"evade-auth-state 2\nwrites 1\ntelemetry 50\n" + k1, "line 3: expected 'telemetry <id> <check value>'"},
      {"evade-auth-state 2\nwrites 1\n" + k1 + t, "line 3: expected 'telemetry"},
      {head() + k1 + "key 2 command standby 0\n", "line 5: expected 'key <id>"},
      {head() + k1 + "key 2 command sleeping 0 " + c + "\n", "line 5: expected 'key <id>"},
      {head() + k1 + "key 2 telemetry active 0 " + c + "\n", "line 5: expected 'key <id>"},
      {head() + k1 + "key 2 command standby -5 " + c + "\n", "line 5: expected 'key <id>"},
      {head() + k1 + "key 0 command standby 5 " + c + "\n", "line 5: expected 'key <id>"},
      {head() + k1 + "key 2 command standby 5 " + c + " \n", "line 5: expected 'key <id>"},
      {head() + k1 + "key 2 command standby 5 " + c.substr(2) + "\n", "line 5: expected 'key <id>"},
      {head() + k1 + "key 2 command standby 99999999999999999999 " + c + "\n", "line 5: expected 'key <id>"},
      {head() + k1 + "\n", "line 5: expected 'key <id>"},
      {head() + k1 + k1, "line 5: key id 1 appears twice"},
      {head() + k1 + "key 50 command standby 0 " + c + "\n", "line 5: key id 50 is the telemetry key's"},
  };
  std::string many = head();
  for (int id = 100; id < 133; ++id) many += "key " + std::to_string(id) + " command standby 0 " + c + "\n";
  cases.push_back({many, "line 36: more than 32 key records"});
  for (const Case& cs : cases) {
    write_file("node.state", sign(cs.body));
    const std::string text = load_error();
    EXPECT_NE(text.find(cs.expect), std::string::npos) << cs.body << "-> " << text;
  }
}

TEST_F(AuthStateFile, LoadRefusesALoadedKeyThatIsNotTheKeyOfItsRecord) {
  (void)initialized();
  keys_[2] = generate_key(2, KeyRole::kCommand).key;  // another key under id 2 in --keys
  EXPECT_NE(load_error().find("key 2 is not the key this state file was written for"), std::string::npos);
}

TEST_F(AuthStateFile, LoadRefusesAKeyWhoseRoleChanged) {
  write_file("node.state", sign(head() + key_line(1, "active", 7) + "key 3 command standby 0 " + kcv(keys_.at(3)) + "\n"));
  EXPECT_NE(load_error().find("key 3 is a command key in it but a sensor key in the key files"), std::string::npos);
}

// The active key's file left out of --keys: only standby keys would be loaded.
TEST_F(AuthStateFile, LoadRefusesAResultWithNoActiveCommandKey) {
  (void)initialized();  // 1 active, 2 standby
  EXPECT_NE(load_error(ring({2, 3})).find("leaves no loaded command key active"), std::string::npos);
  EXPECT_NE(load_error(ring({3, 4})).find("leaves no loaded command key active"), std::string::npos);
  KeyRing sensors_only = ring({3});
  EXPECT_NO_THROW(file().load(&sensors_only));
}

TEST_F(AuthStateFile, LoadRefusesMoreRecordsThanItHoldsWithTheLoadedKeys) {
  std::string body = head() + key_line(1, "active", 7);
  const std::string c = kcv(keys_.at(4));
  for (int id = 100; id < 131; ++id) body += "key " + std::to_string(id) + " command retired 0 " + c + "\n";
  write_file("node.state", sign(body));  // 32 records: 1 and 31 others
  KeyRing r = ring({1});
  EXPECT_NO_THROW(file().load(&r));
  EXPECT_NE(load_error(ring({1, 3})).find("more than 32 keys"), std::string::npos);  // 3 is new: 33
}

}  // namespace
}  // namespace evade::auth
