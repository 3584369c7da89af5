// The node's authenticated state file, version 2 (docs/SECURITY.md AUTH-4, KEY-2; issue 40
// "replay state that cannot be lost silently"), each test in a fresh private directory: init
// then load gives the same states and ARSNs; the file is the documented text with its MAC under
// the derived subkey; load refuses a missing file (naming --auth-init), a symbolic link, a
// directory or FIFO, another user's file, group/other permission bits, version 1, foreign text,
// a file cut at any length or with any byte changed, another telemetry key, every malformed
// line of an authentic file, a loaded key with another check value or role, and a result with
// no active command key, and changes nothing in the ring when it refuses; new keys are standby
// (command) or active (sensor); records of unloaded keys survive saves and keep a retired key
// retired; init refuses anything at the path and a key that is not a loaded command key; save
// removes a file or symbolic link planted at the temporary name without touching the link's
// target, refuses before load or init, returns -errno and leaves no temporary; the directory is
// checked; the transition constructors of the node still work.
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

namespace evade::auth {
namespace {

using test::exists;
using test::mode_of;
using test::read_bytes;
using test::runtime_error_text;
using test::to_hex;

constexpr std::int32_t kTel = 50;
constexpr std::size_t kCmdSlot = static_cast<std::size_t>(ArsnSlot::kCommand);

std::int64_t arsn(const KeyRing& r, std::int32_t id) { return r.find(id)->arsn[kCmdSlot]; }
KeyState state(const KeyRing& r, std::int32_t id) { return r.find(id)->state; }

class AuthStateFile : public test::TempDir {
 protected:
  void SetUp() override {
    TempDir::SetUp();
    for (std::int32_t id : {1, 2, 4}) keys_[id] = generate_key(id, KeyRole::kCommand).key;
    for (std::int32_t id : {3, 5}) keys_[id] = generate_key(id, KeyRole::kSensor).key;
    tel_.id = kTel;
    tel_.role = KeyRole::kTelemetry;
    tel_.key = generate_key(kTel, KeyRole::kTelemetry).key;
    state_ = path("node.state");
  }

  static KeyRole role_of(std::int32_t id) { return id == 3 || id == 5 ? KeyRole::kSensor : KeyRole::kCommand; }

  /// The node's ring as load_into leaves it: command keys standby, sensor and telemetry active.
  KeyRing ring(std::vector<std::int32_t> ids = {1, 2, 3}) const {
    KeyRing r;
    for (std::int32_t id : ids) {
      const KeyRole role = role_of(id);
      EXPECT_EQ(r.add(id, role, keys_.at(id), role == KeyRole::kCommand ? KeyState::kStandby : KeyState::kActive), nullptr);
    }
    EXPECT_EQ(r.add(kTel, KeyRole::kTelemetry, tel_.key, KeyState::kActive), nullptr);
    return r;
  }

  StateFile file() const { return StateFile(state_, tel_); }

  /// A first start with key 1 active and ARSN floor 1000; returns the ring.
  KeyRing initialized(std::vector<std::int32_t> ids = {1, 2, 3}) const {
    KeyRing r = ring(ids);
    StateFile f = file();
    f.init(&r, 1, 1000);
    return r;
  }

  std::string kcv(const KeyBytes& k) const {
    const KeyCheckValue v = key_check_value(k);
    return to_hex(v.data(), v.size());
  }

  /// body with its MAC line under the state subkey of the telemetry key (an authentic file).
  std::string sign(const std::string& body) const {
    KeyBytes sub = derive_subkey(tel_.key, 1, "evadestf");
    const Mac m = hmac_sha256(sub.data(), sub.size(), reinterpret_cast<const std::uint8_t*>(body.data()), body.size());
    return body + "mac " + to_hex(m.data(), m.size()) + "\n";
  }
  std::string head(std::int64_t writes = 3) const {
    return "evade-auth-state 2\nwrites " + std::to_string(writes) + "\ntelemetry " + std::to_string(kTel) + " " +
           kcv(tel_.key) + "\n";
  }
  std::string key_line(std::int32_t id, const char* st, std::int64_t a) const {
    return "key " + std::to_string(id) + " " + role_name(role_of(id)) + " " + st + " " + std::to_string(a) + " " +
           kcv(keys_.at(id)) + "\n";
  }

