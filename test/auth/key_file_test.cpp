// Key files (docs/SECURITY.md KEY-1, KEY-2), each test in a fresh private directory: a generated
// key of every role written and read back is the same key; the file is created with mode 0600,
// never over an existing file or through a symbolic link, and never with a weak key; reading
// refuses a symbolic link (even to a valid key file), a directory, a FIFO (without blocking), a
// file of another user, a file group or others may access ("chmod 600"), a file over 64 KiB;
// load_into makes every command key standby (its order in the files gives it no state) and
// sensor and telemetry keys active. Malformed lines: key_file_malformed_lines_test.cpp; freed
// buffers: key_file_no_freed_key_text_test.cpp; weak keys and generate_key:
// key_generation_test.cpp.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "auth_file_test_support.hpp"
#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"
#include "key_file_test_support.hpp"

namespace evade::auth {
namespace {

using namespace test;  // the shared fixtures and helpers of test/auth

TEST_F(KeyFile, GeneratedKeysOfEveryRoleWrittenAndReadBackAreTheSameKeys) {
  const KeyRecord cmd = generate_key(7, KeyRole::kCommand);
  const KeyRecord sen = generate_key(2147483647, KeyRole::kSensor);
  const KeyRecord tel = generate_key(12, KeyRole::kTelemetry);
  EXPECT_EQ(cmd.id, 7);
  EXPECT_EQ(cmd.role, KeyRole::kCommand);
  EXPECT_NE(cmd.key, sen.key) << "two generated keys are equal";
  EXPECT_EQ(key_weakness(cmd.key), nullptr);
  for (const KeyRecord* k : {&cmd, &sen, &tel}) {
    const std::string p = path("k" + std::to_string(k->id) + ".key");
    write_key_file(p, *k);
    const std::vector<KeyRecord> r = read_key_file(p);
    ASSERT_EQ(r.size(), 1U);
    EXPECT_EQ(r[0].id, k->id);
    EXPECT_EQ(r[0].role, k->role);
    EXPECT_EQ(r[0].key, k->key);
  }
}

TEST_F(KeyFile, GenerateRefusesIdOutOfRange) {
  EXPECT_THROW(generate_key(0, KeyRole::kCommand), std::invalid_argument);
  EXPECT_THROW(generate_key(-1, KeyRole::kSensor), std::invalid_argument);
}

TEST_F(KeyFile, WrittenFileHasMode0600) {
  const std::string p = path("k.key");
  write_key_file(p, generate_key(1, KeyRole::kCommand));
  EXPECT_EQ(mode_of(p), 0600U);
}

TEST_F(KeyFile, WriteRefusesAnExistingFile) {
  const std::string p = write_file("existing.key", "do not replace me\n");
  const std::string text = runtime_error_text([&] { write_key_file(p, generate_key(1, KeyRole::kCommand)); });
  EXPECT_NE(text.find(p), std::string::npos) << text;
  EXPECT_EQ(read_bytes(p), "do not replace me\n");
}

// A symbolic link planted at the new key file's path, dangling or not: nothing is written
// through it (the key does not land in the link's target).
TEST_F(KeyFile, WriteNeverFollowsASymbolicLinkAtThePath) {
  const std::string target = write_file("target", "untouched\n");
  const std::string p = path("new.key");
  ASSERT_EQ(::symlink(target.c_str(), p.c_str()), 0);
  EXPECT_THROW(write_key_file(p, generate_key(1, KeyRole::kCommand)), std::runtime_error);
  EXPECT_EQ(read_bytes(target), "untouched\n");
  const std::string dangling = path("dangling.key");
  ASSERT_EQ(::symlink(path("nowhere").c_str(), dangling.c_str()), 0);
  EXPECT_THROW(write_key_file(dangling, generate_key(1, KeyRole::kCommand)), std::runtime_error);
  EXPECT_FALSE(exists(path("nowhere")));
}

TEST_F(KeyFile, WriteRefusesAWeakKeyWithoutShowingIt) {
  KeyRecord k;
  k.id = 3;
  for (std::size_t i = 0; i < k.key.size(); ++i) k.key[i] = static_cast<std::uint8_t>(0x40 + i);
  const std::string text = runtime_error_text([&] { write_key_file(path("weak.key"), k); });
  EXPECT_NE(text.find("weak"), std::string::npos) << text;
  expect_no_key_text(text, {to_hex(k.key)}, "weak");
  EXPECT_FALSE(exists(path("weak.key")));
}

TEST_F(KeyFile, ReadRefusesGroupOrOtherAccessWithoutShowingTheKey) {
  for (unsigned mode : {0644U, 0640U, 0604U, 0660U, 0601U, 0610U, 0666U}) {
    const std::string p = write_file("open.key", "key 1 command " + hex_a() + "\n", mode);
    const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
    EXPECT_NE(text.find("chmod 600"), std::string::npos) << std::oct << mode << ": " << text;
    EXPECT_NE(text.find(p), std::string::npos) << text;
    expect_no_key_text(text, {hex_a()}, "mode");
  }
  // Owner-only modes are fine (0400: read-only for its owner).
  EXPECT_EQ(read_key_file(write_file("ro.key", "key 1 command " + hex_a() + "\n", 0400U)).size(), 1U);
}

TEST_F(KeyFile, ReadRefusesADirectory) {
  const std::string p = path("sub");
  ASSERT_EQ(::mkdir(p.c_str(), 0700), 0);
  const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
  EXPECT_NE(text.find("not a regular file"), std::string::npos) << text;
}

TEST_F(KeyFile, ReadRefusesAMissingFile) {
  const std::string text = runtime_error_text([&] { (void)read_key_file(path("none.key")); });
  EXPECT_NE(text.find("none.key"), std::string::npos) << text;
}

TEST_F(KeyFile, ReadRefusesASymbolicLinkEvenToAValidKeyFile) {
  const std::string target = write_file("real.key", "key 1 command " + hex_a() + "\n");
  ASSERT_EQ(read_key_file(target).size(), 1U);
  const std::string p = path("link.key");
  ASSERT_EQ(::symlink(target.c_str(), p.c_str()), 0);
  const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
  EXPECT_NE(text.find("is a symbolic link: refused"), std::string::npos) << text;
  expect_no_key_text(text, {hex_a()}, "symlink");
}

// A FIFO at the key file's path: opening it for reading would block until a writer comes; the
// read must refuse it at once. The read runs in a child that an alarm kills after 5 s.
TEST_F(KeyFile, ReadRefusesAFifoWithoutBlocking) {
  const std::string p = path("fifo.key");
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0) << std::strerror(errno);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    (void)::alarm(5);
    try {
      (void)read_key_file(p);
    } catch (const std::runtime_error& e) {
      ::_exit(std::strstr(e.what(), "not a regular file") != nullptr ? 0 : 2);
    }
    ::_exit(3);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "the read blocked on the FIFO (killed by the alarm)";
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST_F(KeyFile, ReadRefusesAFileOwnedByAnotherUser) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give a file to another user";
  const std::string p = write_file("theirs.key", "key 1 command " + hex_a() + "\n");
  ASSERT_EQ(::chown(p.c_str(), 65534, 65534), 0) << std::strerror(errno);
  const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
  EXPECT_NE(text.find("owned by uid 65534"), std::string::npos) << text;
  expect_no_key_text(text, {hex_a()}, "owner");
}

TEST_F(KeyFile, ReadRefusesAFileLargerThan64KiBAndReadsOneOfExactly64KiB) {
  const std::string line = "key 1 command " + hex_a() + "\n";
  std::string exact = line;
  while (exact.size() + 80 <= kMaxKeyFileBytes) exact += "# " + std::string(77, 'x') + "\n";
  exact += "#" + std::string(kMaxKeyFileBytes - exact.size() - 2, 'y') + "\n";
  ASSERT_EQ(exact.size(), kMaxKeyFileBytes);
  EXPECT_EQ(read_key_file(write_file("exact.key", exact)).size(), 1U);
  const std::string text = runtime_error_text([&] { (void)read_key_file(write_file("big.key", exact + "\n")); });
  EXPECT_NE(text.find("larger than 65536 bytes"), std::string::npos) << text;
  // A 1 MiB line of key text.
  std::string huge = "key 1 command ";
  while (huge.size() < (1U << 20U)) huge += hex_a();
  const std::string text2 = runtime_error_text([&] { (void)read_key_file(write_file("huge.key", huge + "\n")); });
  EXPECT_NE(text2.find("larger than"), std::string::npos) << text2;
  expect_no_key_text(text2, {hex_a()}, "1 MiB line");
}

// KEY-2: states never come from the order of --keys. A new command key listed first (the
// attack: it became active without a signed activation) is standby like every command key.
TEST(KeyFileLoadInto, EveryCommandKeyIsStandbyWhereverItIsListed) {
  std::vector<KeyRecord> records;
  for (std::int32_t id : {5, 6, 7}) records.push_back(generate_key(id, KeyRole::kCommand));
  records.insert(records.begin() + 1, generate_key(30, KeyRole::kSensor));
  records.push_back(generate_key(31, KeyRole::kTelemetry));
  // ids in order: 5 command, 30 sensor, 6 command, 7 command, 31 telemetry.
  KeyRing ring;
  load_into(records, &ring);
  ASSERT_EQ(ring.size(), 5U);
  for (std::int32_t id : {5, 6, 7}) EXPECT_EQ(ring.find(id)->state, KeyState::kStandby) << id;
  EXPECT_EQ(ring.find(30)->state, KeyState::kActive);
  EXPECT_EQ(ring.find(31)->state, KeyState::kActive);
  EXPECT_EQ(ring.find(30)->role, KeyRole::kSensor);
  EXPECT_EQ(ring.telemetry_key()->id, 31);
  EXPECT_EQ(ring.find(6)->key, records[2].key);
  EXPECT_EQ(ring.active_command_keys(), 0);
}

TEST(KeyFileLoadInto, ANewCommandKeyListedFirstDoesNotBecomeActive) {
  KeyRing ring;
  load_into({generate_key(9, KeyRole::kCommand)}, &ring);  // the attacker's new key, first
  load_into({generate_key(1, KeyRole::kCommand)}, &ring);  // the ground's key
  EXPECT_EQ(ring.find(9)->state, KeyState::kStandby);
  EXPECT_EQ(ring.find(1)->state, KeyState::kStandby);
  EXPECT_EQ(ring.active_command_keys(), 0);
}

TEST(KeyFileLoadInto, RingRefusalThrowsNamingTheId) {
  KeyRing ring;
  load_into({generate_key(4, KeyRole::kCommand), generate_key(5, KeyRole::kTelemetry)}, &ring);
  const std::string text =
      runtime_error_text([&] { load_into({generate_key(4, KeyRole::kSensor)}, &ring); });
  EXPECT_NE(text.find("key 4"), std::string::npos) << text;
  const std::string text2 =
      runtime_error_text([&] { load_into({generate_key(6, KeyRole::kTelemetry)}, &ring); });
  EXPECT_NE(text2.find("key 6: a second telemetry key"), std::string::npos) << text2;
}

TEST(KeyFileRoleName, NamesAndParsesEveryRole) {
  EXPECT_STREQ(role_name(KeyRole::kCommand), "command");
  EXPECT_STREQ(role_name(KeyRole::kSensor), "sensor");
  EXPECT_STREQ(role_name(KeyRole::kTelemetry), "telemetry");
  for (KeyRole r : {KeyRole::kCommand, KeyRole::kSensor, KeyRole::kTelemetry}) {
    KeyRole parsed = KeyRole::kCommand;
    EXPECT_TRUE(parse_role(role_name(r), &parsed));
    EXPECT_EQ(parsed, r);
  }
  KeyRole parsed = KeyRole::kSensor;
  EXPECT_FALSE(parse_role("Command", &parsed));
  EXPECT_FALSE(parse_role("", &parsed));
  EXPECT_FALSE(parse_role("commands", &parsed));
  EXPECT_EQ(parsed, KeyRole::kSensor);
}

}  // namespace
}  // namespace evade::auth
