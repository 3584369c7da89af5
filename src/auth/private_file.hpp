// The auth module's private files, shared by the key files (docs/SECURITY.md KEY-1), the node's
// state file (AUTH-4) and the ground's ARSN counter (UPLINK-1, issue 40): opening a file without
// following a symbolic link and checking the open descriptor (a regular file, owned by this
// user, no group/other permission bits: no check-then-open race), bounded reads into a buffer
// that is wiped before it is freed, a checked directory, the durable replacement of a file
// (a new temporary name, fsync, rename, fsync of the directory) and the strict little parsers
// of their text formats. Internal to src/auth: not installed, not a public header.
// open_checked() and open_private_dir() are initialization code (allocate, throw
// std::runtime_error with one line); everything else neither allocates nor throws.
#pragma once

#include <sys/types.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace evade::auth::detail {

/// A file descriptor, closed on destruction (move-only; -1: none).
class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) noexcept : fd_(fd) {}
  ~Fd();
  Fd(Fd&& o) noexcept : fd_(o.release()) {}
  Fd& operator=(Fd&& o) noexcept;
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;

  int get() const noexcept { return fd_; }
  bool valid() const noexcept { return fd_ >= 0; }
  int release() noexcept;

 private:
  int fd_ = -1;
};

/// A fixed-capacity heap buffer for text that may hold key bytes: wiped (sodium_memzero) before
/// it is freed, also when an exception unwinds past it.
class SecretText {
 public:
  explicit SecretText(std::size_t capacity);  ///< allocates (initialization)
  ~SecretText();
  SecretText(const SecretText&) = delete;
  SecretText& operator=(const SecretText&) = delete;

  char* data() noexcept { return p_; }
  const char* data() const noexcept { return p_; }
  std::size_t capacity() const noexcept { return cap_; }
  std::size_t size() const noexcept { return n_; }
  void set_size(std::size_t n) noexcept { n_ = n <= cap_ ? n : cap_; }

 private:
  char* p_ = nullptr;
  std::size_t cap_ = 0;
  std::size_t n_ = 0;
};

/// Opens name (relative to dir_fd; AT_FDCWD for the working directory) with
/// O_RDONLY|O_NOFOLLOW|O_CLOEXEC|O_NOCTTY|O_NONBLOCK (a FIFO planted at the name cannot block
/// the open) and checks the open descriptor with fstat: a regular file, owned by geteuid(), no
/// group/other permission bits. label names the file in messages ("key file 'F'"). Throws
/// std::runtime_error "<label> is a symbolic link: refused", "... is not a regular file",
/// "... is owned by uid U, not by this user (uid V)", "... has mode 0644: group or others may
/// access it; chmod 600 it", or "<label>: <strerror>". When *missing is given and the name does
/// not exist, sets it and returns an invalid Fd instead of throwing.
Fd open_checked(int dir_fd, const char* name, const std::string& label, bool* missing = nullptr);

/// Reads fd to its end into out (at most out->capacity() bytes). Throws std::runtime_error
/// "<label> is larger than N bytes: ..." when there is more, "<label>: <strerror>" on an error.
void read_all(int fd, SecretText* out, const std::string& label);

/// Opens the directory dir (O_RDONLY|O_DIRECTORY|O_CLOEXEC) and checks it with fstat: owned by
/// geteuid() and not writable by group or others (no one else can plant, rename or remove a
/// name in it). Throws std::runtime_error "<label>: its directory 'D' ...".
Fd open_private_dir(const std::string& dir, const std::string& label);

/// Splits a path into its directory ("." when none, "/" at the root) and its last component;
/// false when there is no last component ("", "dir/", ".", "..").
bool split_path(const std::string& path, std::string* dir, std::string* name);

/// Writes data[0, n) as dir_fd/name durably: openat(dir_fd, tmp,
/// O_WRONLY|O_CREAT|O_EXCL|O_NOFOLLOW|O_CLOEXEC, 0600); on EEXIST unlinkat(dir_fd, tmp) (the
/// planted file or symbolic link itself, never a symlink's target) and one more try; write,
/// fsync, close; then renameat over name (replace) or linkat to name, which fails with -EEXIST
/// when anything exists there (!replace), and unlinkat of tmp; fsync of the directory. 0, or
/// -errno with tmp removed (the old file, or nothing, remains). No allocation, no exceptions.
int write_durably(int dir_fd, const char* name, const char* tmp, const char* data, std::size_t n,
                  bool replace) noexcept;

// ---- strict parsing of the auth files' text (no allocation) ----

/// A piece of a buffer: [p, p + n).
struct Span {
  const char* p = nullptr;
  std::size_t n = 0;
  bool equals(const char* s) const noexcept;  ///< the same characters as the C string s
};

/// Splits line into fields separated by runs of spaces and tabs (leading and trailing ones
/// ignored) when loose, else by single spaces (an empty field then counts as a field, so that a
/// doubled or trailing space is malformed). Stores up to max fields in out; returns how many
/// there are (possibly more than max).
std::size_t split_fields(Span line, bool loose, Span* out, std::size_t max) noexcept;

/// A decimal number of 1 to 19 digits, no sign, no leading zero (except "0" itself), at most
/// max. False for anything else.
bool parse_decimal(Span s, std::int64_t max, std::int64_t* out) noexcept;

/// Exactly 2 * n lower-case hex digits into out[0, n). False for anything else.
bool parse_hex(Span s, std::uint8_t* out, std::size_t n) noexcept;

/// True when s is 64 hex digits of either case: the shape of a key.
bool looks_like_key_hex(Span s) noexcept;

/// Appends to a fixed buffer; each returns false (and appends nothing) when it does not fit.
struct TextSink {
  char* buf;
  std::size_t cap;
  std::size_t n;
  bool put(const char* s) noexcept;
  bool put_decimal(std::int64_t v) noexcept;  ///< v >= 0
  bool put_hex(const std::uint8_t* b, std::size_t len) noexcept;
};

}  // namespace evade::auth::detail
