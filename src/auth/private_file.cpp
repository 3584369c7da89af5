// The auth module's private files (src/auth/private_file.hpp): the checked open, bounded read,
// checked directory and durable write shared by the key files (docs/SECURITY.md KEY-1), the
// node's state file (AUTH-4) and the ground's ARSN counter (UPLINK-1, issue 40).
#include "private_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "evade/auth/mac.hpp"

namespace evade::auth::detail {
namespace {

constexpr int kMaxIoAttempts = 1000;  // write/read calls per file: each moves >= 1 byte or is EINTR

std::string mode_octal(mode_t mode) {
  char text[8];
  // Four octal digits and a NUL always fit in 8 bytes: snprintf cannot truncate or fail here.
  (void)std::snprintf(text, sizeof(text), "%04o", mode & 07777U);
  return text;
}

// Why st (of an open descriptor) is not a private file, as the message's tail; "" when it is.
std::string private_file_problem(const struct stat& st) {
  if (!S_ISREG(st.st_mode)) return " is not a regular file";
  if (st.st_uid != ::geteuid()) {
    return " is owned by uid " + std::to_string(st.st_uid) + ", not by this user (uid " +
           std::to_string(::geteuid()) + ")";
  }
  if ((st.st_mode & 077U) != 0) {
    return " has mode " + mode_octal(st.st_mode) +
           ": group or others may access it; chmod 600 it";
  }
  return "";
}

int write_all(int fd, const char* data, std::size_t n) noexcept {
  std::size_t done = 0;
  for (int attempt = 0; attempt < kMaxIoAttempts && done < n; ++attempt) {
    const ssize_t w = ::write(fd, data + done, n - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return w < 0 ? -errno : -EIO;
    done += static_cast<std::size_t>(w);  // 0 < w <= n - done
  }
  return done == n ? 0 : -EIO;
}

// Creates tmp afresh in dir_fd: a name already there (a crash's leftover, or a file or
// symbolic link planted by someone) is unlinked itself, once. The descriptor, or -errno.
int create_temporary(int dir_fd, const char* tmp) noexcept {
  constexpr int kFlags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
  int fd = ::openat(dir_fd, tmp, kFlags, 0600);
  if (fd < 0 && errno == EEXIST) {
    if (::unlinkat(dir_fd, tmp, 0) != 0) return -errno;  // a directory: refused, not removed
    fd = ::openat(dir_fd, tmp, kFlags, 0600);
  }
  return fd < 0 ? -errno : fd;
}

// Moves the written temporary to name: over it (replace) or only where nothing is (a hard
// link fails with EEXIST; then the temporary name goes). 0 or -errno.
int publish_temporary(int dir_fd, const char* tmp, const char* name, bool replace) noexcept {
  if (replace) return ::renameat(dir_fd, tmp, dir_fd, name) == 0 ? 0 : -errno;
  if (::linkat(dir_fd, tmp, dir_fd, name, 0) != 0) return -errno;
  return ::unlinkat(dir_fd, tmp, 0) == 0 ? 0 : -errno;
}

}  // namespace

Fd::~Fd() {
  // A read-only or already fsync'ed descriptor: nothing is lost if close reports an error.
  if (fd_ >= 0) (void)::close(fd_);
}

Fd& Fd::operator=(Fd&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) (void)::close(fd_);  // as in the destructor
    fd_ = o.release();
  }
  return *this;
}

int Fd::release() noexcept {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

SecretText::SecretText(std::size_t capacity) : p_(new char[capacity]), cap_(capacity) {}

SecretText::~SecretText() {
  wipe(p_, cap_);
  delete[] p_;
}

Fd open_checked(int dir_fd, const char* name, const std::string& label, bool* missing) {
  Fd fd(::openat(dir_fd, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY | O_NONBLOCK));
  if (!fd.valid()) {
    const int err = errno;
    if (err == ENOENT && missing != nullptr) {
      *missing = true;
      return fd;
    }
    if (err == ELOOP) throw std::runtime_error(label + " is a symbolic link: refused");
    throw std::runtime_error(label + ": " + std::strerror(err));
  }
  if (missing != nullptr) *missing = false;
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) throw std::runtime_error(label + ": " + std::strerror(errno));
  const std::string problem = private_file_problem(st);
  if (!problem.empty()) throw std::runtime_error(label + problem);
  return fd;
}

void read_all(int fd, SecretText* out, const std::string& label) {
  std::size_t n = 0;
  char probe = 0;
  for (int attempt = 0; attempt < kMaxIoAttempts; ++attempt) {
    const bool full = n == out->capacity();
    char* dst = full ? &probe : out->data() + n;  // full: is there one byte more?
    const ssize_t r = ::read(fd, dst, full ? 1U : out->capacity() - n);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw std::runtime_error(label + ": " + std::strerror(errno));
    if (r == 0) {
      out->set_size(n);
      return;
    }
    if (full) {
      wipe(&probe, 1);
      throw std::runtime_error(label + " is larger than " + std::to_string(out->capacity()) +
                               " bytes: refused");
    }
    n += static_cast<std::size_t>(r);  // 0 < r <= capacity - n
  }
  throw std::runtime_error(label + ": the read did not finish");
}

