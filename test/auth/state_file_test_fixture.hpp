// What the state-file tests share (state_file_test.cpp, state_file_load_refusals_test.cpp,
// state_file_save_test.cpp): the fixture, a fresh private directory with the node's keys, its
// ring as load_into leaves it, authentic files signed as the node signs them, load's refusal
// text (the ring must stay unchanged).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "auth_file_test_support.hpp"
#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"
#include "evade/auth/mac.hpp"
#include "evade/auth/state_file.hpp"

namespace evade::auth::test {

constexpr std::int32_t kTel = 50;
constexpr std::size_t kCmdSlot = static_cast<std::size_t>(ArsnSlot::kCommand);

inline std::int64_t arsn(const KeyRing& r, std::int32_t id) { return r.find(id)->arsn[kCmdSlot]; }
inline KeyState state(const KeyRing& r, std::int32_t id) { return r.find(id)->state; }

class AuthStateFile : public TempDir {
 protected:
  void SetUp() override {
    TempDir::SetUp();
    for (std::int32_t id : {1, 2, 4}) keys_[id] = generate_key(id, KeyRole::kCommand).key;
    for (std::int32_t id : {3, 5}) keys_[id] = generate_key(id, KeyRole::kSensor).key;
    tel_.id = kTel;
    tel_.role = KeyRole::kTelemetry;
    tel_.key = generate_key(kTel, KeyRole::kTelemetry).key;
    state_ = path("node.state");
  }

  static KeyRole role_of(std::int32_t id) { return id == 3 || id == 5 ? KeyRole::kSensor : KeyRole::kCommand; }

  /// The node's ring as load_into leaves it: command keys standby, sensor and telemetry active.
  KeyRing ring(std::vector<std::int32_t> ids = {1, 2, 3}) const {
    KeyRing r;
    for (std::int32_t id : ids) {
      const KeyRole role = role_of(id);
      EXPECT_EQ(r.add(id, role, keys_.at(id), role == KeyRole::kCommand ? KeyState::kStandby : KeyState::kActive), nullptr);
    }
    EXPECT_EQ(r.add(kTel, KeyRole::kTelemetry, tel_.key, KeyState::kActive), nullptr);
    return r;
  }

  StateFile file() const { return StateFile(state_, tel_); }

  /// A first start with key 1 active and ARSN floor 1000; returns the ring.
  KeyRing initialized(std::vector<std::int32_t> ids = {1, 2, 3}) const {
    KeyRing r = ring(ids);
    StateFile f = file();
    f.init(&r, 1, 1000);
    return r;
  }

  std::string kcv(const KeyBytes& k) const {
    const KeyCheckValue v = key_check_value(k);
    return to_hex(v.data(), v.size());
  }

  /// body with its MAC line under the state subkey of the telemetry key (an authentic file).
  std::string sign(const std::string& body) const {
    KeyBytes sub = derive_subkey(tel_.key, 1, "evadestf");
    const Mac m = hmac_sha256(sub.data(), sub.size(), reinterpret_cast<const std::uint8_t*>(body.data()), body.size());
    return body + "mac " + to_hex(m.data(), m.size()) + "\n";
  }
  std::string head(std::int64_t writes = 3) const {
    return "evade-auth-state 2\nwrites " + std::to_string(writes) + "\ntelemetry " + std::to_string(kTel) + " " +
           kcv(tel_.key) + "\n";
  }
  std::string key_line(std::int32_t id, const char* st, std::int64_t a) const {
    return "key " + std::to_string(id) + " " + role_name(role_of(id)) + " " + st + " " + std::to_string(a) + " " +
           kcv(keys_.at(id)) + "\n";
  }

  /// The error text of loading the file into r (which must stay unchanged).
  std::string load_error(KeyRing r) const {
    const KeyRing before = r;
    const std::string text = runtime_error_text([&] {
      StateFile f = file();
      f.load(&r);
    });
    for (std::size_t i = 0; i < r.size(); ++i) {
      EXPECT_EQ(r.entry(i).state, before.entry(i).state) << "a refused load changed key " << r.entry(i).id;
      EXPECT_EQ(r.entry(i).arsn, before.entry(i).arsn) << "a refused load changed key " << r.entry(i).id;
    }
    return text;
  }
  std::string load_error() const { return load_error(ring()); }

  std::map<std::int32_t, KeyBytes> keys_;
  KeyEntry tel_;
  std::string state_;
};

}  // namespace evade::auth::test
