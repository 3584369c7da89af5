// KeyRing, the node's receive-side rule (docs/SECURITY.md AUTH-2..3) and the state it
// persists (AUTH-4): every AuthResult of verify() on hand-built signed messages (8 fingerprint
// bytes, a body, the 44-byte trailer of AUTH-1 with the key id and ARSN big-endian, signed by
// sign_encoded); the ARSN advancing only on kOk; a forged message, even one carrying ARSN
// INT64_MAX, changing no state; key states and roles; dirty() marking only what must be
// persisted; the ground's activate/retire commands; the sensor ARSN floor; add() and restore().
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "evade/auth/keyring.hpp"
#include "evade/auth/mac.hpp"
#include "evade/auth/trailer.hpp"

namespace evade::auth {
namespace {

using Bytes = std::vector<std::uint8_t>;

constexpr const char* kBurnPlan = "EVADE_BURN_PLAN";
constexpr const char* kArm = "EVADE_ARM";
constexpr const char* kNavChannel = "EVADE_NAV_STATE";

constexpr std::int32_t kCmdId = 1;
constexpr std::int32_t kCmd2Id = 2;
constexpr std::int32_t kSensorId = 10;

KeyBytes key_bytes(std::uint8_t seed) {
  KeyBytes k{};
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<std::uint8_t>(std::size_t{seed} * 13U + 5U * i + 1U);
  return k;
}

void put_be(std::uint8_t* p, std::uint64_t v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    p[n - 1 - i] = static_cast<std::uint8_t>(v & 0xFFU);
    v >>= 8U;
  }
}

// 8 fingerprint bytes, a 20-byte body, then key id (int32 BE), ARSN (int64 BE) and the MAC
// over everything before it on channel, under key.
Bytes signed_message(const KeyBytes& key, std::int32_t key_id, std::int64_t arsn,
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
KeyRing make_ring() {
  KeyRing ring;
  EXPECT_EQ(ring.add(kCmdId, KeyRole::kCommand, key_bytes(1), KeyState::kActive), nullptr);
  EXPECT_EQ(ring.add(kCmd2Id, KeyRole::kCommand, key_bytes(2), KeyState::kStandby), nullptr);
  EXPECT_EQ(ring.add(kSensorId, KeyRole::kSensor, key_bytes(10), KeyState::kActive), nullptr);
  return ring;
}

std::int64_t arsn_of(const KeyRing& ring, std::int32_t id, ArsnSlot slot) {
  const KeyEntry* e = ring.find(id);
  EXPECT_NE(e, nullptr) << id;
  return e == nullptr ? -1 : e->arsn[static_cast<std::size_t>(slot)];
}

AuthResult verify(KeyRing* ring, ArsnSlot slot, const char* channel, const Bytes& m,
                  std::int32_t* key_id = nullptr) {
  return ring->verify(slot, channel, m.data(), m.size(), key_id);
}

// ---- verify() ----

TEST(KeyRingVerify, OkAdvancesTheArsnAndNamesTheSigner) {
  KeyRing ring = make_ring();
  std::int32_t signer = -1;
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 5, kBurnPlan), &signer),
            AuthResult::kOk);
  EXPECT_EQ(signer, kCmdId);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 5);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kArm, signed_message(key_bytes(1), kCmdId, 6, kArm)),
            AuthResult::kOk);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 6);
  // A gap is fine: the ARSN need only exceed the last accepted one.
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kArm, signed_message(key_bytes(1), kCmdId, 1000, kArm)),
            AuthResult::kOk);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 1000);
}

TEST(KeyRingVerify, SameBytesAgainAreReplayed) {
  KeyRing ring = make_ring();
  const Bytes m = signed_message(key_bytes(1), kCmdId, 5, kBurnPlan);
  ASSERT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan, m), AuthResult::kOk);
  std::int32_t signer = -1;
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan, m, &signer), AuthResult::kReplayed);
  EXPECT_EQ(signer, -1) << "key_id is written only on kOk";
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 5);
}

TEST(KeyRingVerify, LowerArsnIsReplayed) {
  KeyRing ring = make_ring();
  ASSERT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 50, kBurnPlan)),
            AuthResult::kOk);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 49, kBurnPlan)),
            AuthResult::kReplayed);
  // A command key has one ARSN for every command channel: a lower ARSN on another channel is
  // a replay too.
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kArm, signed_message(key_bytes(1), kCmdId, 49, kArm)),
            AuthResult::kReplayed);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kArm, signed_message(key_bytes(1), kCmdId, 50, kArm)),
            AuthResult::kReplayed);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 50);
}

