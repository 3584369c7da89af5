// The text of the node's state file, version 2 (src/auth/state_text.hpp; docs/SECURITY.md
// AUTH-4, KEY-2; issue 40): the version and the MAC checked before any line is trusted, the
// strict parse of the lines, the checks against the loaded keys, and the allocation-free
// formatting that auth::StateFile::save writes.
#include "state_text.hpp"

#include <cstring>
#include <stdexcept>

#include "evade/auth/key_file.hpp"

namespace evade::auth::detail {
namespace {

constexpr std::size_t kMacLineBytes = 4 + 2 * kMacBytes + 1;  // "mac " + 64 hex + "\n"
constexpr std::int64_t kMaxId = 2147483647;

const char* state_word(KeyState s) noexcept {
  switch (s) {
    case KeyState::kActive: return "active";
    case KeyState::kStandby: return "standby";
    case KeyState::kRetired: return "retired";
  }
  return "retired";
}

bool state_from_span(Span s, KeyState* out) noexcept {
  for (KeyState k : {KeyState::kActive, KeyState::kStandby, KeyState::kRetired}) {
    if (s.equals(state_word(k))) {
      *out = k;
      return true;
    }
  }
  return false;
}

bool state_role_from_span(Span s, KeyRole* out) noexcept {
  if (s.equals("command")) *out = KeyRole::kCommand;
  else if (s.equals("sensor")) *out = KeyRole::kSensor;
  else return false;
  return true;
}

bool state_parse_id(Span s, std::int32_t* id) noexcept {
  std::int64_t v = 0;
  if (!parse_decimal(s, kMaxId, &v) || v < 1) return false;
  *id = static_cast<std::int32_t>(v);  // 1 .. 2^31-1
  return true;
}

bool state_parse_key(const Span* f, StateRecord* r) noexcept {
  return f[0].equals("key") && state_parse_id(f[1], &r->id) &&
         state_role_from_span(f[2], &r->role) && state_from_span(f[3], &r->state) &&
         parse_decimal(f[4], kStateMaxCount, &r->command_arsn) &&
         parse_hex(f[5], r->kcv.data(), r->kcv.size());
}

bool state_parse_writes(const Span* f, std::size_t n, ParsedState* st) noexcept {
  return n == 2 && f[0].equals("writes") && parse_decimal(f[1], kStateMaxCount, &st->writes);
}

bool state_parse_telemetry(const Span* f, std::size_t n, ParsedState* st) noexcept {
  return n == 3 && f[0].equals("telemetry") && state_parse_id(f[1], &st->telemetry_id) &&
         parse_hex(f[2], st->telemetry_kcv.data(), st->telemetry_kcv.size());
}

// A key line (line 4 and up) as one more record of *st; throws naming the line.
void state_add_record(const Span* f, std::size_t n, const std::string& where, ParsedState* st) {
  StateRecord r;
  if (n != 6 || !state_parse_key(f, &r)) {
    throw std::runtime_error(where + "expected 'key <id> <command|sensor> <active|standby|retired> "
                                     "<command arsn> <check value>'");
  }
  for (std::size_t i = 0; i < st->n; ++i) {
    if (st->records[i].id == r.id) {
      throw std::runtime_error(where + "key id " + std::to_string(r.id) + " appears twice");
    }
  }
  if (r.id == st->telemetry_id) {
    throw std::runtime_error(where + "key id " + std::to_string(r.id) + " is the telemetry key's");
  }
  if (st->n == StateFile::kMaxRecords) {
    throw std::runtime_error(where + "more than " + std::to_string(StateFile::kMaxRecords) +
                             " key records");
  }
  st->records[st->n++] = r;
}

// Line line_no (2 and up) of an authentic file into *st; throws naming the line.
void state_parse_line(Span line, int line_no, ParsedState* st, const std::string& label) {
  std::array<Span, 6> f{};
  const std::size_t n = split_fields(line, false, f.data(), f.size());
  const std::string where = label + " line " + std::to_string(line_no) + ": ";
  if (line_no == 2 && !state_parse_writes(f.data(), n, st)) {
    throw std::runtime_error(where + "expected 'writes <n>'");
  }
  if (line_no == 3 && !state_parse_telemetry(f.data(), n, st)) {
    throw std::runtime_error(where + "expected 'telemetry <id> <check value>'");
  }
  if (line_no > 3) state_add_record(f.data(), n, where, st);
}

}  // namespace

const char* const kStateHeader = "evade-auth-state 2";

// The first line decides the version; anything but version 2 is refused with what it is.
void state_check_version(Span text, const std::string& label) {
  const void* nl = std::memchr(text.p, '\n', text.n);
  const Span first{text.p, nl == nullptr ? text.n : static_cast<std::size_t>(static_cast<const char*>(nl) - text.p)};
  if (first.equals(kStateHeader)) return;  // the MAC check refuses it if nothing follows
  if (first.equals("evade-auth-state 1")) {
    throw std::runtime_error(label + " is an unauthenticated version-1 file: it cannot show that it "
                             "was not changed or cut; move it aside and start the node once with "
                             "--auth-init KEY_ID (docs/SECURITY.md)");
  }
  const std::string v = "evade-auth-state ";
  if (first.n > v.size() && std::memcmp(first.p, v.data(), v.size()) == 0) {
    throw std::runtime_error(label + " is another version of the format, not 2");
  }
  throw std::runtime_error(label + " is not an evade auth state file (its first line is not '" +
                           kStateHeader + "')");
}

// The MAC line is the file's last; the bytes it signs are returned (its offset).
std::size_t state_verify_mac(Span text, const KeyBytes& mac_key, const std::string& label) {
  const std::string bad = label + " does not verify: it was changed, cut, or written under "
                                  "another telemetry key";
  if (text.n < kMacLineBytes + 1 || text.p[text.n - 1] != '\n') throw std::runtime_error(bad);
  const std::size_t at = text.n - kMacLineBytes;
  Mac stored{};
  if (text.p[at - 1] != '\n' || std::memcmp(text.p + at, "mac ", 4) != 0 ||
      !parse_hex(Span{text.p + at + 4, 2 * kMacBytes}, stored.data(), stored.size())) {
    throw std::runtime_error(bad);
  }
  const Mac computed = hmac_sha256(mac_key.data(), mac_key.size(),
                                   reinterpret_cast<const std::uint8_t*>(text.p), at);
  if (!mac_equal(stored.data(), computed.data())) throw std::runtime_error(bad);
  return at;
}

// Every line after the header, up to the MAC line (signed bytes [0, end), ending in '\n').
ParsedState state_parse(Span text, std::size_t end, const std::string& label) {
  ParsedState st;
  std::size_t pos = 0;
  int line_no = 0;
  while (pos < end) {  // pos grows by at least 1 per line
    const void* nl = std::memchr(text.p + pos, '\n', end - pos);  // found: end - 1 is '\n'
    const std::size_t stop =
        nl == nullptr ? end : static_cast<std::size_t>(static_cast<const char*>(nl) - text.p);
    ++line_no;
    if (line_no > 1) state_parse_line(Span{text.p + pos, stop - pos}, line_no, &st, label);
    pos = stop + 1;
  }
  if (line_no < 3) throw std::runtime_error(label + " line " + std::to_string(line_no + 1) + ": missing");
  return st;
}

const StateRecord* state_find(const ParsedState& st, std::int32_t id) noexcept {
  for (std::size_t i = 0; i < st.n; ++i) {
    if (st.records[i].id == id) return &st.records[i];
  }
  return nullptr;
}

// The state key e would get from st (its record, or new: command standby, sensor active).
KeyState state_for(const ParsedState& st, const KeyEntry& e) noexcept {
  const StateRecord* r = state_find(st, e.id);
  if (r != nullptr) return r->state;
  return e.role == KeyRole::kCommand ? KeyState::kStandby : KeyState::kActive;
}

// Every refusal of load() that concerns the loaded keys, before anything changes.
void state_check_keys(const ParsedState& st, const KeyRing& ring, const std::string& label) {
  std::size_t loaded = 0;
  std::size_t matched = 0;
  int commands = 0;
  int active = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const KeyEntry& e = ring.entry(i);
    const StateRecord* r = state_find(st, e.id);
    if (e.role != KeyRole::kTelemetry) ++loaded;
    if (r != nullptr) {
      ++matched;
      if (r->role != e.role) {
        throw std::runtime_error(label + ": key " + std::to_string(e.id) + " is a " + role_name(r->role) +
                                 " key in it but a " + role_name(e.role) + " key in the key files");
      }
      if (r->kcv != key_check_value(e.key)) {
        throw std::runtime_error(label + ": key " + std::to_string(e.id) +
                                 " is not the key this state file was written for");
      }
    }
    if (e.role == KeyRole::kCommand) {
      ++commands;
      if (state_for(st, e) == KeyState::kActive) ++active;
    }
  }
  if (loaded + (st.n - matched) > StateFile::kMaxRecords) {
    throw std::runtime_error(label + ": its records and the loaded keys are more than " +
                             std::to_string(StateFile::kMaxRecords) + " keys");
  }
  if (commands > 0 && active == 0) {
    throw std::runtime_error(label + " leaves no loaded command key active: the ground could not "
                             "command the node (is the active key's file missing from --keys?)");
  }
}

