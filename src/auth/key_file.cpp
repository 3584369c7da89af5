// Key files (include/evade/auth/key_file.hpp; docs/SECURITY.md KEY-1, KEY-2): the checked read
// (no symbolic link, a regular private file of this user, checked on the open descriptor, at
// most 64 KiB into a buffer wiped before it is freed), the strict line parser whose errors name
// the line and the field but never echo any text of the file, the weak-key rule, key
// generation and the key states at loading (every command key standby until the state file
// says otherwise).
#include "evade/auth/key_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "private_file.hpp"

namespace evade::auth {
namespace {

using detail::Span;

constexpr int kMaxKeyDraws = 8;
constexpr const char* kKeyLineShape =
    "expected 'key <id> <command|sensor|telemetry> <64 hex digits>'";

// A control byte in a line, as a static text; nullptr when there is none. Tabs are spacing.
const char* key_line_control(Span line) noexcept {
  for (std::size_t i = 0; i < line.n; ++i) {
    const auto c = static_cast<unsigned char>(line.p[i]);
    if (c == '\r') return "has a carriage return: key files have Unix line endings (no CRLF)";
    if (c == 0) return "has a NUL byte";
    if ((c < 0x20U && c != '\t') || c == 0x7fU) return "has a control character";
  }
  return nullptr;
}

// A blank line or a '#' comment.
bool key_line_skipped(Span line) noexcept {
  for (std::size_t i = 0; i < line.n; ++i) {
    if (line.p[i] != ' ' && line.p[i] != '\t') return line.p[i] == '#';
  }
  return true;
}

// A hint for a field that has the shape of a key where it should not (fields swapped).
const char* key_shape_hint(Span field) noexcept {
  return detail::looks_like_key_hex(field)
             ? " (this field has the shape of a key: are the fields in the wrong order?)"
             : "";
}

bool role_from_span(Span s, KeyRole* role) noexcept {
  for (KeyRole r : {KeyRole::kCommand, KeyRole::kSensor, KeyRole::kTelemetry}) {
    if (s.equals(role_name(r))) {
      *role = r;
      return true;
    }
  }
  return false;
}

bool has_upper_hex(Span s) noexcept {
  for (std::size_t i = 0; i < s.n; ++i) {
    if (s.p[i] >= 'A' && s.p[i] <= 'F') return true;
  }
  return false;
}

// The fourth field into *key; throws naming what is wrong with it (never its text).
void parse_key_field(Span s, const std::string& where, KeyBytes* key) {
  if (s.n != 2 * kKeyBytes) {
    throw std::runtime_error(where + "the key (fourth field) must be 64 hex digits, not " +
                             std::to_string(s.n) + " characters");
  }
  if (detail::parse_hex(s, key->data(), key->size())) return;
  if (has_upper_hex(s)) {
    throw std::runtime_error(where +
                             "the key (fourth field) has upper-case hex digits: it must be 64 "
                             "lower-case hex digits, as evade keygen writes it");
  }
  throw std::runtime_error(where + "the key (fourth field) holds a character that is not a hex "
                                   "digit 0-9 or a-f");
}

// The four fields of a key line; throws naming the field that is wrong.
void parse_key_fields(const Span* f, const std::string& where, KeyRecord* r) {
  if (!f[0].equals("key")) {
    throw std::runtime_error(where + "the first field must be the word key" + key_shape_hint(f[0]));
  }
  std::int64_t id = 0;
  if (!detail::parse_decimal(f[1], 2147483647, &id) || id < 1) {
    throw std::runtime_error(where + "the id (second field) must be a whole number 1 .. 2147483647" +
                             key_shape_hint(f[1]));
  }
  r->id = static_cast<std::int32_t>(id);  // 1 .. 2^31-1
  if (!role_from_span(f[2], &r->role)) {
    throw std::runtime_error(where + "the role (third field) must be command, sensor or telemetry" +
                             key_shape_hint(f[2]));
  }
  parse_key_field(f[3], where, &r->key);
  if (const char* weak = key_weakness(r->key)) {
    throw std::runtime_error(where + "the key (fourth field) is weak (" + weak +
                             "): make a new one with evade keygen");
  }
}

// One line of a key file: skipped, or one more record in *out (its line in *lines).
void parse_key_line(Span line, const std::string& label, int line_no,
                    std::vector<KeyRecord>* out, std::vector<int>* lines) {
  const std::string where = label + " line " + std::to_string(line_no) + ": ";
  if (const char* bad = key_line_control(line)) throw std::runtime_error(where + bad);
  if (key_line_skipped(line)) return;
  std::array<Span, 4> f{};
  const std::size_t n = detail::split_fields(line, true, f.data(), f.size());
  if (n != f.size()) {
    throw std::runtime_error(where + (n < f.size() ? "a field is missing: " : "an extra field: ") +
                             kKeyLineShape + " (4 fields, not " + std::to_string(n) + ")");
  }
  KeyRecord r;
  parse_key_fields(f.data(), where, &r);
  for (std::size_t i = 0; i < out->size(); ++i) {
    if ((*out)[i].id == r.id) {
      throw std::runtime_error(where + "key id " + std::to_string(r.id) +
                               " appears twice (first on line " + std::to_string((*lines)[i]) + ")");
    }
  }
  out->push_back(r);
  lines->push_back(line_no);
}

// The text of a key file holding key; false if it does not fit (69 + 4 + 10 + 1 + 9 + 1 + 64 + 1
// = 159 bytes at most: it always fits in 256).
bool format_key_text(const KeyRecord& key, detail::TextSink* out) noexcept {
  return out->put("# evade HMAC-SHA-256 key (docs/SECURITY.md). Secret: keep mode 0600.\n") &&
         out->put("key ") && out->put_decimal(key.id) && out->put(" ") &&
         out->put(role_name(key.role)) && out->put(" ") &&
         out->put_hex(key.key.data(), key.key.size()) && out->put("\n");
}

// Writes text[0, n) to a new file at path (mode 0600; O_EXCL: never over a file, nor through a
// symbolic link) and fsyncs it. 0, or the errno; a file this call created is removed again on
// failure (a partial key file must not remain).
int create_key_file(const std::string& path, const char* text, std::size_t n) noexcept {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) return errno;
  const ssize_t w = ::write(fd, text, n);
  int err = w == static_cast<ssize_t>(n) ? 0 : (w < 0 ? errno : EIO);  // n <= 256
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) (void)::unlink(path.c_str());  // failing already: the unlink's own result adds nothing
  return err;
}

