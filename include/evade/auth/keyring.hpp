// The node's keys and anti-replay state (docs/SECURITY.md AUTH-*, KEY-*): a fixed table of up
// to kMaxKeys HMAC-SHA-256 keys, each a security association in the sense of CCSDS 355.0-B-2
// with its role, its state and its last accepted anti-replay sequence numbers (ARSN).
//
// check() is the whole receive-side rule, in this order: the trailer is read (too short:
// kMalformed; key id 0: kUnsigned), the key is looked up (kUnknownKey), the MAC is checked in
// constant time (kBadMac) — nothing in the message has been trusted or decoded yet, and a forged
// message changes no state — then the key's state (kStandbyKey, kRetiredKey) and role
// (kWrongRole: a sensor key cannot command, a command key cannot feed guidance, a telemetry key
// signs only what the node sends), then the ARSN must exceed the last accepted one of its slot
// (kReplayed). check() changes nothing: the caller decodes the message, checks its freshness,
// and only then commit()s its ARSN (docs/SECURITY.md ARSN-1: the ARSN advances only for a
// message accepted in full; a refused message changes nothing). verify() is check() and
// commit() at once, for a caller with nothing to check in between.
// Command keys keep one ARSN for every command channel (the ground's counter); sensor keys keep
// one per sensor channel. The telemetry key (at most one) signs the node's acknowledgements and
// status (docs/SECURITY.md TM-*). After construction nothing allocates or throws.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "evade/auth/mac.hpp"
#include "evade/auth/trailer.hpp"

namespace evade::auth {

enum class KeyRole : std::uint8_t { kCommand = 0, kSensor = 1, kTelemetry = 2 };
enum class KeyState : std::uint8_t { kActive = 0, kStandby = 1, kRetired = 2 };

/// Which ARSN a message advances.
enum class ArsnSlot : std::uint8_t { kCommand = 0, kAngles = 1, kNav = 2, kClock = 3 };
inline constexpr std::size_t kArsnSlots = 4;

enum class AuthResult : std::uint8_t {
  kOk = 0,
  kMalformed,    ///< shorter than a fingerprint and a trailer
  kUnsigned,     ///< key id 0 (no trailer filled in)
  kUnknownKey,   ///< no loaded key has this id
  kBadMac,       ///< the MAC does not match (forged, corrupted, or signed for another channel)
  kStandbyKey,   ///< loaded but not activated by the ground
  kRetiredKey,   ///< retired by the ground
  kWrongRole,    ///< a sensor key on a command channel, a command key on a sensor channel, or
                 ///< the telemetry key on any input
  kReplayed,     ///< authentic, but the ARSN is not above the last accepted one
  kCount
};
const char* auth_result_name(AuthResult r) noexcept;

/// Outcome of a key command (lcm_types/evade_key_cmd_t.lcm; values as the status's KEY_CMD_*).
enum class KeyCmdResult : std::uint8_t {
  kNone = 0,
  kDone = 1,
  kUnknownKey = 2,
  kRetired = 3,
  kLastKey = 4,
  kBadOp = 5,
};

struct KeyEntry {
  std::int32_t id = 0;
  KeyRole role = KeyRole::kCommand;
  KeyState state = KeyState::kActive;
  KeyBytes key{};
  std::array<std::int64_t, kArsnSlots> arsn{};  ///< last accepted per slot
};

class KeyRing {
 public:
  static constexpr std::size_t kMaxKeys = 8;

  KeyRing() = default;
  KeyRing(const KeyRing& other) = default;
  KeyRing& operator=(const KeyRing& other) = default;
  ~KeyRing();  ///< wipes the key bytes

  /// Initialization: adds a key. nullptr when added, else why not (a static text).
  const char* add(std::int32_t id, KeyRole role, const KeyBytes& key, KeyState state) noexcept;

  /// The receive-side rule without its last step (see the file comment): changes nothing. On
  /// kOk, kReplayed, kStandbyKey, kRetiredKey and kWrongRole the MAC was valid and *trailer (if
  /// given) is the message's trailer: the message is authentic and may be acknowledged.
  AuthResult check(ArsnSlot slot, const char* channel, const std::uint8_t* data, std::size_t size,
                   TrailerView* trailer = nullptr) const noexcept;
  /// Advances the slot's ARSN of key_id to arsn when arsn is above it (true); false when it is
  /// not (a message with this ARSN is now a replay) or key_id is not loaded.
  bool commit(std::int32_t key_id, ArsnSlot slot, std::int64_t arsn) noexcept;
  /// check() then, on kOk, commit(). On kOk the slot's ARSN has advanced and *key_id (if given)
  /// is the signer; on anything else no state changed.
  AuthResult verify(ArsnSlot slot, const char* channel, const std::uint8_t* data,
                    std::size_t size, std::int32_t* key_id = nullptr) noexcept;
  /// The slot's last accepted ARSN of key_id (0 when none or the key is not loaded).
  std::int64_t last_arsn(std::int32_t key_id, ArsnSlot slot) const noexcept;
  /// The telemetry key (role kTelemetry), or nullptr when none is loaded.
  const KeyEntry* telemetry_key() const noexcept;

  /// Key commands from the ground (already authenticated).
  KeyCmdResult activate(std::int32_t id) noexcept;
  KeyCmdResult retire(std::int32_t id) noexcept;

  /// Restores a persisted state and command ARSN (initialization). False if id is not loaded.
  bool restore(std::int32_t id, KeyState state, std::int64_t command_arsn) noexcept;
  /// Raises every sensor key's sensor slots to at least floor (the time base of sensor ARSNs:
  /// nothing signed before the node started is accepted after it started).
  void raise_sensor_floor(std::int64_t floor) noexcept;

  /// True when a persisted value (a command ARSN or a key state) changed since mark_persisted.
  bool dirty() const noexcept { return dirty_; }
  void mark_persisted() noexcept { dirty_ = false; }

  std::size_t size() const noexcept { return n_; }
  const KeyEntry& entry(std::size_t i) const noexcept { return keys_[i]; }
  const KeyEntry* find(std::int32_t id) const noexcept;
  int active_command_keys() const noexcept;

 private:
  KeyEntry* find_mutable(std::int32_t id) noexcept;

  std::array<KeyEntry, kMaxKeys> keys_{};
  std::size_t n_ = 0;
  bool dirty_ = false;
};

}  // namespace evade::auth