TEST(KeyRingVerify, ZeroAndNegativeArsnOnAFreshKeyAreReplayed) {
  KeyRing ring = make_ring();
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 0, kBurnPlan)),
            AuthResult::kReplayed);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, -1, kBurnPlan)),
            AuthResult::kReplayed);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 0);
}

TEST(KeyRingVerify, KeyIdZeroIsUnsigned) {
  KeyRing ring = make_ring();
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), 0, 5, kBurnPlan)),
            AuthResult::kUnsigned);
  // An all-zero trailer (an unsigned message) too.
  const Bytes zeros(8 + 20 + kTrailerBytes, 0);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan, zeros), AuthResult::kUnsigned);
}

TEST(KeyRingVerify, TooShortIsMalformed) {
  KeyRing ring = make_ring();
  const Bytes m = signed_message(key_bytes(1), kCmdId, 5, kBurnPlan);
  EXPECT_EQ(ring.verify(ArsnSlot::kCommand, kBurnPlan, m.data(), kMinSignedBytes - 1),
            AuthResult::kMalformed);
  EXPECT_EQ(ring.verify(ArsnSlot::kCommand, kBurnPlan, m.data(), 0), AuthResult::kMalformed);
  EXPECT_EQ(ring.verify(ArsnSlot::kCommand, kBurnPlan, nullptr, m.size()), AuthResult::kMalformed);
}

TEST(KeyRingVerify, UnknownKeyId) {
  KeyRing ring = make_ring();
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), 99, 5, kBurnPlan)),
            AuthResult::kUnknownKey);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), -1, 5, kBurnPlan)),
            AuthResult::kUnknownKey);
}

TEST(KeyRingVerify, WrongKeyBytesAreBadMac) {
  KeyRing ring = make_ring();
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(77), kCmdId, 5, kBurnPlan)),
            AuthResult::kBadMac);
  // Key 2's bytes under key 1's id.
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(2), kCmdId, 5, kBurnPlan)),
            AuthResult::kBadMac);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 0);
}

TEST(KeyRingVerify, SignedForAnotherChannelIsBadMac) {
  KeyRing ring = make_ring();
  const Bytes m = signed_message(key_bytes(1), kCmdId, 5, kBurnPlan);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kArm, m), AuthResult::kBadMac);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 0);
  // The same bytes still verify on the channel they were signed for.
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan, m), AuthResult::kOk);
}

TEST(KeyRingVerify, CorruptedByteIsBadMac) {
  KeyRing ring = make_ring();
  Bytes m = signed_message(key_bytes(1), kCmdId, 5, kBurnPlan);
  m[12] ^= 0x04U;  // a body byte
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan, m), AuthResult::kBadMac);
}

TEST(KeyRingVerify, ForgedMessageWithMaxArsnChangesNoState) {
  // The key security property: a forged message's ARSN is never trusted. If it were, one
  // forgery carrying INT64_MAX would lock the ground out for good.
  KeyRing ring = make_ring();
  ASSERT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 10, kBurnPlan)),
            AuthResult::kOk);
  ring.mark_persisted();

  Bytes forged = signed_message(key_bytes(1), kCmdId, INT64_MAX, kBurnPlan);
  forged[forged.size() - 1] ^= 0x01U;  // the MAC no longer matches
  std::int32_t signer = -1;
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan, forged, &signer), AuthResult::kBadMac);
  EXPECT_EQ(signer, -1);
  // Signed under a key the attacker guessed, with the real key's id.
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(200), kCmdId, INT64_MAX, kBurnPlan)),
            AuthResult::kBadMac);
  // The same with the sensor key's id on a sensor slot.
  EXPECT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(200), kSensorId, INT64_MAX, kNavChannel)),
            AuthResult::kBadMac);

  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 10);
  EXPECT_EQ(arsn_of(ring, kSensorId, ArsnSlot::kNav), 0);
  EXPECT_FALSE(ring.dirty());
  // The genuine sender's next message, with an ordinary ARSN, is still accepted.
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 11, kBurnPlan)),
            AuthResult::kOk);
  EXPECT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(10), kSensorId, 3, kNavChannel)),
            AuthResult::kOk);
}

TEST(KeyRingVerify, StandbyKeyIsRefused) {
  KeyRing ring = make_ring();
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(2), kCmd2Id, 5, kBurnPlan)),
            AuthResult::kStandbyKey);
  EXPECT_EQ(arsn_of(ring, kCmd2Id, ArsnSlot::kCommand), 0);
  // Once the ground activates it, the same message is accepted.
  ASSERT_EQ(ring.activate(kCmd2Id), KeyCmdResult::kDone);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(2), kCmd2Id, 5, kBurnPlan)),
            AuthResult::kOk);
}

