// KeyRing, the state it persists (docs/SECURITY.md AUTH-4): dirty() marking only what must be
// persisted; the ground's activate/retire commands; the sensor ARSN floor; add() and
// restore(). verify(), the receive-side rule (AUTH-2..3): keyring_verify_test.cpp.
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
