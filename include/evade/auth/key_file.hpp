// Key files (docs/SECURITY.md KEY-1..3): text, one key per line,
//   key <id> <command|sensor> <64 hex digits>
// with '#' comments. `evade keygen` writes one (mode 0600, never over an existing file); the
// node and the ground read them at start-up and refuse a file that group or others can read
// or write, or that is not a regular file. No function here prints or returns key bytes in an
// error text. Initialization code: allocates and throws std::runtime_error.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "evade/auth/keyring.hpp"

namespace evade::auth {

struct KeyRecord {
  std::int32_t id = 0;
  KeyRole role = KeyRole::kCommand;
  KeyBytes key{};
};

/// Every key of the file at path. Throws std::runtime_error naming the file (and the line) when
/// it cannot be read, is group/other accessible, or holds a malformed line, a bad id or role,
/// a key that is not 64 hex digits, or the same id twice.
std::vector<KeyRecord> read_key_file(const std::string& path);

/// A new key from the operating system's random generator. Throws std::runtime_error if
/// libsodium cannot be initialized, std::invalid_argument for an id outside 1 .. 2^31-1.
KeyRecord generate_key(std::int32_t id, KeyRole role);

/// Writes one key to a new file at path with mode 0600 (O_EXCL: never replaces a file), and
/// fsyncs it. Throws std::runtime_error naming the path on failure.
void write_key_file(const std::string& path, const KeyRecord& key);

/// "command" / "sensor".
const char* role_name(KeyRole r) noexcept;

/// Loads records into ring: the first command key active, every other command key standby
/// (the ground activates it: KEY-2), sensor keys active. Throws std::runtime_error naming the
/// id when the ring refuses one.
void load_into(const std::vector<KeyRecord>& records, KeyRing* ring);

}  // namespace evade::auth
