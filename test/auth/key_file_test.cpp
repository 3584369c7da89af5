// Key files (docs/SECURITY.md KEY-1) and the persisted authentication state (AUTH-4), each
// test in its own fresh directory under /tmp. Key files: a generated key written and read
// back is the same key; the file is created with mode 0600 and never over an existing file;
// a file that group or others may read is refused with a "chmod 600" hint; every malformed
// line is refused naming its line number, and no error text ever contains the key's hex;
// comments and blank lines are skipped; load_into makes the first command key active and
// the others standby. State file: save then load restores key states and command ARSNs; a
// missing file is a first start; a malformed file is refused naming the line; an empty path
// disables it; a failed save returns -errno; no temporary file is ever left behind.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"
#include "evade/auth/state_file.hpp"

namespace evade::auth {
namespace {

// 64 hex digits that appear in no message: the key text the errors must not echo.
std::string hex_a() { return "00112233445566778899aabbccddeeff0123456789abcdef0f1e2d3c4b5a6978"; }
std::string hex_b() { return "ffeeddccbbaa99887766554433221100fedcba98765432100123456789abcdef"; }

std::string to_hex(const KeyBytes& k) {
  static const char* const kDigits = "0123456789abcdef";
  std::string s;
  for (std::uint8_t b : k) {
    s.push_back(kDigits[b >> 4U]);
    s.push_back(kDigits[b & 0x0FU]);
  }
  return s;
}

bool exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

unsigned mode_of(const std::string& path) {
  struct stat st {};
  EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
  return static_cast<unsigned>(st.st_mode & 07777U);
}

// The text of the std::runtime_error that f throws ("" and a test failure if none).
template <typename F>
std::string runtime_error_text(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  } catch (...) {
    ADD_FAILURE() << "threw something other than std::runtime_error";
    return "";
  }
  ADD_FAILURE() << "did not throw";
  return "";
}

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/evade_auth_test_XXXXXX";
    const char* d = ::mkdtemp(tmpl);
    ASSERT_NE(d, nullptr) << std::strerror(errno);
    dir_ = d;
  }
  void TearDown() override {
    if (dir_.empty()) return;
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
    EXPECT_FALSE(ec) << "cannot remove " << dir_ << ": " << ec.message();
  }

  std::string path(const std::string& name) const { return dir_ + "/" + name; }

  // Writes text to a new file with the given mode (chmod: independent of the umask).
  std::string write_file(const std::string& name, const std::string& text,
                         unsigned mode = 0600U) const {
    std::string p = path(name);
    {
      std::ofstream f(p, std::ios::binary | std::ios::trunc);
      EXPECT_TRUE(f.good()) << p;
      f << text;
      f.flush();
      EXPECT_TRUE(f.good()) << p;
    }
    EXPECT_EQ(::chmod(p.c_str(), static_cast<mode_t>(mode)), 0) << p << ": " << std::strerror(errno);
    return p;
  }

  std::string dir_;
};

// ---- key files ----

using KeyFile = TempDir;

TEST_F(KeyFile, GenerateWriteReadRoundTrip) {
  const KeyRecord cmd = generate_key(7, KeyRole::kCommand);
  const KeyRecord sen = generate_key(2147483647, KeyRole::kSensor);
  EXPECT_EQ(cmd.id, 7);
  EXPECT_EQ(cmd.role, KeyRole::kCommand);
  EXPECT_NE(cmd.key, sen.key) << "two generated keys are equal";
  EXPECT_NE(cmd.key, KeyBytes{}) << "a generated key is all zero";

  const std::string p1 = path("cmd.key");
  const std::string p2 = path("sensor.key");
  write_key_file(p1, cmd);
  write_key_file(p2, sen);

  const std::vector<KeyRecord> r1 = read_key_file(p1);
  ASSERT_EQ(r1.size(), 1U);
  EXPECT_EQ(r1[0].id, 7);
  EXPECT_EQ(r1[0].role, KeyRole::kCommand);
  EXPECT_EQ(r1[0].key, cmd.key);

  const std::vector<KeyRecord> r2 = read_key_file(p2);
  ASSERT_EQ(r2.size(), 1U);
  EXPECT_EQ(r2[0].id, 2147483647);
  EXPECT_EQ(r2[0].role, KeyRole::kSensor);
  EXPECT_EQ(r2[0].key, sen.key);
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
  std::ifstream f(p);
  std::stringstream content;
  content << f.rdbuf();
  EXPECT_EQ(content.str(), "do not replace me\n");
}