TEST(KeyRingVerify, RetiredKeyIsRefused) {
  KeyRing ring = make_ring();
  ASSERT_EQ(ring.activate(kCmd2Id), KeyCmdResult::kDone);
  ASSERT_EQ(ring.retire(kCmdId), KeyCmdResult::kDone);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 5, kBurnPlan)),
            AuthResult::kRetiredKey);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 0);
}

TEST(KeyRingVerify, SensorKeyOnCommandSlotIsWrongRole) {
  KeyRing ring = make_ring();
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(10), kSensorId, 5, kBurnPlan)),
            AuthResult::kWrongRole);
  EXPECT_EQ(arsn_of(ring, kSensorId, ArsnSlot::kCommand), 0);
}

TEST(KeyRingVerify, CommandKeyOnNavSlotIsWrongRole) {
  KeyRing ring = make_ring();
  EXPECT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(1), kCmdId, 5, kNavChannel)),
            AuthResult::kWrongRole);
  EXPECT_EQ(verify(&ring, ArsnSlot::kAngles, "EVADE_ANGLES",
                   signed_message(key_bytes(1), kCmdId, 5, "EVADE_ANGLES")),
            AuthResult::kWrongRole);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kNav), 0);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 0);
}

TEST(KeyRingVerify, SensorSlotsKeepSeparateArsns) {
  KeyRing ring = make_ring();
  EXPECT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(10), kSensorId, 100, kNavChannel)),
            AuthResult::kOk);
  // A lower ARSN on another sensor slot is fine: one ARSN per sensor channel.
  EXPECT_EQ(verify(&ring, ArsnSlot::kAngles, "EVADE_ANGLES",
                   signed_message(key_bytes(10), kSensorId, 7, "EVADE_ANGLES")),
            AuthResult::kOk);
  EXPECT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(10), kSensorId, 100, kNavChannel)),
            AuthResult::kReplayed);
  EXPECT_EQ(arsn_of(ring, kSensorId, ArsnSlot::kNav), 100);
  EXPECT_EQ(arsn_of(ring, kSensorId, ArsnSlot::kAngles), 7);
  EXPECT_EQ(arsn_of(ring, kSensorId, ArsnSlot::kClock), 0);
}

TEST(KeyRingVerify, ResultNamesAreDistinct) {
  EXPECT_STREQ(auth_result_name(AuthResult::kOk), "ok");
  EXPECT_STREQ(auth_result_name(AuthResult::kBadMac), "bad_mac");
  EXPECT_STREQ(auth_result_name(AuthResult::kReplayed), "replayed");
  for (int a = 0; a < static_cast<int>(AuthResult::kCount); ++a) {
    for (int b = a + 1; b < static_cast<int>(AuthResult::kCount); ++b) {
      EXPECT_STRNE(auth_result_name(static_cast<AuthResult>(a)),
                   auth_result_name(static_cast<AuthResult>(b)));
    }
  }
}

// ---- dirty() ----

TEST(KeyRingDirty, SetOnlyWhenACommandArsnAdvances) {
  KeyRing ring = make_ring();
  EXPECT_FALSE(ring.dirty());
  // A sensor ARSN is not persisted.
  ASSERT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(10), kSensorId, 5, kNavChannel)),
            AuthResult::kOk);
  EXPECT_FALSE(ring.dirty());
  // Refused command messages change nothing.
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(99), kCmdId, 5, kBurnPlan)),
            AuthResult::kBadMac);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(2), kCmd2Id, 5, kBurnPlan)),
            AuthResult::kStandbyKey);
  EXPECT_FALSE(ring.dirty());
  // An accepted command ARSN is.
  ASSERT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 5, kBurnPlan)),
            AuthResult::kOk);
  EXPECT_TRUE(ring.dirty());
  ring.mark_persisted();
  EXPECT_FALSE(ring.dirty());
  // A replay of it does not make the ring dirty again.
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 5, kBurnPlan)),
            AuthResult::kReplayed);
  EXPECT_FALSE(ring.dirty());
}