bool state_put_record(TextSink* out, std::int32_t id, KeyRole role, KeyState state,
                      std::int64_t arsn, const KeyCheckValue& kcv) noexcept {
  return out->put("key ") && out->put_decimal(id) && out->put(" ") && out->put(role_name(role)) &&
         out->put(" ") && out->put(state_word(state)) && out->put(" ") && out->put_decimal(arsn) &&
         out->put(" ") && out->put_hex(kcv.data(), kcv.size()) && out->put("\n");
}

bool state_put_header(TextSink* out, std::int64_t writes, std::int32_t telemetry_id,
                      const KeyCheckValue& telemetry_kcv) noexcept {
  return out->put(kStateHeader) && out->put("\nwrites ") && out->put_decimal(writes) &&
         out->put("\ntelemetry ") && out->put_decimal(telemetry_id) && out->put(" ") &&
         out->put_hex(telemetry_kcv.data(), telemetry_kcv.size()) && out->put("\n");
}

// The MAC line over everything written so far.
bool state_put_mac(TextSink* out, const KeyBytes& mac_key) noexcept {
  const Mac mac = hmac_sha256(mac_key.data(), mac_key.size(),
                              reinterpret_cast<const std::uint8_t*>(out->buf), out->n);
  return out->put("mac ") && out->put_hex(mac.data(), mac.size()) && out->put("\n");
}

}  // namespace evade::auth::detail