std::vector<KeyRecord> parse_key_text(const detail::SecretText& text, const std::string& label) {
  std::vector<KeyRecord> out;
  std::vector<int> lines;
  const char* p = text.data();
  const std::size_t n = text.size();
  std::size_t pos = 0;
  int line_no = 0;
  while (pos < n) {  // pos grows by at least 1 per line: at most n passes
    const void* nl = std::memchr(p + pos, '\n', n - pos);
    const std::size_t end = nl == nullptr ? n : static_cast<std::size_t>(static_cast<const char*>(nl) - p);
    ++line_no;
    parse_key_line(Span{p + pos, end - pos}, label, line_no, &out, &lines);
    pos = end + 1;
  }
  if (out.empty()) throw std::runtime_error(label + " holds no key");
  return out;
}

}  // namespace

KeyRecord::~KeyRecord() { wipe(key.data(), key.size()); }

const char* role_name(KeyRole r) noexcept {
  switch (r) {
    case KeyRole::kCommand: return "command";
    case KeyRole::kSensor: return "sensor";
    case KeyRole::kTelemetry: return "telemetry";
  }
  return "command";
}

bool parse_role(const std::string& name, KeyRole* role) noexcept {
  return role_from_span(Span{name.data(), name.size()}, role);
}

std::vector<KeyRecord> read_key_file(const std::string& path) {
  const std::string label = "key file '" + path + "'";
  const detail::Fd fd = detail::open_checked(AT_FDCWD, path.c_str(), label);
  detail::SecretText text(kMaxKeyFileBytes);
  detail::read_all(fd.get(), &text, label);
  return parse_key_text(text, label);
}

// The probabilities of refusing a key drawn from a working generator: all zero 2^-256; an
// arithmetic sequence 2^16 of 2^256 keys (2^-240); fewer than 16 distinct values among 32
// uniform random bytes 3.2e-17 (sum over k <= 15 of C(256,k) S(32,k) k! / 256^32, S the Stirling
// numbers of the second kind; at most 16 distinct: 2.2e-15). 32 distinct values happen with
// probability 0.13, so the rule refuses only keys no generator should produce.
const char* key_weakness(const KeyBytes& key) noexcept {
  bool all_zero = true;
  bool arithmetic = true;
  const auto step = static_cast<std::uint8_t>(key[1] - key[0]);  // mod 256
  std::array<bool, 256> seen{};
  int distinct = 0;
  for (std::size_t i = 0; i < key.size(); ++i) {
    all_zero = all_zero && key[i] == 0;
    if (i > 0 && static_cast<std::uint8_t>(key[i] - key[i - 1]) != step) arithmetic = false;
    if (!seen[key[i]]) ++distinct;
    seen[key[i]] = true;
  }
  wipe(seen.data(), seen.size());  // which byte values the key holds
  if (all_zero) return "all zero";
  if (arithmetic) return "an arithmetic sequence: the same difference between successive bytes";
  if (distinct < 16) return "fewer than 16 distinct byte values";
  return nullptr;
}

KeyRecord generate_key(std::int32_t id, KeyRole role, RandomSource source) {
  if (id < 1) throw std::invalid_argument("key id must be 1 .. 2147483647");
  if (source == nullptr) throw std::invalid_argument("generate_key: no random source");
  KeyRecord r;
  r.id = id;
  r.role = role;
  for (int draw = 0; draw < kMaxKeyDraws; ++draw) {
    if (!source(r.key.data(), r.key.size())) {
      throw std::runtime_error("the random generator failed (libsodium could not be initialized): "
                               "no key made");
    }
    if (key_weakness(r.key) == nullptr) return r;
  }
  throw std::runtime_error("the random generator gave 8 weak keys in a row: it is broken; no key "
                           "made");
}

void write_key_file(const std::string& path, const KeyRecord& key) {
  if (key.id < 1) throw std::invalid_argument("key id must be 1 .. 2147483647");
  if (const char* weak = key_weakness(key.key)) {
    throw std::runtime_error("key file '" + path + "': refusing to write a weak key (" + weak + ")");
  }
  char text[256];
  detail::TextSink out{text, sizeof(text), 0};
  const int err = format_key_text(key, &out) ? create_key_file(path, text, out.n) : ENOSPC;
  wipe(text, sizeof(text));
  if (err != 0) {
    throw std::runtime_error("cannot create key file '" + path + "': " + std::strerror(err));
  }
}

void load_into(const std::vector<KeyRecord>& records, KeyRing* ring) {
  for (const KeyRecord& r : records) {
    const KeyState s = r.role == KeyRole::kCommand ? KeyState::kStandby : KeyState::kActive;
    const char* why = ring->add(r.id, r.role, r.key, s);
    if (why != nullptr) {
      throw std::runtime_error("key " + std::to_string(r.id) + ": " + why);
    }
  }
}

}  // namespace evade::auth
