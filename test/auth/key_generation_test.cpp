// Key generation (docs/SECURITY.md KEY-1): the weak-key rules (all zero, an arithmetic
// sequence, fewer than 16 distinct values) at their boundaries; generate_key redraws a weak
// draw, gives up after 8 weak draws, and a failing source makes no key.
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

namespace evade::auth {
namespace {

using test::exists;
using test::key_text_in;
using test::mode_of;
using test::read_bytes;
using test::runtime_error_text;
using test::TempDir;
using test::to_hex;

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

}  // namespace
}  // namespace evade::auth
