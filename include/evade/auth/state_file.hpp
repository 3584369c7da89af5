// The node's persisted authentication state (docs/SECURITY.md AUTH-4): every key's state and
// every command key's last accepted ARSN, so that a restart reopens neither replay nor a
// retired key. Text, one line per key:
//   evade-auth-state 1
//   key <id> <active|standby|retired> <command arsn>
// save() writes a temporary file beside it, fsyncs it, renames it over the old one and fsyncs
// the directory: after a crash the file is the old state or the new one, never a mix. save()
// neither allocates nor throws (it formats into a fixed buffer) and blocks on the disk: the
// node calls it between cycles, and holds back the commands that advanced the state until it
// has returned 0 (commands take effect only once their ARSN is on disk).
// Sensor ARSNs are not persisted: their time base is the message time (KeyRing::
// raise_sensor_floor), so nothing signed before a restart is accepted after it.
#pragma once

#include <string>

#include "evade/auth/keyring.hpp"

namespace evade::auth {

class StateFile {
 public:
  /// Initialization: remembers the paths (allocates). An empty path means none: load() and
  /// save() then do nothing.
  explicit StateFile(std::string path);

  bool enabled() const noexcept { return !path_.empty(); }
  const std::string& path() const noexcept { return path_; }

  /// Applies the file to ring (initialization). A missing file is a first start (nothing
  /// applied); an unreadable or malformed one throws std::runtime_error naming the file and
  /// line. Keys in the file that ring does not hold are ignored.
  void load(KeyRing* ring) const;

  /// Writes ring's state durably. 0 on success, else -errno (nothing half-written remains).
  int save(const KeyRing& ring) const noexcept;

 private:
  void restore_line(const std::string& line, int line_no, KeyRing* ring) const;

  std::string path_;
  std::string tmp_path_;
  std::string dir_path_;
};

}  // namespace evade::auth
