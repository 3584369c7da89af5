// KeyRing::verify(), the node's receive-side rule (docs/SECURITY.md AUTH-2..3): every
// AuthResult of verify() on hand-built signed messages (8 fingerprint bytes, a body, the
// 44-byte trailer of AUTH-1 with the key id and ARSN big-endian, signed by sign_encoded); the
// ARSN advancing only on kOk; a forged message, even one carrying ARSN INT64_MAX, changing no
// state; key states and roles.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "evade/auth/keyring.hpp"
#include "evade/auth/mac.hpp"
#include "evade/auth/trailer.hpp"

#include "keyring_test_support.hpp"

namespace evade::auth {
namespace {

using namespace test;  // NOLINT(google-build-using-namespace): the shared keys and messages

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

}  // namespace
}  // namespace evade::auth
