// What the KeyRing tests share (keyring_test.cpp, keyring_verify_test.cpp): their keys and
// channels, hand-built signed messages, the ring of two command keys and a sensor key.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "evade/auth/keyring.hpp"
#include "evade/auth/mac.hpp"
#include "evade/auth/trailer.hpp"

namespace evade::auth::test {

using Bytes = std::vector<std::uint8_t>;

constexpr const char* kBurnPlan = "EVADE_BURN_PLAN";
constexpr const char* kArm = "EVADE_ARM";
constexpr const char* kNavChannel = "EVADE_NAV_STATE";

constexpr std::int32_t kCmdId = 1;
constexpr std::int32_t kCmd2Id = 2;
constexpr std::int32_t kSensorId = 10;

inline KeyBytes key_bytes(std::uint8_t seed) {
  KeyBytes k{};
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<std::uint8_t>(std::size_t{seed} * 13U + 5U * i + 1U);
  return k;
}

inline void put_be(std::uint8_t* p, std::uint64_t v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    p[n - 1 - i] = static_cast<std::uint8_t>(v & 0xFFU);
    v >>= 8U;
  }
}

// 8 fingerprint bytes, a 20-byte body, then key id (int32 BE), ARSN (int64 BE) and the MAC
// over everything before it on channel, under key.
inline Bytes signed_message(const KeyBytes& key, std::int32_t key_id, std::int64_t arsn,
                            const char* channel, std::uint8_t body_seed = 0) {
  Bytes b(8 + 20 + kTrailerBytes, 0);
  const std::uint8_t fingerprint[8] = {0x12, 0x34, 0x56, 0x78, 0x9a, 0xbc, 0xde, 0xf0};
  for (std::size_t i = 0; i < 8; ++i) b[i] = fingerprint[i];
  for (std::size_t i = 0; i < 20; ++i) b[8 + i] = static_cast<std::uint8_t>(body_seed + i);
  const std::size_t t = b.size() - kTrailerBytes;
  put_be(b.data() + t, static_cast<std::uint32_t>(key_id), 4);
  put_be(b.data() + t + 4, static_cast<std::uint64_t>(arsn), 8);
  EXPECT_TRUE(sign_encoded(key, channel, b.data(), b.size()));
  return b;
}

// Command key 1 (active), command key 2 (standby), sensor key 10 (active).
inline KeyRing make_ring() {
  KeyRing ring;
  EXPECT_EQ(ring.add(kCmdId, KeyRole::kCommand, key_bytes(1), KeyState::kActive), nullptr);
  EXPECT_EQ(ring.add(kCmd2Id, KeyRole::kCommand, key_bytes(2), KeyState::kStandby), nullptr);
  EXPECT_EQ(ring.add(kSensorId, KeyRole::kSensor, key_bytes(10), KeyState::kActive), nullptr);
  return ring;
}

inline std::int64_t arsn_of(const KeyRing& ring, std::int32_t id, ArsnSlot slot) {
  const KeyEntry* e = ring.find(id);
  EXPECT_NE(e, nullptr) << id;
  return e == nullptr ? -1 : e->arsn[static_cast<std::size_t>(slot)];
}

inline AuthResult verify(KeyRing* ring, ArsnSlot slot, const char* channel, const Bytes& m,
                         std::int32_t* key_id = nullptr) {
  return ring->verify(slot, channel, m.data(), m.size(), key_id);
}

}  // namespace evade::auth::test
