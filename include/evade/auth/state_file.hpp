// The node's persisted authentication state, version 2 (docs/SECURITY.md AUTH-4, KEY-2; issue 40
// "replay state that cannot be lost silently"): every key's state and every command key's last
// accepted ARSN, so that a restart reopens neither replay nor a retired key, in a file that
// cannot be deleted, cut, edited or swapped for a symbolic link without the node refusing to
// start. Text, one concept per line, the MAC line last and nothing after it:
//   evade-auth-state 2
//   writes <n>                                  (+1 per save)
//   telemetry <id> <check value: 16 hex>
//   key <id> <command|sensor> <active|standby|retired> <command arsn> <check value: 16 hex>
//   ...
//   mac <64 hex>     HMAC-SHA-256(state subkey, every byte before "mac ")
// The state subkey is derived from the node's telemetry key (crypto_kdf_derive_from_key, context
// "evadestf", subkey id 1); a check value is auth::key_check_value (it names a key without
// revealing it). Records of keys that are not loaded are kept and written back on every save,
// so a retired key stays retired if it is ever loaded again.
// save() formats into a fixed buffer and writes a new temporary (O_EXCL|O_NOFOLLOW: a file or
// symbolic link planted at the temporary name is removed, never followed), fsyncs it, renames it
// over the file and fsyncs the directory: after a crash the file is the old state or the new
// one. It neither allocates nor throws and blocks on the disk: the node calls it between cycles
// and holds back the commands that advanced the state until it has returned 0.
// Not covered by the file alone: someone who can write the directory (it must be this user's and
// not group/other writable) could put back an older authentic file; the write counter lets the
// ground notice. Sensor ARSNs are not persisted: their time base is the message time
// (KeyRing::raise_sensor_floor).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "evade/auth/keyring.hpp"

namespace evade::auth {

/// One key's line of the state file.
struct StateRecord {
  std::int32_t id = 0;
  KeyRole role = KeyRole::kCommand;  ///< command or sensor (the telemetry key has its own line)
  KeyState state = KeyState::kStandby;
  std::int64_t command_arsn = 0;
  std::array<std::uint8_t, 8> kcv{};  ///< key_check_value of the key
};

class StateFile {  // move-only (it holds the directory's descriptor)
 public:
  static constexpr std::size_t kMaxRecords = 32;     ///< key records in one file
  static constexpr std::size_t kMaxFileBytes = 4096;  ///< a full file is 2,329 bytes

  /// Initialization (allocates, throws std::runtime_error with one line naming the path and the
  /// problem): opens the file's directory and checks it: owned by this user, not writable by
  /// group or others. telemetry: the node's telemetry key (role kTelemetry); the file is
  /// authenticated with HMAC-SHA-256 under a subkey derived from it with libsodium's
  /// crypto_kdf_derive_from_key (context "evadestf", subkey id 1), held until destruction and
  /// then wiped.
  StateFile(std::string path, const KeyEntry& telemetry);
  ~StateFile();
  StateFile(StateFile&& other) noexcept;
  StateFile& operator=(StateFile&& other) noexcept;
  StateFile(const StateFile&) = delete;
  StateFile& operator=(const StateFile&) = delete;

  /// Start from the file (initialization). Refuses (throws) a missing file ("... does not exist:
  /// a node with command keys starts only from its state file; on its very first start give
  /// --auth-init KEY_ID (docs/SECURITY.md)"), a symlink, a non-regular file, a file not owned by
  /// this user, group/other permission bits ("chmod 600 it"), another version (version 1: "an
  /// unauthenticated version-1 file"), a bad MAC ("does not verify: it was changed, cut, or
  /// written under another telemetry key"), a malformed line, a telemetry key id or check value
  /// other than the node's, a loaded key whose check value differs from its record ("key N is
  /// not the key this state file was written for") or whose role differs, more than kMaxRecords
  /// records with the loaded keys, and a result with command keys loaded but none active (the
  /// ground could never command the node: its active key's file is missing from --keys). Refuses
  /// before it changes anything in ring. Applies the records to ring: each loaded key gets its
  /// persisted state and command ARSN; a loaded key with no record is new: command keys stay
  /// standby (the ground activates them), sensor keys active. Records of keys not loaded are
  /// kept and written back on every save (a retired key stays retired if it is ever loaded
  /// again).
  void load(KeyRing* ring);

  /// First start (--auth-init): refuses if anything exists at the path (file, symlink, dangling
  /// symlink; the final link of the new file fails rather than replace what appeared meanwhile);
  /// key active_key must be a loaded command key and becomes the only active command key (others
  /// standby); every command key's command ARSN starts at arsn_floor (>= 0; the operator's
  /// recovery after a lost file); writes the file now. Changes ring only once the file is written.
  void init(KeyRing* ring, std::int32_t active_key, std::int64_t arsn_floor);

  /// Writes ring's state (plus the kept records) durably: formats into a fixed buffer, then
  /// openat(dir, tmp, O_WRONLY|O_CREAT|O_EXCL|O_NOFOLLOW|O_CLOEXEC, 0600); on EEXIST unlinkat the
  /// temporary name (removes a planted file or symlink itself, never its target) and try once
  /// more; write, fsync, close, renameat over the file, fsync the directory. 0 on success, else
  /// -errno (nothing half-written remains); -EINVAL before a load() or init() succeeded (a save
  /// must not replace a file it has not read: the kept records and the write counter would be
  /// lost). No allocation, no exceptions (the node calls it between real-time cycles).
  int save(const KeyRing& ring) noexcept;

  const std::string& path() const noexcept { return path_; }
  std::int64_t writes() const noexcept { return writes_; }  ///< the file's write counter

 private:
  void attach(const KeyEntry& telemetry);
  void take(StateFile* other) noexcept;
  void require_attached(const char* what) const;
  void check_ring_telemetry(const KeyRing& ring) const;
  int write_state(const KeyRing& ring, bool replace) noexcept;
  std::string label() const;

  std::string path_;
  std::string dir_;
  std::string name_;
  std::string tmp_;
  int dir_fd_ = -1;
  KeyBytes mac_key_{};  ///< the state subkey (wiped on destruction)
  std::int32_t telemetry_id_ = 0;
  std::array<std::uint8_t, 8> telemetry_kcv_{};
  std::array<StateRecord, kMaxRecords> kept_{};
  std::size_t n_kept_ = 0;
  std::int64_t writes_ = 0;
  bool ready_ = false;        ///< load() or init() succeeded: save() may write
};

}  // namespace evade::auth
