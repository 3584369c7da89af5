// The ground's anti-replay counter (docs/SECURITY.md UPLINK-1, AUTH-2; issue 40 "counters, not
// clocks"): the last ARSN the ground signed with, per key, in a file beside the key file, so that
// `evade plan --publish --key`, `evade arm` and `evade key` sign with last + 1 instead of their
// CLOCK_REALTIME in microseconds (a ground clock an hour ahead burned an hour of ARSNs and locked
// out every correct ground). Text:
//   evade-arsn 1
//   key <id> <last ARSN>
// A number is on disk (temporary with O_CREAT|O_EXCL|O_NOFOLLOW, fsync, rename, fsync of the
// directory) before next() returns it: a crash never reuses one. Two commands never share the
// counter: each holds an exclusive flock on its key file for the object's life. A lost or
// removed file is an empty counter: the node refuses the ground's next ARSN as a replay, and its
// acknowledgement (the node's last accepted ARSN) brings the counter back up (raise_to), so
// losing the file weakens nothing. Ground code: allocates and throws std::runtime_error with one
// line naming the file.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace evade::auth {

class ArsnCounter {
 public:
  /// The counter file beside key_file: "<key_file>.arsn". Locks it for the object's life (flock
  /// on a descriptor of the key file opened O_RDONLY|O_NOFOLLOW; LOCK_EX|LOCK_NB retried every
  /// 20 ms for at most 10 s, then "another evade command holds the ARSN counter of key file F").
  /// Checks the directory (owned by this user, not group/other writable), the key file (no
  /// symlink, a regular file of this user, mode 0600) and an existing counter file (regular, no
  /// symlink, owner, mode 0600, the format above). A missing file is an empty counter (every key
  /// at 0; existed() false).
  explicit ArsnCounter(const std::string& key_file);
  ~ArsnCounter();  ///< releases the lock
  ArsnCounter(const ArsnCounter&) = delete;
  ArsnCounter& operator=(const ArsnCounter&) = delete;
  ArsnCounter(ArsnCounter&&) = delete;
  ArsnCounter& operator=(ArsnCounter&&) = delete;

  /// Whether the counter file existed when the object was made.
  bool existed() const noexcept { return existed_; }
  /// The last ARSN used with key_id, 0 if none.
  std::int64_t last(std::int32_t key_id) const noexcept;
  /// last(key_id) + 1, written durably BEFORE it is returned: a crash after it never reuses the
  /// number. Throws std::runtime_error if it cannot be written (the counter is then unchanged)
  /// or if last(key_id) is INT64_MAX (the key cannot sign again: retire it), never wraps;
  /// std::invalid_argument for a key id outside 1 .. 2^31-1.
  std::int64_t next(std::int32_t key_id);
  /// Raises the counter to at least floor (persisted the same way); no effect when already there.
  void raise_to(std::int32_t key_id, std::int64_t floor);
  const std::string& path() const noexcept { return path_; }

 private:
  void read_existing();
  void persist(const std::map<std::int32_t, std::int64_t>& values) const;
  std::string label() const;

  std::string key_file_;
  std::string path_;
  std::string name_;
  std::string tmp_;
  int dir_fd_ = -1;
  int lock_fd_ = -1;
  std::map<std::int32_t, std::int64_t> last_;
  bool existed_ = false;
};

}  // namespace evade::auth
