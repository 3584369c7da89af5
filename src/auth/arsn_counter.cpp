// The ground's anti-replay counter (include/evade/auth/arsn_counter.hpp; docs/SECURITY.md
// UPLINK-1, AUTH-2; issue 40 "counters, not clocks"): the lock on the key file (bounded retries),
// the checked read and strict parse of "<key file>.arsn", and the durable write that precedes
// every number next() hands out.
#include "evade/auth/arsn_counter.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include "private_file.hpp"

namespace evade::auth {
namespace {

constexpr int kLockTries = 501;               // the first try and 500 retries 20 ms apart: 10 s
constexpr long kLockRetryNs = 20L * 1000 * 1000;
constexpr std::size_t kMaxCounterBytes = std::size_t{64} * 1024;
constexpr std::int64_t kMaxArsn = 9223372036854775807;  // INT64_MAX
constexpr const char* kCounterHeader = "evade-arsn 1";

void check_key_id(std::int32_t key_id) {
  if (key_id < 1) throw std::invalid_argument("key id must be 1 .. 2147483647");
}

// Takes the exclusive lock on fd, retrying every 20 ms for at most 10 s; throws when it cannot.
void lock_or_throw(int fd, const std::string& key_file) {
  for (int attempt = 0; attempt < kLockTries; ++attempt) {
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) return;
    if (errno != EWOULDBLOCK && errno != EINTR) {
      throw std::runtime_error("cannot lock key file '" + key_file + "': " + std::strerror(errno));
    }
    if (attempt + 1 == kLockTries) break;
    timespec pause{0, kLockRetryNs};
    // An interrupted pause only shortens one retry interval: the number of tries stays bounded.
    (void)::nanosleep(&pause, nullptr);
  }
  throw std::runtime_error("another evade command holds the ARSN counter of key file '" + key_file +
                           "' (waited 10 s)");
}

// One "key <id> <last>" line into *out; false when it is not one.
bool counter_line(detail::Span line, std::int32_t* id, std::int64_t* last) noexcept {
  std::array<detail::Span, 3> f{};
  std::int64_t v = 0;
  if (detail::split_fields(line, false, f.data(), f.size()) != 3 || !f[0].equals("key") ||
      !detail::parse_decimal(f[1], 2147483647, &v) || v < 1 ||
      !detail::parse_decimal(f[2], kMaxArsn, last)) {
    return false;
  }
  *id = static_cast<std::int32_t>(v);  // 1 .. 2^31-1
  return true;
}

std::string counter_text(const std::map<std::int32_t, std::int64_t>& values) {
  std::string text = std::string(kCounterHeader) + "\n";
  for (const auto& kv : values) {
    text += "key " + std::to_string(kv.first) + " " + std::to_string(kv.second) + "\n";
  }
  return text;
}

}  // namespace

ArsnCounter::ArsnCounter(const std::string& key_file) : key_file_(key_file), path_(key_file + ".arsn") {
  std::string dir;
  std::string key_name;
  if (!detail::split_path(key_file, &dir, &key_name)) {
    throw std::runtime_error(label() + ": '" + key_file + "' is not a key file path");
  }
  name_ = key_name + ".arsn";
  tmp_ = name_ + ".tmp";
  detail::Fd dir_fd = detail::open_private_dir(dir, label());
  detail::Fd lock = detail::open_checked(dir_fd.get(), key_name.c_str(), "key file '" + key_file + "'");
  lock_or_throw(lock.get(), key_file);
  dir_fd_ = dir_fd.release();
  lock_fd_ = lock.release();
  try {
    read_existing();
  } catch (...) {
    (void)::close(lock_fd_);  // failing already: the lock goes with the descriptor
    (void)::close(dir_fd_);
    throw;
  }
}

ArsnCounter::~ArsnCounter() {
  // Read-only descriptors: closing releases the lock and loses nothing, whatever close says.
  if (lock_fd_ >= 0) (void)::close(lock_fd_);
  if (dir_fd_ >= 0) (void)::close(dir_fd_);
}

std::string ArsnCounter::label() const { return "ARSN counter '" + path_ + "'"; }

void ArsnCounter::read_existing() {
  bool missing = false;
  const detail::Fd fd = detail::open_checked(dir_fd_, name_.c_str(), label(), &missing);
  existed_ = !missing;
  if (missing) return;
  detail::SecretText text(kMaxCounterBytes);
  detail::read_all(fd.get(), &text, label());
  const char* p = text.data();
  std::size_t pos = 0;
  int line_no = 0;
  const std::string fix = " (remove the file to start from 0: the node's acknowledgement brings a "
                          "counter that is behind back up)";
  while (pos < text.size()) {  // pos grows by at least 1 per line
    const void* nl = std::memchr(p + pos, '\n', text.size() - pos);
    if (nl == nullptr) throw std::runtime_error(label() + " was cut: its last line has no newline" + fix);
    const std::size_t end = static_cast<std::size_t>(static_cast<const char*>(nl) - p);
    const detail::Span line{p + pos, end - pos};
    const std::string where = label() + " line " + std::to_string(++line_no) + ": ";
    std::int32_t id = 0;
    std::int64_t last = 0;
    if (line_no == 1 && !line.equals(kCounterHeader)) {
      std::string e = where;
      e.append("expected '").append(kCounterHeader).append("'").append(fix);
      throw std::runtime_error(e);
    }
    if (line_no > 1 && !counter_line(line, &id, &last)) {
      std::string e = where;
      e.append("expected 'key <id> <last ARSN>'").append(fix);
      throw std::runtime_error(e);
    }
    if (line_no > 1 && !last_.emplace(id, last).second) {
      std::string e = where;
      e.append("key id ").append(std::to_string(id)).append(" appears twice").append(fix);
      throw std::runtime_error(e);
    }
    pos = end + 1;
  }
  if (line_no == 0) throw std::runtime_error(label() + " is empty" + fix);
}

std::int64_t ArsnCounter::last(std::int32_t key_id) const noexcept {
  const auto it = last_.find(key_id);
  return it == last_.end() ? 0 : it->second;
}

std::int64_t ArsnCounter::next(std::int32_t key_id) {
  check_key_id(key_id);
  const std::int64_t prev = last(key_id);
  if (prev == kMaxArsn) {
    throw std::runtime_error(label() + ": key " + std::to_string(key_id) +
                             " has used the largest ARSN (9223372036854775807): it cannot sign "
                             "again; retire it and sign with a new key");
  }
  std::map<std::int32_t, std::int64_t> values = last_;
  values[key_id] = prev + 1;
  persist(values);
  last_.swap(values);
  return prev + 1;
}

void ArsnCounter::raise_to(std::int32_t key_id, std::int64_t floor) {
  check_key_id(key_id);
  if (floor <= last(key_id)) return;
  std::map<std::int32_t, std::int64_t> values = last_;
  values[key_id] = floor;
  persist(values);
  last_.swap(values);
}

void ArsnCounter::persist(const std::map<std::int32_t, std::int64_t>& values) const {
  const std::string text = counter_text(values);
  const int rc = detail::write_durably(dir_fd_, name_.c_str(), tmp_.c_str(), text.data(),
                                       text.size(), true);
  if (rc != 0) throw std::runtime_error(label() + " cannot be written: " + std::strerror(-rc));
}

}  // namespace evade::auth