TEST(KeyRingDirty, SetWhenAKeyStateChanges) {
  KeyRing ring = make_ring();
  ASSERT_EQ(ring.activate(kCmd2Id), KeyCmdResult::kDone);
  EXPECT_TRUE(ring.dirty());
  ring.mark_persisted();
  ASSERT_EQ(ring.activate(kCmd2Id), KeyCmdResult::kDone);  // already active: no change
  EXPECT_FALSE(ring.dirty());
  ASSERT_EQ(ring.retire(kCmdId), KeyCmdResult::kDone);
  EXPECT_TRUE(ring.dirty());
  ring.mark_persisted();
  EXPECT_EQ(ring.retire(kCmdId), KeyCmdResult::kDone);  // already retired: no change
  EXPECT_FALSE(ring.dirty());
}

// ---- activate / retire ----

TEST(KeyRingCommands, ActivateStandbyKeyIsDone) {
  KeyRing ring = make_ring();
  EXPECT_EQ(ring.active_command_keys(), 1);
  EXPECT_EQ(ring.activate(kCmd2Id), KeyCmdResult::kDone);
  EXPECT_EQ(ring.find(kCmd2Id)->state, KeyState::kActive);
  EXPECT_EQ(ring.active_command_keys(), 2);
  EXPECT_EQ(ring.activate(kCmd2Id), KeyCmdResult::kDone);  // idempotent
}

TEST(KeyRingCommands, ActivateUnknownIdOrSensorKeyIsUnknownKey) {
  KeyRing ring = make_ring();
  EXPECT_EQ(ring.activate(99), KeyCmdResult::kUnknownKey);
  EXPECT_EQ(ring.activate(0), KeyCmdResult::kUnknownKey);
  EXPECT_EQ(ring.activate(kSensorId), KeyCmdResult::kUnknownKey);
  EXPECT_FALSE(ring.dirty());
}

TEST(KeyRingCommands, ActivateRetiredKeyIsRetired) {
  KeyRing ring = make_ring();
  ASSERT_EQ(ring.retire(kCmd2Id), KeyCmdResult::kDone);  // a standby key may be retired
  EXPECT_EQ(ring.find(kCmd2Id)->state, KeyState::kRetired);
  EXPECT_EQ(ring.activate(kCmd2Id), KeyCmdResult::kRetired);
  EXPECT_EQ(ring.find(kCmd2Id)->state, KeyState::kRetired);
}

TEST(KeyRingCommands, RetireUnknownIdOrSensorKeyIsUnknownKey) {
  KeyRing ring = make_ring();
  EXPECT_EQ(ring.retire(99), KeyCmdResult::kUnknownKey);
  EXPECT_EQ(ring.retire(kSensorId), KeyCmdResult::kUnknownKey);
  EXPECT_EQ(ring.find(kSensorId)->state, KeyState::kActive);
}

TEST(KeyRingCommands, RetiringTheOnlyActiveCommandKeyIsLastKey) {
  KeyRing ring = make_ring();
  EXPECT_EQ(ring.retire(kCmdId), KeyCmdResult::kLastKey);
  EXPECT_EQ(ring.find(kCmdId)->state, KeyState::kActive);
  EXPECT_FALSE(ring.dirty());
  // With a second active key, the first may go.
  ASSERT_EQ(ring.activate(kCmd2Id), KeyCmdResult::kDone);
  EXPECT_EQ(ring.retire(kCmdId), KeyCmdResult::kDone);
  EXPECT_EQ(ring.find(kCmdId)->state, KeyState::kRetired);
  EXPECT_EQ(ring.active_command_keys(), 1);
  EXPECT_EQ(ring.retire(kCmd2Id), KeyCmdResult::kLastKey);
}

// ---- raise_sensor_floor ----

TEST(KeyRingSensorFloor, RejectsSensorArsnAtOrBelowTheFloor) {
  KeyRing ring = make_ring();
  ring.raise_sensor_floor(1000);
  EXPECT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(10), kSensorId, 999, kNavChannel)),
            AuthResult::kReplayed);
  EXPECT_EQ(verify(&ring, ArsnSlot::kClock, "EVADE_SIM_CLOCK",
                   signed_message(key_bytes(10), kSensorId, 1000, "EVADE_SIM_CLOCK")),
            AuthResult::kReplayed);
  EXPECT_EQ(verify(&ring, ArsnSlot::kAngles, "EVADE_ANGLES",
                   signed_message(key_bytes(10), kSensorId, 1000, "EVADE_ANGLES")),
            AuthResult::kReplayed);
  EXPECT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(10), kSensorId, 1001, kNavChannel)),
            AuthResult::kOk);
  // The command ARSN is untouched.
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 0);
  EXPECT_EQ(arsn_of(ring, kSensorId, ArsnSlot::kCommand), 0);
}