TEST_F(KeyFile, ReadRefusesMode0644And0640WithoutShowingTheKey) {
  for (unsigned mode : {0644U, 0640U, 0604U, 0660U}) {
    const std::string p = write_file("open.key", "key 1 command " + hex_a() + "\n", mode);
    const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
    EXPECT_NE(text.find("chmod 600"), std::string::npos) << std::oct << mode << ": " << text;
    EXPECT_EQ(text.find(hex_a()), std::string::npos) << text;
    EXPECT_EQ(text.find(hex_a().substr(0, 16)), std::string::npos) << text;
    ASSERT_EQ(::unlink(p.c_str()), 0);
  }
}

TEST_F(KeyFile, ReadRefusesADirectory) {
  const std::string p = path("sub");
  ASSERT_EQ(::mkdir(p.c_str(), 0700), 0);
  EXPECT_THROW((void)read_key_file(p), std::runtime_error);
}

TEST_F(KeyFile, ReadRefusesAMissingFile) {
  const std::string text = runtime_error_text([&] { (void)read_key_file(path("none.key")); });
  EXPECT_NE(text.find("none.key"), std::string::npos) << text;
}

TEST_F(KeyFile, MalformedLinesNameTheLineAndNeverTheKey) {
  struct Case {
    const char* what;
    std::string line;
    std::string secret;  // the key text that must not appear in the error
  };
  const std::string hex63 = hex_a().substr(0, 63);
  std::string non_hex = hex_a();
  non_hex[40] = 'g';
  const std::vector<Case> cases = {
      {"wrong word", "kee 1 command " + hex_a(), hex_a()},
      {"id 0", "key 0 command " + hex_a(), hex_a()},
      {"negative id", "key -4 command " + hex_a(), hex_a()},
      {"id above 2^31-1", "key 2147483648 command " + hex_a(), hex_a()},
      {"id not a number", "key one command " + hex_a(), hex_a()},
      {"bad role", "key 1 ground " + hex_a(), hex_a()},
      {"63 hex digits", "key 1 command " + hex63, hex63},
      {"65 hex digits", "key 1 command " + hex_a() + "0", hex_a()},
      {"non-hex digit", "key 1 command " + non_hex, non_hex},
      {"trailing word", "key 1 command " + hex_a() + " extra", hex_a()},
      {"missing key", "key 1 command", ""},
  };
  for (const Case& c : cases) {
    // The bad line is line 4, after a comment, a blank line and a good key.
    const std::string p = write_file("bad.key", "# keys\n\nkey 9 sensor " + hex_b() + "\n" + c.line + "\n");
    const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
    EXPECT_NE(text.find("line 4"), std::string::npos) << c.what << ": " << text;
    EXPECT_NE(text.find(p), std::string::npos) << c.what << ": " << text;
    if (!c.secret.empty()) {
      EXPECT_EQ(text.find(c.secret), std::string::npos) << c.what << ": " << text;
      EXPECT_EQ(text.find(c.secret.substr(0, 16)), std::string::npos) << c.what << ": " << text;
    }
    EXPECT_EQ(text.find(hex_b()), std::string::npos) << c.what << ": " << text;
    ASSERT_EQ(::unlink(p.c_str()), 0);
  }
}

