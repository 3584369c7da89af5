// Key files (docs/SECURITY.md KEY-1, KEY-2), each test in a fresh private directory: a generated
// key of every role written and read back is the same key; the file is created with mode 0600,
// never over an existing file or through a symbolic link, and never with a weak key; reading
// refuses a symbolic link (even to a valid key file), a directory, a FIFO (without blocking), a
// file of another user, a file group or others may access ("chmod 600"), a file over 64 KiB;
// every malformed line (fields in any wrong order, a missing or extra field, bad id, role or
// key text, upper case, CRLF, NUL, a duplicate id) is refused naming its line and its field,
// and no error text ever contains the key's hex or any 16-digit window of it; no heap block is
// freed still holding key text, on success or on any error; weak keys are refused with their
// reason; generate_key redraws weak draws and gives up after 8; load_into makes every command
// key standby (its order in the files gives it no state) and sensor and telemetry keys active.
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
#include "freed_memory_scan.hpp"

namespace evade::auth {
namespace {

using test::exists;
using test::key_text_in;
using test::mode_of;
using test::read_bytes;
using test::runtime_error_text;
using test::TempDir;
using test::to_hex;

// 64 hex digits (32 distinct byte values) that appear in no message: key text errors must not echo.
std::string hex_a() { return "00112233445566778899aabbccddeeff0123456789abcdef0f1e2d3c4b5a6978"; }
std::string hex_b() { return "ffeeddccbbaa99887766554433221100fedcba98765432100123456789abcdef"; }

KeyBytes bytes_of(const std::string& hex) {
  KeyBytes k{};
  for (std::size_t i = 0; i < k.size(); ++i) {
    k[i] = static_cast<std::uint8_t>(std::stoul(hex.substr(2 * i, 2), nullptr, 16));
  }
  return k;
}

// Checks that text contains none of the key texts (nor a 16-digit window, either case).
void expect_no_key_text(const std::string& text, const std::vector<std::string>& hexes,
                        const std::string& what) {
  for (const std::string& h : hexes) {
    EXPECT_EQ(key_text_in(text, h), "") << what << ": " << text;
  }
}

using KeyFile = TempDir;

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

struct BadLine {
  const char* what;
  std::string line;
  const char* field;  // the part of the message that says which field (or what) is wrong
};

std::vector<BadLine> bad_lines() {
  const std::string h = hex_a();
  std::string non_hex = h;
  non_hex[40] = 'g';
  std::string with_nul = h;
  with_nul[10] = '\0';
  return {
      {"wrong word", "kee 1 command " + h, "first field must be the word key"},
      {"id 0", "key 0 command " + h, "the id (second field)"},
      {"negative id", "key -4 command " + h, "the id (second field)"},
      {"id above 2^31-1", "key 2147483648 command " + h, "the id (second field)"},
      {"id with a sign", "key +4 command " + h, "the id (second field)"},
      {"id not a number", "key one command " + h, "the id (second field)"},
      {"the hex in place of the id", "key " + h + " command " + h, "the id (second field)"},
      {"bad role", "key 1 ground " + h, "the role (third field) must be command, sensor or telemetry"},
      {"role in capitals", "key 1 COMMAND " + h, "the role (third field)"},
      {"the hex in place of the role", "key 1 " + h + " " + h, "the role (third field)"},
      {"63 hex digits", "key 1 command " + h.substr(0, 63), "64 hex digits, not 63"},
      {"65 hex digits", "key 1 command " + h + "0", "64 hex digits, not 65"},
      {"non-hex digit", "key 1 command " + non_hex, "not a hex digit"},
      {"upper case", "key 1 command " + test::upper(h), "upper-case"},
      {"0x prefix", "key 1 command 0x" + h.substr(2), "not a hex digit"},
      {"trailing word", "key 1 command " + h + " extra", "an extra field"},
      {"the hex twice", "key 1 command " + h + " " + h, "an extra field"},
      {"hex split in two", "key 1 command " + h.substr(0, 32) + " " + h.substr(32), "an extra field"},
      {"missing key", "key 1 command", "a field is missing"},
      {"missing role", "key 1 " + h, "a field is missing"},
      {"missing id", "key command " + h, "a field is missing"},
      {"missing word", "1 command " + h, "a field is missing"},
      {"only the hex", h, "a field is missing"},
      {"carriage return", "key 1 command " + h + "\r", "carriage return"},
      {"NUL byte in the key", "key 1 command " + with_nul, "NUL byte"},
      {"NUL byte after the key", "key 1 command " + h + std::string(1, '\0'), "NUL byte"},
      {"escape character", "key 1 command\x1b" + h, "control character"},
      {"all-zero key", "key 1 command " + std::string(64, '0'), "weak (all zero)"},
      {"arithmetic key", "key 1 command 000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f",
       "weak (an arithmetic sequence"},
      {"low-entropy key", "key 1 command " + std::string("0102030405060708090a0b0c0d0e0f01") + "0102030405060708090a0b0c0d0e0f01",
       "weak (fewer than 16 distinct byte values)"},
  };
}

// The bad line is line 4, after a comment, a blank line and a good key (whose text must not
// appear either).
TEST_F(KeyFile, MalformedLinesNameTheLineAndTheFieldAndNeverTheKey) {
  for (const BadLine& c : bad_lines()) {
    const std::string p = write_file("bad.key", "# keys\n\nkey 9 sensor " + hex_b() + "\n" + c.line + "\n");
    const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
    EXPECT_NE(text.find("key file '" + p + "' line 4: "), std::string::npos) << c.what << ": " << text;
    EXPECT_NE(text.find(c.field), std::string::npos) << c.what << ": " << text;
    expect_no_key_text(text, {hex_a(), hex_b(), test::upper(hex_a())}, c.what);
  }
}

// Every order of the four fields but the right one, with a genuinely random key.
TEST_F(KeyFile, EveryWrongOrderOfTheFourFieldsIsRefusedWithoutTheKey) {
  const KeyRecord k = generate_key(5, KeyRole::kCommand);
  const std::string hex = to_hex(k.key);
  std::array<std::string, 4> fields = {"key", "5", "command", hex};
  std::array<int, 4> order = {0, 1, 2, 3};
  int refused = 0;
  do {
    if (order == std::array<int, 4>{0, 1, 2, 3}) continue;
    std::string line;
    for (int i : order) line += (line.empty() ? "" : " ") + fields[static_cast<std::size_t>(i)];
    const std::string p = write_file("swapped.key", line + "\n");
    const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
    EXPECT_NE(text.find("line 1: "), std::string::npos) << line.substr(0, 20) << ": " << text;
    EXPECT_NE(text.find("field"), std::string::npos) << text;
    expect_no_key_text(text, {hex}, "swapped");
    ++refused;
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_EQ(refused, 23);
}

TEST_F(KeyFile, DuplicateIdsAreRefusedNamingBothLines) {
  const std::string p = write_file("dup.key", "key 3 command " + hex_a() + "\nkey 3 sensor " + hex_b() + "\n");
  const std::string text = runtime_error_text([&] { (void)read_key_file(p); });
  EXPECT_NE(text.find("line 2: key id 3 appears twice (first on line 1)"), std::string::npos) << text;
  expect_no_key_text(text, {hex_a(), hex_b()}, "duplicate");
}

TEST_F(KeyFile, FileWithoutAKeyIsRefused) {
  for (const char* content : {"", "# only a comment\n\n", "\n\n\n", " \t \n"}) {
    const std::string text = runtime_error_text([&] { (void)read_key_file(write_file("empty.key", content)); });
    EXPECT_NE(text.find("holds no key"), std::string::npos) << text;
  }
}

TEST_F(KeyFile, CommentsBlankLinesAndTabsAreSkipped) {
  const std::string p = write_file("many.key",
                                   "# evade keys\n"
                                   "\n"
                                   "   \t\n"
                                   "  # an indented comment with key text " + hex_b() + "\n"
                                   "key 1 command " + hex_a() + "\n"
                                   "\n"
                                   "\tkey\t20  sensor\t" + hex_b() + "  \n"
                                   "key 21 telemetry " + hex_b().substr(32) + hex_b().substr(0, 32) + "\n"
                                   "# the end, no newline after the last line");
  const std::vector<KeyRecord> r = read_key_file(p);
  ASSERT_EQ(r.size(), 3U);
  EXPECT_EQ(r[0].id, 1);
  EXPECT_EQ(r[0].role, KeyRole::kCommand);
  EXPECT_EQ(to_hex(r[0].key), hex_a());
  EXPECT_EQ(r[1].id, 20);
  EXPECT_EQ(r[1].role, KeyRole::kSensor);
  EXPECT_EQ(to_hex(r[1].key), hex_b());
  EXPECT_EQ(r[2].role, KeyRole::kTelemetry);
}

TEST_F(KeyFile, LastLineWithoutANewlineIsRead) {
  const std::vector<KeyRecord> r = read_key_file(write_file("nonl.key", "key 2 sensor " + hex_a()));
  ASSERT_EQ(r.size(), 1U);
  EXPECT_EQ(r[0].key, bytes_of(hex_a()));
}

TEST_F(KeyFile, UpperCaseHexIsRefusedNamingTheField) {
  const std::string text = runtime_error_text(
      [&] { (void)read_key_file(write_file("upper.key", "key 5 sensor " + test::upper(hex_a()) + "\n")); });
  EXPECT_NE(text.find("the key (fourth field) has upper-case hex digits"), std::string::npos) << text;
  expect_no_key_text(text, {hex_a()}, "upper case");
}

TEST_F(KeyFile, CrlfLineEndingsAreRefused) {
  const std::string text = runtime_error_text([&] {
    (void)read_key_file(write_file("crlf.key", "# keys\r\nkey 5 sensor " + hex_a() + "\r\n"));
  });
  EXPECT_NE(text.find("line 1: has a carriage return"), std::string::npos) << text;
  expect_no_key_text(text, {hex_a()}, "CRLF");
}

TEST_F(KeyFile, WeakKeysAreRefusedNamingTheReasonWithoutTheKey) {
  struct Weak {
    std::string hex;
    const char* reason;
  };
  const std::vector<Weak> weak = {
      {std::string(64, '0'), "all zero"},
      {"000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f", "arithmetic"},
      {"1112131415161718191a1b1c1d1e1f202122232425262728292a2b2c2d2e2f30", "arithmetic"},
      {"fffefdfcfbfaf9f8f7f6f5f4f3f2f1f0efeeedecebeae9e8e7e6e5e4e3e2e1e0", "arithmetic"},
      {std::string(64, 'a'), "arithmetic"},
      {"00800080008000800080008000800080008000800080008000800080008000800", "arithmetic"},
      {"0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef", "fewer than 16 distinct"},
  };
  for (const Weak& w : weak) {
    const std::string hex = w.hex.substr(0, 64);
    const std::string text = runtime_error_text(
        [&] { (void)read_key_file(write_file("weak.key", "key 1 command " + hex + "\n")); });
    EXPECT_NE(text.find("is weak"), std::string::npos) << hex.substr(0, 8) << ": " << text;
    EXPECT_NE(text.find(w.reason), std::string::npos) << hex.substr(0, 8) << ": " << text;
    expect_no_key_text(text, {hex}, w.reason);
  }
}

// Every path of read_key_file, on success and on each refusal, frees its heap blocks only
// after wiping the key text and key bytes out of them.
TEST_F(KeyFile, NoFreedBufferHoldsKeyTextOnSuccessOrOnAnyError) {
  const KeyRecord k = generate_key(4, KeyRole::kCommand);
  const std::string hex = to_hex(k.key);
  std::vector<std::string> files;
  files.push_back(write_file("good.key", "key 4 command " + hex + "\n"));
  files.push_back(write_file("open.key", "key 4 command " + hex + "\n", 0644U));
  files.push_back(write_file("crlf.key", "key 4 command " + hex + "\r\n"));
  files.push_back(write_file("swap.key", "key 4 " + hex + " command\n"));
  files.push_back(write_file("upper.key", "key 4 command " + test::upper(hex) + "\n"));
  files.push_back(write_file("dup.key", "key 4 command " + hex + "\nkey 4 sensor " + hex + "\n"));
  files.push_back(write_file("extra.key", "key 4 command " + hex + " " + hex + "\n"));
  files.push_back(write_file("later.key", "key 4 command " + hex + "\nkey 5 sensor 00\n"));
  const std::vector<std::string> needles = test::secret_needles(k.key.data(), k.key.size());
  for (const std::string& f : files) {
    long hits = 0;
    long scanned = 0;
    bool threw = false;
    {
      test::FreedMemoryScan scan(needles);
      try {
        std::vector<KeyRecord> r = read_key_file(f);
        r.push_back(r.at(0));  // a copy and a reallocation: the moved-from storage too
      } catch (const std::runtime_error&) {
        threw = true;
      }
      scan.stop();
      hits = scan.hits();
      scanned = scan.scanned();
    }
    EXPECT_EQ(hits, 0) << f << (threw ? " (refused)" : " (read)");
    EXPECT_GT(scanned, 0) << f << ": the scan saw no freed block";
    EXPECT_EQ(threw, f != files[0]) << f;
  }
}

// The scan above can fail: a freed string that still holds key text is found.
TEST(FreedMemoryScan, FindsKeyTextLeftInAFreedBlock) {
  const KeyRecord k = generate_key(4, KeyRole::kCommand);
  const std::vector<std::string> needles = test::secret_needles(k.key.data(), k.key.size());
  const std::string hex = to_hex(k.key);
  long hits = 0;
  {
    test::FreedMemoryScan scan(needles);
    { const std::string copy = "prefix " + hex.substr(10, 20); }  // freed unwiped
    scan.stop();
    hits = scan.hits();
  }
  EXPECT_GE(hits, 1) << "a string freed still holding key text was not found";
}

TEST(KeyWeakness, AllZeroArithmeticAndFewDistinctValuesAreWeak) {
  KeyBytes k{};
  EXPECT_STREQ(key_weakness(k), "all zero");
  for (unsigned step : {0U, 1U, 3U, 128U, 255U}) {
    for (unsigned start : {0U, 0x11U, 0xf0U}) {
      for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<std::uint8_t>(start + step * i);
      if (start == 0 && step == 0) continue;  // all zero
      const char* why = key_weakness(k);
      ASSERT_NE(why, nullptr) << start << " + " << step << " i";
      EXPECT_NE(std::strstr(why, "arithmetic"), nullptr) << why;
    }
  }
}

// The distinct-value rule at its boundary: 15 distinct values are weak, 16 are not (neither
// key is an arithmetic sequence).
TEST(KeyWeakness, FifteenDistinctValuesAreWeakSixteenAreNot) {
  KeyBytes k{};
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<std::uint8_t>((i * 7U) % 15U + 1U);
  EXPECT_STREQ(key_weakness(k), "fewer than 16 distinct byte values");
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<std::uint8_t>((i * 7U) % 16U + 1U);
  EXPECT_EQ(key_weakness(k), nullptr);
}

TEST(KeyWeakness, RandomKeysAreNotWeak) {
  for (int i = 0; i < 20000; ++i) {
    KeyBytes k{};
    ASSERT_TRUE(random_bytes(k.data(), k.size()));
    ASSERT_EQ(key_weakness(k), nullptr) << to_hex(k);
  }
}

std::atomic<int> g_draws{0};

bool zero_then_random(std::uint8_t* out, std::size_t n) noexcept {
  if (++g_draws <= 3) {
    std::memset(out, 0, n);
    return true;
  }
  return random_bytes(out, n);
}
bool always_arithmetic(std::uint8_t* out, std::size_t n) noexcept {
  ++g_draws;
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>(0x30 + i);
  return true;
}
bool failing(std::uint8_t*, std::size_t) noexcept { return false; }

TEST(GenerateKey, RedrawsAWeakDraw) {
  g_draws = 0;
  const KeyRecord k = generate_key(2, KeyRole::kSensor, &zero_then_random);
  EXPECT_EQ(g_draws.load(), 4);
  EXPECT_EQ(key_weakness(k.key), nullptr);
}

TEST(GenerateKey, GivesUpAfterEightWeakDraws) {
  g_draws = 0;
  const std::string text = runtime_error_text([] { (void)generate_key(2, KeyRole::kCommand, &always_arithmetic); });
  EXPECT_NE(text.find("8 weak keys in a row"), std::string::npos) << text;
  EXPECT_EQ(g_draws.load(), 8);
}

TEST(GenerateKey, AFailingSourceMakesNoKey) {
  EXPECT_THROW((void)generate_key(2, KeyRole::kCommand, &failing), std::runtime_error);
  EXPECT_THROW((void)generate_key(2, KeyRole::kCommand, nullptr), std::invalid_argument);
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