  /// The error text of loading the file into r (which must stay unchanged).
  std::string load_error(KeyRing r) const {
    const KeyRing before = r;
    const std::string text = runtime_error_text([&] {
      StateFile f = file();
      f.load(&r);
    });
    for (std::size_t i = 0; i < r.size(); ++i) {
      EXPECT_EQ(r.entry(i).state, before.entry(i).state) << "a refused load changed key " << r.entry(i).id;
      EXPECT_EQ(r.entry(i).arsn, before.entry(i).arsn) << "a refused load changed key " << r.entry(i).id;
    }
    return text;
  }
  std::string load_error() const { return load_error(ring()); }

  std::map<std::int32_t, KeyBytes> keys_;
  KeyEntry tel_;
  std::string state_;
};

// ---- the round trip and the format ----

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

// ---- load's refusals ----

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

// ---- save ----

TEST_F(AuthStateFile, SaveRemovesAFilePlantedAtTheTemporaryName) {
  KeyRing r = initialized();
  write_file("node.state.tmp", "planted\n", 0644U);
  StateFile f = file();
  f.load(&r);
  ASSERT_TRUE(r.commit(1, ArsnSlot::kCommand, 1001));
  ASSERT_EQ(f.save(r), 0);
  EXPECT_FALSE(exists(state_ + ".tmp"));
  KeyRing after = ring();
  file().load(&after);
  EXPECT_EQ(arsn(after, 1), 1001);
}

// A hard link to another file planted at the temporary name: the name goes, the file it shares
// stays byte for byte.
TEST_F(AuthStateFile, SaveNeverWritesIntoAFileHardLinkedAtTheTemporaryName) {
  KeyRing r = initialized();
  const std::string victim = write_file("victim", "precious\n", 0600U);
  ASSERT_EQ(::link(victim.c_str(), (state_ + ".tmp").c_str()), 0);
  StateFile f = file();
  f.load(&r);
  ASSERT_EQ(f.save(r), 0);
  EXPECT_EQ(read_bytes(victim), "precious\n");
  EXPECT_FALSE(exists(state_ + ".tmp"));
}

TEST_F(AuthStateFile, SaveNeverWritesThroughASymbolicLinkAtTheTemporaryName) {
  KeyRing r = initialized();
  const std::string target = write_file("victim", "precious bytes\n\x01\x02", 0600U);
  const std::string before = read_bytes(target);
  ASSERT_EQ(::symlink(target.c_str(), (state_ + ".tmp").c_str()), 0);
  ASSERT_EQ(::symlink(path("not-there").c_str(), path("second.state.tmp").c_str()), 0);
  StateFile f = file();
  f.load(&r);
  ASSERT_TRUE(r.commit(1, ArsnSlot::kCommand, 1002));
  ASSERT_EQ(f.save(r), 0);
  EXPECT_EQ(read_bytes(target), before) << "the symlink's target was written";
  EXPECT_FALSE(exists(state_ + ".tmp"));
  KeyRing after = ring();
  file().load(&after);
  EXPECT_EQ(arsn(after, 1), 1002);
  // A dangling symlink at the temporary name of a first start: the target is not created.
  KeyRing r2 = ring();
  StateFile(path("second.state"), tel_).init(&r2, 1, 0);
  EXPECT_FALSE(exists(path("not-there")));
}

TEST_F(AuthStateFile, SaveWithADirectoryAtTheTemporaryNameFailsAndKeepsTheOldState) {
  KeyRing r = initialized();
  ASSERT_EQ(::mkdir((state_ + ".tmp").c_str(), 0700), 0);
  StateFile f = file();
  f.load(&r);
  const std::string old = read_bytes(state_);
  ASSERT_TRUE(r.commit(1, ArsnSlot::kCommand, 1003));
  const int rc = f.save(r);
  EXPECT_LT(rc, 0);
  EXPECT_TRUE(rc == -EISDIR || rc == -EPERM) << rc;
  EXPECT_EQ(read_bytes(state_), old);
  EXPECT_EQ(f.writes(), 1) << "a failed save counted";
}

TEST_F(AuthStateFile, FailedRenameLeavesNoTemporary) {
  KeyRing r = initialized();
  StateFile f = file();
  f.load(&r);
  ASSERT_EQ(::unlink(state_.c_str()), 0);
  ASSERT_EQ(::mkdir(state_.c_str(), 0700), 0);  // rename over a directory fails
  EXPECT_EQ(f.save(r), -EISDIR);
  EXPECT_FALSE(exists(state_ + ".tmp"));
}

TEST_F(AuthStateFile, SaveBeforeLoadOrInitIsRefusedAndWritesNothing) {
  KeyRing r = initialized();
  const std::string old = read_bytes(state_);
  StateFile f = file();
  EXPECT_EQ(f.save(r), -EINVAL);
  EXPECT_EQ(read_bytes(state_), old);
  // A refused load (here: a changed file) does not allow a save over the file either.
  std::string changed = old;
  changed[changed.find("standby")] = 'S';
  write_file("node.state", changed);
  StateFile g = file();
  EXPECT_THROW(g.load(&r), std::runtime_error);
  EXPECT_EQ(g.save(r), -EINVAL);
  EXPECT_EQ(read_bytes(state_), changed);
}

TEST_F(AuthStateFile, SaveIntoARemovedDirectoryReturnsNegativeErrno) {
  const std::string sub = path("sub");
  ASSERT_EQ(::mkdir(sub.c_str(), 0700), 0);
  KeyRing r = ring();
  StateFile f(sub + "/node.state", tel_);
  f.init(&r, 1, 0);
  ASSERT_EQ(::unlink((sub + "/node.state").c_str()), 0);
  ASSERT_EQ(::rmdir(sub.c_str()), 0);
  EXPECT_EQ(f.save(r), -ENOENT);
}

// ---- the directory, the constructor, moves ----

TEST_F(AuthStateFile, ConstructorRefusesADirectoryGroupOrOthersCanWriteAndAMissingOne) {
  for (unsigned mode : {0770U, 0707U, 0777U}) {
    ASSERT_EQ(::chmod(dir_.c_str(), mode), 0);
    const std::string text = runtime_error_text([&] { (void)file(); });
    EXPECT_NE(text.find("its directory '" + dir_ + "' has mode"), std::string::npos) << text;
    EXPECT_NE(text.find("chmod go-w it"), std::string::npos) << text;
  }
  ASSERT_EQ(::chmod(dir_.c_str(), 0755), 0);  // readable by others, writable by no one else: fine
  EXPECT_NO_THROW((void)file());
  ASSERT_EQ(::chmod(dir_.c_str(), 0700), 0);
  EXPECT_THROW((void)StateFile(path("none/node.state"), tel_), std::runtime_error);
  EXPECT_THROW((void)StateFile(dir_ + "/", tel_), std::runtime_error);
  EXPECT_THROW((void)StateFile("", tel_), std::runtime_error);
}

TEST_F(AuthStateFile, ConstructorRefusesADirectoryOfAnotherUser) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give a directory to another user";
  ASSERT_EQ(::chown(dir_.c_str(), 65534, 65534), 0);
  EXPECT_NE(runtime_error_text([&] { (void)file(); }).find("is owned by uid 65534"), std::string::npos);
  ASSERT_EQ(::chown(dir_.c_str(), 0, 0), 0);
}

TEST_F(AuthStateFile, LoadAndInitRefuseARingWhoseTelemetryKeyIsNotTheFilesOne) {
  (void)initialized();
  KeyEntry other = tel_;
  other.key = generate_key(kTel, KeyRole::kTelemetry).key;
  KeyRing r = ring();  // holds tel_
  const std::string text = runtime_error_text([&] { StateFile(state_, other).load(&r); });
  EXPECT_NE(text.find("the ring's telemetry key 50 is not the telemetry key the state file was opened with"),
            std::string::npos) << text;
  const std::string text2 = runtime_error_text([&] { StateFile(path("b.state"), other).init(&r, 1, 0); });
  EXPECT_NE(text2.find("is not the telemetry key the state file was opened with"), std::string::npos) << text2;
  EXPECT_FALSE(exists(path("b.state")));
}

TEST_F(AuthStateFile, ConstructorRefusesAKeyThatIsNotATelemetryKey) {
  KeyEntry cmd = tel_;
  cmd.role = KeyRole::kCommand;
  EXPECT_NE(runtime_error_text([&] { (void)StateFile(state_, cmd); }).find("needs the node's telemetry key"),
            std::string::npos);
}

TEST_F(AuthStateFile, AMovedStateFileKeepsWorkingAndTheMovedFromOneRefuses) {
  KeyRing r = initialized();
  StateFile a = file();
  a.load(&r);
  StateFile b = std::move(a);
  EXPECT_EQ(b.save(r), 0);
  EXPECT_EQ(a.save(r), -EINVAL);  // NOLINT(bugprone-use-after-move): the moved-from state is the point
  StateFile c = file();
  c = std::move(b);
  EXPECT_EQ(c.save(r), 0);
  EXPECT_EQ(c.writes(), 3);
}

}  // namespace
}  // namespace evade::auth