TEST_F(KeyFile, DuplicateIdsAreRefused) {
  const std::string p = write_file("dup.key", "key 3 command " + hex_a() + "\nkey 3 sensor " + hex_b() + "\n");
  const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
  EXPECT_NE(text.find("line 2"), std::string::npos) << text;
  EXPECT_EQ(text.find(hex_a()), std::string::npos) << text;
  EXPECT_EQ(text.find(hex_b()), std::string::npos) << text;
}

TEST_F(KeyFile, EmptyFileIsRefused) {
  EXPECT_THROW((void)read_key_file(write_file("empty.key", "")), std::runtime_error);
  EXPECT_THROW((void)read_key_file(write_file("comments.key", "# only a comment\n\n")),
               std::runtime_error);
}

TEST_F(KeyFile, CommentsAndBlankLinesAreSkipped) {
  const std::string p = write_file("many.key",
                                   "# evade keys\n"
                                   "\n"
                                   "   \t\n"
                                   "  # an indented comment\n"
                                   "key 1 command " + hex_a() + "\n"
                                   "\n"
                                   "key 20 sensor " + hex_b() + "\r\n"
                                   "# the end\n");
  const std::vector<KeyRecord> r = read_key_file(p);
  ASSERT_EQ(r.size(), 2U);
  EXPECT_EQ(r[0].id, 1);
  EXPECT_EQ(r[0].role, KeyRole::kCommand);
  EXPECT_EQ(to_hex(r[0].key), hex_a());
  EXPECT_EQ(r[1].id, 20);
  EXPECT_EQ(r[1].role, KeyRole::kSensor);
  EXPECT_EQ(to_hex(r[1].key), hex_b());
}

TEST_F(KeyFile, UppercaseHexIsAccepted) {
  std::string upper = hex_a();
  for (char& ch : upper) {
    if (ch >= 'a' && ch <= 'f') ch = static_cast<char>(ch - 'a' + 'A');
  }
  const std::vector<KeyRecord> r = read_key_file(write_file("upper.key", "key 5 sensor " + upper + "\n"));
  ASSERT_EQ(r.size(), 1U);
  EXPECT_EQ(to_hex(r[0].key), hex_a());
}

TEST(KeyFileLoadInto, FirstCommandKeyActiveOthersStandbySensorsActive) {
  std::vector<KeyRecord> records;
  for (std::int32_t id : {5, 6, 7}) records.push_back(generate_key(id, KeyRole::kCommand));
  records.insert(records.begin() + 1, generate_key(30, KeyRole::kSensor));
  records.push_back(generate_key(31, KeyRole::kSensor));
  // ids in order: 5 command, 30 sensor, 6 command, 7 command, 31 sensor.
  KeyRing ring;
  load_into(records, &ring);
  ASSERT_EQ(ring.size(), 5U);
  EXPECT_EQ(ring.find(5)->state, KeyState::kActive);
  EXPECT_EQ(ring.find(6)->state, KeyState::kStandby);
  EXPECT_EQ(ring.find(7)->state, KeyState::kStandby);
  EXPECT_EQ(ring.find(30)->state, KeyState::kActive);
  EXPECT_EQ(ring.find(31)->state, KeyState::kActive);
  EXPECT_EQ(ring.find(30)->role, KeyRole::kSensor);
  EXPECT_EQ(ring.find(6)->key, records[2].key);
  EXPECT_EQ(ring.active_command_keys(), 1);
}

TEST(KeyFileLoadInto, SensorKeysFirstStillLeaveOneActiveCommandKey) {
  const std::vector<KeyRecord> records = {generate_key(30, KeyRole::kSensor),
                                          generate_key(1, KeyRole::kCommand),
                                          generate_key(2, KeyRole::kCommand)};
  KeyRing ring;
  load_into(records, &ring);
  EXPECT_EQ(ring.find(1)->state, KeyState::kActive);
  EXPECT_EQ(ring.find(2)->state, KeyState::kStandby);
}

