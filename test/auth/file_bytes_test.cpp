// A key file and an authentication state file written on one target are read on another
// (issue 42 item 4): both are written here from fixed keys, their bytes compared with the size
// and digest recorded on x86-64, and read back. scripts/cross runs this on aarch64, armhf and
// big-endian s390x: the same bytes on every target and each target reading its own means each
// reads every other's. EVADE_PRINT_FILE_BYTES=1 prints the recorded values (after a format
// change).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "auth_file_test_support.hpp"
#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"
#include "evade/auth/mac.hpp"
#include "evade/auth/state_file.hpp"

namespace evade::auth {
namespace {

// Deterministic key bytes (not weak: 32 distinct values, no constant step).
KeyBytes fixed_key(std::uint8_t seed) {
  KeyBytes k{};
  std::uint32_t x = 2463534242U ^ seed;
  for (auto& b : k) {
    x ^= x << 13U;
    x ^= x >> 17U;
    x ^= x << 5U;
    b = static_cast<std::uint8_t>(x >> 24U);
  }
  return k;
}

std::string digest(const std::string& bytes) {
  const KeyBytes k = fixed_key(99);
  const Mac m = hmac_sha256(k.data(), k.size(), reinterpret_cast<const std::uint8_t*>(bytes.data()),
                            bytes.size());
  return test::to_hex(m.data(), 12);
}

KeyRecord record(std::int32_t id, KeyRole role, std::uint8_t seed) {
  KeyRecord r;
  r.id = id;
  r.role = role;
  r.key = fixed_key(seed);
  return r;
}

class FileBytes : public test::TempDir {};

TEST_F(FileBytes, KeyFileHasTheRecordedBytesAndReadsBack) {
  const KeyRecord k = record(7, KeyRole::kCommand, 1);
  ASSERT_EQ(key_weakness(k.key), nullptr);
  write_key_file(path("ground.key"), k);
  const std::string bytes = test::read_bytes(path("ground.key"));
  if (std::getenv("EVADE_PRINT_FILE_BYTES")) {
    std::printf("key file: %zu bytes, digest %s\n", bytes.size(), digest(bytes).c_str());
  }
  EXPECT_EQ(bytes.size(), 148U);
  EXPECT_EQ(digest(bytes), "212b4a61b562d4e2ac31ab13");
  const auto back = read_key_file(path("ground.key"));
  ASSERT_EQ(back.size(), 1U);
  EXPECT_EQ(back[0].id, 7);
  EXPECT_EQ(back[0].role, KeyRole::kCommand);
  EXPECT_TRUE(back[0].key == k.key);
}

TEST_F(FileBytes, StateFileHasTheRecordedBytesAndLoadsBack) {
  KeyEntry tel;
  tel.id = 50;
  tel.role = KeyRole::kTelemetry;
  tel.key = fixed_key(50);
  KeyRing ring;
  ASSERT_EQ(ring.add(1, KeyRole::kCommand, fixed_key(1), KeyState::kStandby), nullptr);
  ASSERT_EQ(ring.add(2, KeyRole::kCommand, fixed_key(2), KeyState::kStandby), nullptr);
  ASSERT_EQ(ring.add(3, KeyRole::kSensor, fixed_key(3), KeyState::kActive), nullptr);
  ASSERT_EQ(ring.add(50, KeyRole::kTelemetry, tel.key, KeyState::kActive), nullptr);
  {
    StateFile f(path("node.state"), tel);
    f.init(&ring, 1, 1000);
  }
  const std::string bytes = test::read_bytes(path("node.state"));
  if (std::getenv("EVADE_PRINT_FILE_BYTES")) {
    std::printf("state file: %zu bytes, digest %s\n", bytes.size(), digest(bytes).c_str());
  }
  EXPECT_EQ(bytes.size(), 253U);
  EXPECT_EQ(digest(bytes), "c92251bedfa0f72e3f396fbb");
  KeyRing again;
  ASSERT_EQ(again.add(1, KeyRole::kCommand, fixed_key(1), KeyState::kStandby), nullptr);
  ASSERT_EQ(again.add(2, KeyRole::kCommand, fixed_key(2), KeyState::kStandby), nullptr);
  ASSERT_EQ(again.add(3, KeyRole::kSensor, fixed_key(3), KeyState::kActive), nullptr);
  ASSERT_EQ(again.add(50, KeyRole::kTelemetry, tel.key, KeyState::kActive), nullptr);
  StateFile g(path("node.state"), tel);
  g.load(&again);
  EXPECT_EQ(again.find(1)->state, KeyState::kActive);
  EXPECT_EQ(again.find(2)->state, KeyState::kStandby);
  EXPECT_EQ(again.find(1)->arsn[static_cast<std::size_t>(ArsnSlot::kCommand)], 1000);
}

}  // namespace
}  // namespace evade::auth