Fd open_private_dir(const std::string& dir, const std::string& label) {
  Fd fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  const std::string where = label + ": its directory '" + dir + "'";
  if (!fd.valid()) throw std::runtime_error(where + ": " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) throw std::runtime_error(where + ": " + std::strerror(errno));
  if (st.st_uid != ::geteuid()) {
    throw std::runtime_error(where + " is owned by uid " + std::to_string(st.st_uid) +
                             ", not by this user (uid " + std::to_string(::geteuid()) + ")");
  }
  if ((st.st_mode & 022U) != 0) {
    throw std::runtime_error(where + " has mode " + mode_octal(st.st_mode) +
                             ": group or others may write in it; chmod go-w it");
  }
  return fd;
}

bool split_path(const std::string& path, std::string* dir, std::string* name) {
  const std::size_t slash = path.rfind('/');
  *name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (slash == std::string::npos) {
    *dir = ".";
  } else {
    *dir = slash == 0 ? "/" : path.substr(0, slash);
  }
  return !name->empty() && *name != "." && *name != "..";
}

int write_durably(int dir_fd, const char* name, const char* tmp, const char* data, std::size_t n,
                  bool replace) noexcept {
  const int fd = create_temporary(dir_fd, tmp);
  if (fd < 0) return fd;
  int rc = write_all(fd, data, n);
  if (rc == 0 && ::fsync(fd) != 0) rc = -errno;
  if (::close(fd) != 0 && rc == 0) rc = -errno;
  if (rc == 0) rc = publish_temporary(dir_fd, tmp, name, replace);
  if (rc != 0) {
    (void)::unlinkat(dir_fd, tmp, 0);  // failing already: only the old file (or none) may remain
    return rc;
  }
  return ::fsync(dir_fd) == 0 ? 0 : -errno;
}

// ---- parsing and formatting ----

bool Span::equals(const char* s) const noexcept {
  const std::size_t len = std::strlen(s);
  return len == n && std::memcmp(p, s, n) == 0;
}

std::size_t split_fields(Span line, bool loose, Span* out, std::size_t max) noexcept {
  std::size_t count = 0;
  std::size_t i = 0;
  const auto sep = [&](std::size_t k) {
    return line.p[k] == ' ' || (loose && line.p[k] == '\t');
  };
  while (i <= line.n) {  // i grows every pass: at most line.n + 1 passes
    if (loose) {
      while (i < line.n && sep(i)) ++i;
      if (i == line.n) break;
    }
    const std::size_t start = i;
    while (i < line.n && !sep(i)) ++i;
    if (count < max) out[count] = Span{line.p + start, i - start};
    ++count;
    ++i;  // past the separator (or past the end)
  }
  return count;
}

bool parse_decimal(Span s, std::int64_t max, std::int64_t* out) noexcept {
  if (s.n == 0 || s.n > 19 || (s.n > 1 && s.p[0] == '0')) return false;
  std::int64_t v = 0;
  for (std::size_t i = 0; i < s.n; ++i) {
    const char c = s.p[i];
    if (c < '0' || c > '9') return false;
    const int d = c - '0';
    if (v > max / 10 || (v == max / 10 && d > max % 10)) return false;  // v * 10 + d > max
    v = v * 10 + d;
  }
  *out = v;
  return true;
}

bool parse_hex(Span s, std::uint8_t* out, std::size_t n) noexcept {
  if (s.n != 2 * n) return false;
  const auto digit = [](char c) {
    if (c >= '0' && c <= '9') return c - '0';
    return (c >= 'a' && c <= 'f') ? c - 'a' + 10 : -1;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const int hi = digit(s.p[2 * i]);
    const int lo = digit(s.p[2 * i + 1]);
    if (hi < 0 || lo < 0) return false;
    out[i] = static_cast<std::uint8_t>(hi * 16 + lo);  // 0 .. 255
  }
  return true;
}

bool looks_like_key_hex(Span s) noexcept {
  if (s.n != 2 * kKeyBytes) return false;
  for (std::size_t i = 0; i < s.n; ++i) {
    const char c = s.p[i];
    const bool hex = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
    if (!hex) return false;
  }
  return true;
}

bool TextSink::put(const char* s) noexcept {
  const std::size_t len = std::strlen(s);
  if (len > cap - n) return false;
  (void)std::memcpy(buf + n, s, len);  // returns its destination
  n += len;
  return true;
}

bool TextSink::put_decimal(std::int64_t v) noexcept {
  char digits[20];
  std::size_t k = 0;
  std::uint64_t u = v < 0 ? 0U : static_cast<std::uint64_t>(v);
  do {
    digits[k++] = static_cast<char>('0' + u % 10U);  // one digit
    u /= 10U;
  } while (u != 0 && k < sizeof(digits));
  if (k > cap - n) return false;
  for (std::size_t i = 0; i < k; ++i) buf[n + i] = digits[k - 1 - i];
  n += k;
  return true;
}

bool TextSink::put_hex(const std::uint8_t* b, std::size_t len) noexcept {
  static const char kDigits[] = "0123456789abcdef";
  if (2 * len > cap - n) return false;
  for (std::size_t i = 0; i < len; ++i) {
    buf[n + 2 * i] = kDigits[b[i] >> 4U];
    buf[n + 2 * i + 1] = kDigits[b[i] & 0x0FU];
  }
  n += 2 * len;
  return true;
}

}  // namespace evade::auth::detail