TEST(KeyFileLoadInto, RingRefusalThrowsNamingTheId) {
  KeyRing ring;
  load_into({generate_key(4, KeyRole::kCommand)}, &ring);
  const std::string text =
      runtime_error_text([&] { load_into({generate_key(4, KeyRole::kSensor)}, &ring); });
  EXPECT_NE(text.find("key 4"), std::string::npos) << text;
  // The second file's command key joins as standby: the ring already has an active one.
  load_into({generate_key(8, KeyRole::kCommand)}, &ring);
  EXPECT_EQ(ring.find(8)->state, KeyState::kStandby);
}

TEST(KeyFileRoleName, Names) {
  EXPECT_STREQ(role_name(KeyRole::kCommand), "command");
  EXPECT_STREQ(role_name(KeyRole::kSensor), "sensor");
}

// ---- state file ----

using AuthStateFile = TempDir;

KeyRing three_keys() {
  KeyRing ring;
  KeyBytes k{};
  k.fill(1);
  EXPECT_EQ(ring.add(1, KeyRole::kCommand, k, KeyState::kActive), nullptr);
  k.fill(2);
  EXPECT_EQ(ring.add(2, KeyRole::kCommand, k, KeyState::kStandby), nullptr);
  k.fill(3);
  EXPECT_EQ(ring.add(3, KeyRole::kSensor, k, KeyState::kActive), nullptr);
  return ring;
}

TEST_F(AuthStateFile, SaveThenLoadRestoresStatesAndCommandArsn) {
  KeyRing ring = three_keys();
  ASSERT_TRUE(ring.restore(1, KeyState::kRetired, 123456789012LL));
  ASSERT_TRUE(ring.restore(2, KeyState::kActive, 77));
  const StateFile sf(path("auth.state"));
  EXPECT_TRUE(sf.enabled());
  EXPECT_EQ(sf.path(), path("auth.state"));
  ASSERT_EQ(sf.save(ring), 0);
  EXPECT_FALSE(exists(path("auth.state.tmp")));

  KeyRing fresh = three_keys();
  sf.load(&fresh);
  EXPECT_EQ(fresh.find(1)->state, KeyState::kRetired);
  EXPECT_EQ(fresh.find(1)->arsn[static_cast<std::size_t>(ArsnSlot::kCommand)], 123456789012LL);
  EXPECT_EQ(fresh.find(2)->state, KeyState::kActive);
  EXPECT_EQ(fresh.find(2)->arsn[static_cast<std::size_t>(ArsnSlot::kCommand)], 77);
  EXPECT_EQ(fresh.find(3)->state, KeyState::kActive);
  EXPECT_FALSE(fresh.dirty());
}

TEST_F(AuthStateFile, SaveReplacesTheOldStateAndLeavesNoTemporary) {
  KeyRing ring = three_keys();
  const StateFile sf(path("auth.state"));
  ASSERT_EQ(sf.save(ring), 0);
  ASSERT_TRUE(ring.restore(1, KeyState::kActive, 9));
  ASSERT_EQ(sf.save(ring), 0);
  EXPECT_FALSE(exists(path("auth.state.tmp")));
  KeyRing fresh = three_keys();
  sf.load(&fresh);
  EXPECT_EQ(fresh.find(1)->arsn[static_cast<std::size_t>(ArsnSlot::kCommand)], 9);
  EXPECT_EQ(mode_of(path("auth.state")), 0600U);
}

TEST_F(AuthStateFile, MissingFileLoadsNothing) {
  KeyRing ring = three_keys();
  const StateFile sf(path("never-written.state"));
  EXPECT_NO_THROW(sf.load(&ring));
  EXPECT_EQ(ring.find(1)->state, KeyState::kActive);
  EXPECT_EQ(ring.find(2)->state, KeyState::kStandby);
  EXPECT_EQ(ring.find(1)->arsn[static_cast<std::size_t>(ArsnSlot::kCommand)], 0);
}

