// Key files (include/evade/auth/key_file.hpp).
#include "evade/auth/key_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace evade::auth {
namespace {

int hex_digit(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool parse_hex_key(const std::string& hex, KeyBytes* out) noexcept {
  if (hex.size() != 2 * kKeyBytes) return false;
  for (std::size_t i = 0; i < kKeyBytes; ++i) {
    const int hi = hex_digit(hex[2 * i]);
    const int lo = hex_digit(hex[2 * i + 1]);
    if (hi < 0 || lo < 0) return false;
    (*out)[i] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  return true;
}

void check_private_file(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    throw std::runtime_error("key file '" + path + "': " + std::strerror(errno));
  }
  if (!S_ISREG(st.st_mode)) throw std::runtime_error("key file '" + path + "': not a regular file");
  if ((st.st_mode & 077U) != 0) {
    char mode[8];
    (void)std::snprintf(mode, sizeof(mode), "%04o", st.st_mode & 07777U);
    throw std::runtime_error("key file '" + path + "' has mode " + mode +
                             ": group or others may access it; chmod 600 it");
  }
}

KeyRecord parse_key_line(const std::string& path, int line_no, const std::string& line) {
  std::istringstream in(line);
  std::string word, role, hex, extra;
  long long id = 0;
  const std::string where = "key file '" + path + "' line " + std::to_string(line_no) + ": ";
  if (!(in >> word >> id >> role >> hex) || word != "key" || (in >> extra)) {
    throw std::runtime_error(where + "expected 'key <id> <command|sensor> <64 hex digits>'");
  }
  KeyRecord r;
  if (id < 1 || id > 2147483647LL) throw std::runtime_error(where + "key id must be 1 .. 2147483647");
  r.id = static_cast<std::int32_t>(id);
  if (role == "command") {
    r.role = KeyRole::kCommand;
  } else if (role == "sensor") {
    r.role = KeyRole::kSensor;
  } else {
    throw std::runtime_error(where + "role '" + role + "' is not command or sensor");
  }
  if (!parse_hex_key(hex, &r.key)) {
    throw std::runtime_error(where + "the key is not 64 hex digits (its value is not shown)");
  }
  return r;
}

}  // namespace

const char* role_name(KeyRole r) noexcept {
  switch (r) {
    case KeyRole::kCommand: return "command";
    case KeyRole::kSensor: return "sensor";
    case KeyRole::kTelemetry: return "telemetry";
  }
  return "command";
}

std::vector<KeyRecord> read_key_file(const std::string& path) {
  check_private_file(path);
  std::ifstream f(path);
  if (!f) throw std::runtime_error("key file '" + path + "': cannot open");
  std::vector<KeyRecord> out;
  std::set<std::int32_t> ids;
  std::string line;
  int line_no = 0;
  while (std::getline(f, line)) {
    ++line_no;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    out.push_back(parse_key_line(path, line_no, line));
    if (!ids.insert(out.back().id).second) {
      throw std::runtime_error("key file '" + path + "' line " + std::to_string(line_no) +
                               ": key id " + std::to_string(out.back().id) + " appears twice");
    }
  }
  if (out.empty()) throw std::runtime_error("key file '" + path + "' holds no key");
  return out;
}

KeyRecord generate_key(std::int32_t id, KeyRole role) {
  if (id < 1) throw std::invalid_argument("key id must be 1 .. 2147483647");
  KeyRecord r;
  r.id = id;
  r.role = role;
  if (!random_bytes(r.key.data(), r.key.size())) {
    throw std::runtime_error("libsodium could not be initialized: no random key");
  }
  return r;
}

void write_key_file(const std::string& path, const KeyRecord& key) {
  char text[256];
  int n = std::snprintf(text, sizeof(text),
                        "# evade HMAC-SHA-256 key (docs/SECURITY.md). Secret: keep mode 0600.\n"
                        "key %d %s ",
                        static_cast<int>(key.id), role_name(key.role));
  for (std::uint8_t b : key.key) n += std::snprintf(text + n, sizeof(text) - static_cast<std::size_t>(n), "%02x", b);
  n += std::snprintf(text + n, sizeof(text) - static_cast<std::size_t>(n), "\n");
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    wipe(text, sizeof(text));
    throw std::runtime_error("cannot create key file '" + path + "': " + std::strerror(errno));
  }
  const bool ok = ::write(fd, text, static_cast<std::size_t>(n)) == n && ::fsync(fd) == 0;
  const int err = errno;
  wipe(text, sizeof(text));
  const bool closed = ::close(fd) == 0;
  if (!ok || !closed) {
    (void)::unlink(path.c_str());  // failing already: a partial key file must not remain
    throw std::runtime_error("cannot write key file '" + path + "': " + std::strerror(err));
  }
}

void load_into(const std::vector<KeyRecord>& records, KeyRing* ring) {
  bool have_active_command = ring->active_command_keys() > 0;
  for (const KeyRecord& r : records) {
    KeyState s = KeyState::kActive;
    if (r.role == KeyRole::kCommand) {
      s = have_active_command ? KeyState::kStandby : KeyState::kActive;
      have_active_command = true;
    }
    const char* why = ring->add(r.id, r.role, r.key, s);
    if (why != nullptr) {
      throw std::runtime_error("key " + std::to_string(r.id) + ": " + why);
    }
  }
}

}  // namespace evade::auth
