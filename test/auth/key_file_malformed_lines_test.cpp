// Key files' malformed lines (docs/SECURITY.md KEY-1), each test in a fresh private directory:
// every malformed line (fields in any wrong order, a missing or extra field, bad id, role or
// key text, upper case, CRLF, NUL, a duplicate id) is refused naming its line and its field,
// and no error text ever contains the key's hex or any 16-digit window of it; weak keys are
// refused with their reason.
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

}  // namespace
}  // namespace evade::auth
