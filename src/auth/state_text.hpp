// The text of the node's state file, version 2 (docs/SECURITY.md AUTH-4, KEY-2; issue 40;
// format in include/evade/auth/state_file.hpp), apart from the file handling of StateFile:
// refusing any version but 2 and any file whose MAC does not verify before a line is trusted,
// the strict parse of the lines, the refusals that concern the loaded keys, and the
// allocation-free formatting of a file. Internal to src/auth. The parse and the checks are
// initialization code (throw std::runtime_error with one line naming the file); the formatting
// neither allocates nor throws.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "evade/auth/keyring.hpp"
#include "evade/auth/state_file.hpp"
#include "private_file.hpp"

namespace evade::auth::detail {

extern const char* const kStateHeader;  ///< "evade-auth-state 2"
inline constexpr std::int64_t kStateMaxCount = 9223372036854775807;  ///< INT64_MAX

/// The lines of an authentic file.
struct ParsedState {
  std::int64_t writes = 0;
  std::int32_t telemetry_id = 0;
  KeyCheckValue telemetry_kcv{};
  std::array<StateRecord, StateFile::kMaxRecords> records{};
  std::size_t n = 0;
};

/// Refuses anything whose first line is not "evade-auth-state 2", naming what it is.
void state_check_version(Span text, const std::string& label);
/// Refuses a file whose last line is not "mac <64 hex>" of HMAC-SHA-256(mac_key, every byte
/// before it) (constant-time comparison); returns the number of signed bytes.
std::size_t state_verify_mac(Span text, const KeyBytes& mac_key, const std::string& label);
/// Lines 2 to the MAC line of an authentic file (signed bytes [0, end)); throws naming the line.
ParsedState state_parse(Span text, std::size_t end, const std::string& label);

/// The record of key id, or nullptr.
const StateRecord* state_find(const ParsedState& st, std::int32_t id) noexcept;
/// The state key e gets from st: its record's, or new: command standby, sensor active.
KeyState state_for(const ParsedState& st, const KeyEntry& e) noexcept;
/// Every refusal of StateFile::load that concerns the loaded keys (role, check value, room for
/// the records, an active command key), before anything changes.
void state_check_keys(const ParsedState& st, const KeyRing& ring, const std::string& label);

/// The first three lines.
bool state_put_header(TextSink* out, std::int64_t writes, std::int32_t telemetry_id,
                      const KeyCheckValue& telemetry_kcv) noexcept;
/// One key line.
bool state_put_record(TextSink* out, std::int32_t id, KeyRole role, KeyState state,
                      std::int64_t arsn, const KeyCheckValue& kcv) noexcept;
/// The MAC line over everything written so far.
bool state_put_mac(TextSink* out, const KeyBytes& mac_key) noexcept;

}  // namespace evade::auth::detail
