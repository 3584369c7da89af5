// Persisted key states and command ARSNs (include/evade/auth/state_file.hpp).
#include "evade/auth/state_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace evade::auth {
namespace {

const char* state_name(KeyState s) noexcept {
  switch (s) {
    case KeyState::kActive: return "active";
    case KeyState::kStandby: return "standby";
    case KeyState::kRetired: return "retired";
  }
  return "retired";
}

bool parse_state(const std::string& w, KeyState* s) {
  if (w == "active") *s = KeyState::kActive;
  else if (w == "standby") *s = KeyState::kStandby;
  else if (w == "retired") *s = KeyState::kRetired;
  else return false;
  return true;
}

// Formats the state into buf; the byte count, or -1 if it does not fit.
int format_state(const KeyRing& ring, char* buf, std::size_t cap) noexcept {
  int n = std::snprintf(buf, cap, "evade-auth-state 1\n");
  for (std::size_t i = 0; i < ring.size() && n > 0 && static_cast<std::size_t>(n) < cap; ++i) {
    const KeyEntry& e = ring.entry(i);
    n += std::snprintf(buf + n, cap - static_cast<std::size_t>(n), "key %d %s %lld\n",
                       static_cast<int>(e.id), state_name(e.state),
                       static_cast<long long>(e.arsn[static_cast<std::size_t>(ArsnSlot::kCommand)]));
  }
  return (n > 0 && static_cast<std::size_t>(n) < cap) ? n : -1;
}

int write_all_and_sync(int fd, const char* buf, std::size_t n) noexcept {
  std::size_t done = 0;
  while (done < n) {
    const ssize_t w = ::write(fd, buf + done, n - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return w < 0 ? -errno : -EIO;
    done += static_cast<std::size_t>(w);
  }
  return ::fsync(fd) == 0 ? 0 : -errno;
}

}  // namespace

StateFile::StateFile(std::string path) : path_(std::move(path)) {
  if (path_.empty()) return;
  tmp_path_ = path_ + ".tmp";
  const std::size_t slash = path_.rfind('/');
  dir_path_ = slash == std::string::npos ? "." : (slash == 0 ? "/" : path_.substr(0, slash));
}

// One "key <id> <active|standby|retired> <arsn>" line into ring; throws naming the line.
void StateFile::restore_line(const std::string& line, int line_no, KeyRing* ring) const {
  std::istringstream in(line);
  std::string word, state, extra;
  long long id = 0, arsn = 0;
  KeyState s = KeyState::kActive;
  const bool read = static_cast<bool>(in >> word >> id >> state >> arsn) && !(in >> extra);
  if (!read || word != "key" || !parse_state(state, &s) || id < 1 || id > 2147483647LL ||
      arsn < 0) {
    throw std::runtime_error("auth state file '" + path_ + "' line " + std::to_string(line_no) +
                             ": expected 'key <id> <active|standby|retired> <arsn>'");
  }
  (void)ring->restore(static_cast<std::int32_t>(id), s, arsn);  // a key not loaded: ignored
}

void StateFile::load(KeyRing* ring) const {
  if (!enabled()) return;
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) {
    if (errno == ENOENT) return;  // first start
    throw std::runtime_error("auth state file '" + path_ + "': " + std::strerror(errno));
  }
  if (!S_ISREG(st.st_mode)) throw std::runtime_error("auth state file '" + path_ + "': not a regular file");
  std::ifstream f(path_);
  std::string line;
  if (!f || !std::getline(f, line) || line != "evade-auth-state 1") {
    // An empty or foreign file must not pass for a first start: that would reset every ARSN
    // and bring retired keys back.
    throw std::runtime_error("auth state file '" + path_ + "': not an evade-auth-state 1 file");
  }
  int line_no = 1;
  while (std::getline(f, line)) {
    ++line_no;
    restore_line(line, line_no, ring);
  }
}

int StateFile::save(const KeyRing& ring) const noexcept {
  if (!enabled()) return 0;
  char buf[1024];
  const int n = format_state(ring, buf, sizeof(buf));
  if (n < 0) return -ENOSPC;
  const int fd = ::open(tmp_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) return -errno;
  int rc = write_all_and_sync(fd, buf, static_cast<std::size_t>(n));
  if (::close(fd) != 0 && rc == 0) rc = -errno;
  if (rc == 0 && ::rename(tmp_path_.c_str(), path_.c_str()) != 0) rc = -errno;
  if (rc != 0) {
    (void)::unlink(tmp_path_.c_str());  // failing already: only the old state may remain
    return rc;
  }
  const int dfd = ::open(dir_path_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd < 0) return -errno;
  rc = ::fsync(dfd) == 0 ? 0 : -errno;
  if (::close(dfd) != 0 && rc == 0) rc = -errno;
  return rc;
}

}  // namespace evade::auth