TEST(KeyRingSensorFloor, NeverLowersAnArsn) {
  KeyRing ring = make_ring();
  ASSERT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(10), kSensorId, 5000, kNavChannel)),
            AuthResult::kOk);
  ring.raise_sensor_floor(1000);
  EXPECT_EQ(arsn_of(ring, kSensorId, ArsnSlot::kNav), 5000);
  EXPECT_EQ(arsn_of(ring, kSensorId, ArsnSlot::kAngles), 1000);
  EXPECT_EQ(verify(&ring, ArsnSlot::kNav, kNavChannel,
                   signed_message(key_bytes(10), kSensorId, 4000, kNavChannel)),
            AuthResult::kReplayed);
}

// ---- add() ----

TEST(KeyRingAdd, RefusesIdZeroDuplicatesAndANinthKey) {
  KeyRing ring;
  EXPECT_NE(ring.add(0, KeyRole::kCommand, key_bytes(1), KeyState::kActive), nullptr);
  EXPECT_NE(ring.add(-3, KeyRole::kCommand, key_bytes(1), KeyState::kActive), nullptr);
  EXPECT_EQ(ring.size(), 0U);
  EXPECT_EQ(ring.add(1, KeyRole::kCommand, key_bytes(1), KeyState::kActive), nullptr);
  EXPECT_NE(ring.add(1, KeyRole::kSensor, key_bytes(2), KeyState::kActive), nullptr);
  EXPECT_EQ(ring.size(), 1U);
  EXPECT_EQ(ring.find(1)->role, KeyRole::kCommand);
  for (std::int32_t id = 2; id <= static_cast<std::int32_t>(KeyRing::kMaxKeys); ++id) {
    EXPECT_EQ(ring.add(id, KeyRole::kSensor, key_bytes(static_cast<std::uint8_t>(id)),
                       KeyState::kActive),
              nullptr)
        << id;
  }
  EXPECT_EQ(ring.size(), KeyRing::kMaxKeys);
  const char* why = ring.add(9, KeyRole::kSensor, key_bytes(9), KeyState::kActive);
  ASSERT_NE(why, nullptr);
  EXPECT_NE(std::string(why).find('8'), std::string::npos) << why;
  EXPECT_EQ(ring.size(), KeyRing::kMaxKeys);
  EXPECT_EQ(ring.find(9), nullptr);
}

TEST(KeyRingAdd, StoresIdRoleStateAndKey) {
  KeyRing ring;
  ASSERT_EQ(ring.add(42, KeyRole::kSensor, key_bytes(42), KeyState::kStandby), nullptr);
  const KeyEntry* e = ring.find(42);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e, &ring.entry(0));
  EXPECT_EQ(e->id, 42);
  EXPECT_EQ(e->role, KeyRole::kSensor);
  EXPECT_EQ(e->state, KeyState::kStandby);
  EXPECT_EQ(e->key, key_bytes(42));
  for (std::int64_t a : e->arsn) EXPECT_EQ(a, 0);
  EXPECT_EQ(ring.find(43), nullptr);
}

// ---- restore() ----

TEST(KeyRingRestore, SetsStateAndCommandArsn) {
  KeyRing ring = make_ring();
  EXPECT_TRUE(ring.restore(kCmdId, KeyState::kActive, 500));
  EXPECT_TRUE(ring.restore(kCmd2Id, KeyState::kRetired, 7));
  EXPECT_FALSE(ring.restore(99, KeyState::kActive, 1));
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 500);
  EXPECT_EQ(ring.find(kCmd2Id)->state, KeyState::kRetired);
  EXPECT_FALSE(ring.dirty()) << "restoring the persisted state is not a change to persist";
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 500, kBurnPlan)),
            AuthResult::kReplayed);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 501, kBurnPlan)),
            AuthResult::kOk);
  EXPECT_EQ(verify(&ring, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(2), kCmd2Id, 8, kBurnPlan)),
            AuthResult::kRetiredKey);
}

TEST(KeyRingCopy, CopyIsIndependent) {
  KeyRing ring = make_ring();
  KeyRing copy = ring;
  ASSERT_EQ(verify(&copy, ArsnSlot::kCommand, kBurnPlan,
                   signed_message(key_bytes(1), kCmdId, 5, kBurnPlan)),
            AuthResult::kOk);
  EXPECT_EQ(arsn_of(copy, kCmdId, ArsnSlot::kCommand), 5);
  EXPECT_EQ(arsn_of(ring, kCmdId, ArsnSlot::kCommand), 0);
}

}  // namespace
}  // namespace evade::auth