TEST_F(AuthStateFile, MalformedFileThrowsNamingTheLine) {
  const std::vector<std::string> bad_lines = {
      "key 2 sleeping 5",   // bad state
      "key 0 active 5",     // bad id
      "key 2 active -1",    // negative ARSN
      "kee 2 active 5",     // wrong word
      "key 2 active",       // missing ARSN
      "key 2 active 5 junk",  // trailing text
  };
  for (const std::string& bad : bad_lines) {
    const std::string p = write_file("auth.state", "evade-auth-state 1\nkey 1 active 4\n" + bad + "\n");
    KeyRing ring = three_keys();
    const std::string text = runtime_error_text([&] { StateFile(p).load(&ring); });
    EXPECT_NE(text.find("line 3"), std::string::npos) << bad << ": " << text;
    EXPECT_NE(text.find(p), std::string::npos) << bad << ": " << text;
  }
}

TEST_F(AuthStateFile, WrongHeaderThrows) {
  const std::string p = write_file("auth.state", "evade-auth-state 2\nkey 1 active 4\n");
  KeyRing ring = three_keys();
  EXPECT_THROW(StateFile(p).load(&ring), std::runtime_error);
}

// An empty state file or a directory at the path must not pass for a first start: that would
// reset every ARSN (reopening replay) and bring retired keys back.
TEST_F(AuthStateFile, EmptyFileOrADirectoryIsRefusedNotAFirstStart) {
  const std::string p = write_file("auth.state", "");
  KeyRing ring = three_keys();
  EXPECT_THROW(StateFile(p).load(&ring), std::runtime_error);
  const std::string d = path("a-directory");
  ASSERT_EQ(mkdir(d.c_str(), 0700), 0);
  EXPECT_THROW(StateFile(d).load(&ring), std::runtime_error);
  (void)rmdir(d.c_str());
}

TEST_F(AuthStateFile, KeysTheRingDoesNotHoldAreIgnored) {
  const std::string p = write_file("auth.state", "evade-auth-state 1\nkey 99 retired 4\nkey 1 active 8\n");
  KeyRing ring = three_keys();
  EXPECT_NO_THROW(StateFile(p).load(&ring));
  EXPECT_EQ(ring.find(1)->arsn[static_cast<std::size_t>(ArsnSlot::kCommand)], 8);
  EXPECT_EQ(ring.find(99), nullptr);
}

TEST_F(AuthStateFile, EmptyPathIsDisabled) {
  const StateFile sf("");
  EXPECT_FALSE(sf.enabled());
  KeyRing ring = three_keys();
  ASSERT_TRUE(ring.restore(1, KeyState::kActive, 5));
  EXPECT_EQ(sf.save(ring), 0);
  KeyRing fresh = three_keys();
  EXPECT_NO_THROW(sf.load(&fresh));
  EXPECT_EQ(fresh.find(1)->arsn[static_cast<std::size_t>(ArsnSlot::kCommand)], 0);
}

TEST_F(AuthStateFile, SaveIntoMissingDirectoryReturnsNegativeErrno) {
  const std::string p = path("no-such-dir/auth.state");
  const StateFile sf(p);
  const int rc = sf.save(three_keys());
  EXPECT_LT(rc, 0);
  EXPECT_EQ(rc, -ENOENT);
  EXPECT_FALSE(exists(p + ".tmp"));
  EXPECT_FALSE(exists(p));
}

TEST_F(AuthStateFile, FailedRenameRemovesTheTemporary) {
  // The state path is a directory: the temporary is written, the rename over it fails, and
  // the temporary must not remain.
  const std::string p = path("auth.state");
  ASSERT_EQ(::mkdir(p.c_str(), 0700), 0);
  const int rc = StateFile(p).save(three_keys());
  EXPECT_LT(rc, 0);
  EXPECT_EQ(rc, -EISDIR);
  EXPECT_FALSE(exists(p + ".tmp"));
}

}  // namespace
}  // namespace evade::auth
