// Key files (docs/SECURITY.md KEY-1, KEY-2): text, one key per line,
//   key <id> <command|sensor|telemetry> <64 lower-case hex digits>
// with '#' comment lines and blank lines, Unix line endings. `evade keygen` writes one (mode
// 0600, never over an existing file). The node and the ground read them at start-up and refuse
// a symbolic link, anything but a regular file, a file owned by another user or one that group
// or others may access (checked on the open descriptor: no race between a check and the open),
// a file over 64 KiB, a malformed line and a weak key. An error names the file, the line and
// which field is wrong, never the text of a field or line (a user who swaps fields puts the
// key where the role should be): no function here prints, returns or throws key bytes, and
// every buffer that held key text is wiped before it is freed. Initialization code: allocates
// and throws std::runtime_error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "evade/auth/keyring.hpp"

namespace evade::auth {

/// One key of a key file. Wipes its key bytes on destruction.
struct KeyRecord {
  std::int32_t id = 0;
  KeyRole role = KeyRole::kCommand;
  KeyBytes key{};

  KeyRecord() = default;
  KeyRecord(const KeyRecord&) = default;
  KeyRecord& operator=(const KeyRecord&) = default;
  ~KeyRecord();
};

/// The largest key file read_key_file reads.
inline constexpr std::size_t kMaxKeyFileBytes = std::size_t{64} * 1024;

/// Every key of the file at path. Throws std::runtime_error naming the file (and the line and
/// field) when it is a symbolic link, not a regular file, not owned by this user, accessible
/// to group or others ("chmod 600 it"), larger than kMaxKeyFileBytes, or holds a control
/// character (a carriage return, a NUL byte), a line without exactly four fields, a first
/// field other than "key", a bad id, role or key text (64 lower-case hex digits), a weak key
/// (key_weakness), the same id twice, or no key at all.
std::vector<KeyRecord> read_key_file(const std::string& path);

/// Why key is too weak to use (a static text without key bytes), nullptr when it is fine:
/// all zero; an arithmetic sequence mod 256 (the same difference between successive bytes:
/// 00 01 02 ..., 11 12 13 ..., every byte equal); fewer than 16 distinct byte values. A key
/// from a working random generator is refused with probability below 1e-16.
const char* key_weakness(const KeyBytes& key) noexcept;

/// Where generate_key draws its bytes: fills out[0, n), false when it cannot.
using RandomSource = bool (*)(std::uint8_t* out, std::size_t n) noexcept;

/// A new key from source (by default the operating system's random generator). A weak draw
/// (key_weakness) is drawn again, at most 8 draws in all; then std::runtime_error (a generator
/// that gives 8 weak keys in a row is broken). std::runtime_error if source fails,
/// std::invalid_argument for an id outside 1 .. 2^31-1.
KeyRecord generate_key(std::int32_t id, KeyRole role, RandomSource source = &random_bytes);

/// Writes one key to a new file at path with mode 0600 (O_EXCL: never replaces a file, nor
/// follows a symbolic link), and fsyncs it. Throws std::runtime_error naming the path on
/// failure or for a weak key, std::invalid_argument for an id outside 1 .. 2^31-1.
void write_key_file(const std::string& path, const KeyRecord& key);

/// "command" / "sensor" / "telemetry".
const char* role_name(KeyRole r) noexcept;
/// The role named name (as role_name writes it); false for anything else.
bool parse_role(const std::string& name, KeyRole* role) noexcept;

/// Adds records to ring: every command key standby, sensor and telemetry keys active. The
/// states of command keys never come from the order of the files (a new command key listed
/// first must not become active without a signed activation, KEY-2): the node's state file
/// (auth::StateFile::load, or init on a first start) sets them. Throws std::runtime_error
/// naming the id when the ring refuses one.
void load_into(const std::vector<KeyRecord>& records, KeyRing* ring);

}  // namespace evade::auth
