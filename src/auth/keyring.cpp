// Receive-side authentication and key states (include/evade/auth/keyring.hpp).
#include "evade/auth/keyring.hpp"

namespace evade::auth {
namespace {

bool is_command_slot(ArsnSlot slot) noexcept { return slot == ArsnSlot::kCommand; }

}  // namespace

const char* auth_result_name(AuthResult r) noexcept {
  switch (r) {
    case AuthResult::kOk: return "ok";
    case AuthResult::kMalformed: return "too_short_for_trailer";
    case AuthResult::kUnsigned: return "unsigned";
    case AuthResult::kUnknownKey: return "unknown_key";
    case AuthResult::kBadMac: return "bad_mac";
    case AuthResult::kStandbyKey: return "standby_key";
    case AuthResult::kRetiredKey: return "retired_key";
    case AuthResult::kWrongRole: return "wrong_key_role";
    case AuthResult::kReplayed: return "replayed";
    case AuthResult::kCount: break;
  }
  return "?";
}

KeyRing::~KeyRing() { wipe(keys_.data(), sizeof(keys_)); }

const char* KeyRing::add(std::int32_t id, KeyRole role, const KeyBytes& key,
                         KeyState state) noexcept {
  if (id <= 0) return "key id must be 1 .. 2147483647";
  if (find(id) != nullptr) return "key id loaded twice";
  if (n_ == kMaxKeys) return "more keys than the node holds (8)";
  if (role == KeyRole::kTelemetry && telemetry_key() != nullptr) {
    return "a second telemetry key (the node signs with one)";
  }
  KeyEntry& e = keys_[n_++];
  e.id = id;
  e.role = role;
  e.state = state;
  e.key = key;
  e.arsn.fill(0);
  return nullptr;
}

const KeyEntry* KeyRing::find(std::int32_t id) const noexcept {
  for (std::size_t i = 0; i < n_; ++i) {
    if (keys_[i].id == id) return &keys_[i];
  }
  return nullptr;
}

KeyEntry* KeyRing::find_mutable(std::int32_t id) noexcept {
  for (std::size_t i = 0; i < n_; ++i) {
    if (keys_[i].id == id) return &keys_[i];
  }
  return nullptr;
}

AuthResult KeyRing::check(ArsnSlot slot, const char* channel, const std::uint8_t* data,
                          std::size_t size, TrailerView* trailer) const noexcept {
  TrailerView t;
  if (!read_trailer(data, size, &t)) return AuthResult::kMalformed;
  if (t.key_id == 0) return AuthResult::kUnsigned;
  const KeyEntry* e = find(t.key_id);
  if (e == nullptr) return AuthResult::kUnknownKey;
  if (!mac_valid(e->key, channel, data, size)) return AuthResult::kBadMac;
  if (trailer != nullptr) *trailer = t;  // authentic from here on
  if (e->state == KeyState::kRetired) return AuthResult::kRetiredKey;
  if (e->state == KeyState::kStandby) return AuthResult::kStandbyKey;
  const bool role_ok = is_command_slot(slot) ? e->role == KeyRole::kCommand
                                             : e->role == KeyRole::kSensor;
  if (!role_ok) return AuthResult::kWrongRole;
  if (t.arsn <= e->arsn[static_cast<std::size_t>(slot)]) return AuthResult::kReplayed;
  return AuthResult::kOk;
}

bool KeyRing::commit(std::int32_t key_id, ArsnSlot slot, std::int64_t arsn) noexcept {
  KeyEntry* e = find_mutable(key_id);
  if (e == nullptr) return false;
  std::int64_t& last = e->arsn[static_cast<std::size_t>(slot)];
  if (arsn <= last) return false;
  last = arsn;
  if (e->role == KeyRole::kCommand) dirty_ = true;
  return true;
}

AuthResult KeyRing::verify(ArsnSlot slot, const char* channel, const std::uint8_t* data,
                           std::size_t size, std::int32_t* key_id) noexcept {
  TrailerView t;
  const AuthResult r = check(slot, channel, data, size, &t);
  if (r != AuthResult::kOk) return r;
  if (!commit(t.key_id, slot, t.arsn)) return AuthResult::kReplayed;  // cannot happen: checked
  if (key_id != nullptr) *key_id = t.key_id;
  return AuthResult::kOk;
}

std::int64_t KeyRing::last_arsn(std::int32_t key_id, ArsnSlot slot) const noexcept {
  const KeyEntry* e = find(key_id);
  return e == nullptr ? 0 : e->arsn[static_cast<std::size_t>(slot)];
}

const KeyEntry* KeyRing::telemetry_key() const noexcept {
  for (std::size_t i = 0; i < n_; ++i) {
    if (keys_[i].role == KeyRole::kTelemetry) return &keys_[i];
  }
  return nullptr;
}

KeyCmdResult KeyRing::activate(std::int32_t id) noexcept {
  KeyEntry* e = find_mutable(id);
  if (e == nullptr || e->role != KeyRole::kCommand) return KeyCmdResult::kUnknownKey;
  if (e->state == KeyState::kRetired) return KeyCmdResult::kRetired;
  if (e->state != KeyState::kActive) dirty_ = true;
  e->state = KeyState::kActive;
  return KeyCmdResult::kDone;
}

KeyCmdResult KeyRing::retire(std::int32_t id) noexcept {
  KeyEntry* e = find_mutable(id);
  if (e == nullptr || e->role != KeyRole::kCommand) return KeyCmdResult::kUnknownKey;
  if (e->state == KeyState::kRetired) return KeyCmdResult::kDone;
  if (e->state == KeyState::kActive && active_command_keys() <= 1) return KeyCmdResult::kLastKey;
  e->state = KeyState::kRetired;
  dirty_ = true;
  return KeyCmdResult::kDone;
}

bool KeyRing::restore(std::int32_t id, KeyState state, std::int64_t command_arsn) noexcept {
  KeyEntry* e = find_mutable(id);
  if (e == nullptr) return false;
  e->state = state;
  e->arsn[static_cast<std::size_t>(ArsnSlot::kCommand)] = command_arsn;
  return true;
}

void KeyRing::raise_sensor_floor(std::int64_t floor) noexcept {
  for (std::size_t i = 0; i < n_; ++i) {
    if (keys_[i].role != KeyRole::kSensor) continue;
    for (std::size_t s = 1; s < kArsnSlots; ++s) {
      if (keys_[i].arsn[s] < floor) keys_[i].arsn[s] = floor;
    }
  }
}

int KeyRing::active_command_keys() const noexcept {
  int n = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    if (keys_[i].role == KeyRole::kCommand && keys_[i].state == KeyState::kActive) ++n;
  }
  return n;
}

}  // namespace evade::auth
