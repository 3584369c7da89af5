// Scenario YAML reading with typed, range-checked accessors (see the header).
#include "evade/config/scenario.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

#include <yaml-cpp/yaml.h>

#include "scenario_text.hpp"

namespace evade::config {
namespace {

using detail::join;

using nlohmann::json;

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : key) {
    if (c == '.') {
      parts.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  parts.push_back(cur);
  return parts;
}

bool is_index(const std::string& s) {
  return !s.empty() && s.size() < 9 && std::all_of(s.begin(), s.end(), [](char c) {
    return c >= '0' && c <= '9';
  });
}

std::string first_bad_byte(const std::string& text);

// A scalar as yaml-cpp decoded it (escapes, encodings) must be text too: checked again, the
// error placed at the scalar in the source.
const std::string& scalar_text(const YAML::Node& n, const std::string& where) {
  const std::string bad = first_bad_byte(n.Scalar());
  if (!bad.empty()) {
    const YAML::Mark m = n.Mark();
    throw ConfigError(where + ": line " + std::to_string(m.line + 1) + ", column " +
                      std::to_string(m.column + 1) + ": the scalar, decoded, is not text (its " +
                      bad + ")");
  }
  return n.Scalar();
}

ConfigError duplicate_key_error(const std::string& where, const std::string& key) {
  return ConfigError(where + ": duplicate key '" + key + "'");
}

// YAML -> JSON, keeping every scalar as text so the typed getters do the only parsing.
json to_json(const YAML::Node& n, const std::string& where) {
  switch (n.Type()) {
    case YAML::NodeType::Null:
      return json();
    case YAML::NodeType::Scalar:
      return json(scalar_text(n, where));
    case YAML::NodeType::Sequence: {
      json a = json::array();
      for (std::size_t i = 0; i < n.size(); ++i) a.push_back(to_json(n[i], where));
      return a;
    }
    case YAML::NodeType::Map: {
      json o = json::object();
      for (const auto& kv : n) {
        const std::string k = kv.first.IsScalar() ? scalar_text(kv.first, where)
                                                  : kv.first.as<std::string>();
        if (o.contains(k)) throw duplicate_key_error(where, k);
        o[k] = to_json(kv.second, where);
      }
      return o;
    }
    default:
      return json();
  }
}

bool file_exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}


void collect_leaves(const json& n, const std::string& prefix, std::vector<std::string>& out) {
  if (n.is_object()) {
    for (auto it = n.begin(); it != n.end(); ++it)
      collect_leaves(it.value(), prefix.empty() ? it.key() : prefix + "." + it.key(), out);
  } else if (n.is_array() && std::any_of(n.begin(), n.end(), [](const json& e) {
               return e.is_object() || e.is_array();
             })) {
    for (std::size_t i = 0; i < n.size(); ++i)
      collect_leaves(n[i], prefix + "." + std::to_string(i), out);
  } else {
    out.push_back(prefix);
  }
}

// Lead bytes of well-formed UTF-8 (RFC 3629 sec. 4, Unicode table 3-7: no overlong forms,
// no surrogates, nothing above U+10FFFF): range, sequence length, range of the second byte.
struct Utf8Lead {
  unsigned char first, last;
  std::size_t length;
  unsigned char lo, hi;
};
constexpr Utf8Lead kUtf8Leads[] = {
    {0xC2, 0xDF, 2, 0x80, 0xBF}, {0xE0, 0xE0, 3, 0xA0, 0xBF}, {0xE1, 0xEC, 3, 0x80, 0xBF},
    {0xED, 0xED, 3, 0x80, 0x9F}, {0xEE, 0xEF, 3, 0x80, 0xBF}, {0xF0, 0xF0, 4, 0x90, 0xBF},
    {0xF1, 0xF3, 4, 0x80, 0xBF}, {0xF4, 0xF4, 4, 0x80, 0x8F}};

// Length of the well-formed UTF-8 sequence at s[i], or 0 when it is not one.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  if (b(i) < 0x80) return 1;
  for (const Utf8Lead& l : kUtf8Leads) {
    if (b(i) < l.first || b(i) > l.last) continue;
    if (i + l.length > s.size() || b(i + 1) < l.lo || b(i + 1) > l.hi) return 0;
    for (std::size_t k = 2; k < l.length; ++k)
      if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
    return l.length;
  }
  return 0;
}

// A control byte that YAML 1.2 sec. 5.1 does not allow in a stream (c-printable admits tab,
// LF and CR only). NUL among them matters beyond the standard: yaml-cpp takes a stream that
// starts with 01 00 00 00 for UTF-32 and decodes it to code points beyond U+10FFFF.
bool is_control_byte(unsigned char c) { return (c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F; }

// The first byte of text that is not UTF-8 (YAML 1.2 sec. 5.2) or is a control character,
// as "line L, column C: what (byte 0xNN)"; empty when the text is clean.
std::string first_bad_byte(const std::string& text) {
  int line = 1, col = 1;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(text, i);
    const auto c = static_cast<unsigned char>(text[i]);
    if (n == 0 || is_control_byte(c)) {
      char byte[8];
      // "0xHH" always fits: the count snprintf returns is not needed.
      (void)std::snprintf(byte, sizeof byte, "0x%02X", c);
      return "line " + std::to_string(line) + ", column " + std::to_string(col) +
             (n == 0 ? ": not UTF-8 text (byte " : ": a control character (byte ") + byte + ")";
    }
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
    i += n;
  }
  return {};
}

// Scenario text is UTF-8 of YAML's printable characters; anything else is refused here,
// naming the line, the column and the byte, before it can reach a key, a value or a JSON
// result (JSON output cannot carry it). Found by fuzzing (docs/ASSURANCE.md, findings 3, 9).
void require_yaml_text(const std::string& text, const std::string& where) {
  const std::string bad = first_bad_byte(text);
  if (!bad.empty()) throw ConfigError(where + ": " + bad);
}

// The folder of the running executable (/proc/self/exe), "" when it cannot be read.
std::string executable_dir() {
  char buf[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n <= 0) return std::string();
  buf[n] = '\0';
  std::string p(buf);
  const std::size_t slash = p.rfind('/');
  return slash == std::string::npos ? std::string() : p.substr(0, slash);
}

}  // namespace

std::vector<std::string> scenario_search_dirs() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("EVADE_SCENARIO_DIR"); env && *env) dirs.emplace_back(env);
  // An installed executable (<prefix>/bin/evade) finds <prefix>/share/evade/scenarios, wherever
  // the prefix was moved after the build; a build-tree executable has no such folder beside it.
  const std::string exe_dir = executable_dir();
  if (!exe_dir.empty()) {
    const std::string installed = exe_dir + "/../" + EVADE_INSTALL_SCENARIO_REL_DIR;
    struct stat st {};
    if (::stat(installed.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) dirs.push_back(installed);
  }
#ifdef EVADE_SOURCE_SCENARIO_DIR
  dirs.emplace_back(EVADE_SOURCE_SCENARIO_DIR);
#endif
  return dirs;
}

Scenario::Scenario(json tree, std::string source) : tree_(std::move(tree)), source_(std::move(source)) {
  if (tree_.is_null()) tree_ = json::object();
  if (!tree_.is_object()) throw ConfigError(source_ + ": the top level must be a mapping of keys");
}

Scenario Scenario::empty(const std::string& source_name) { return Scenario(json::object(), source_name); }

Scenario Scenario::from_yaml_string(const std::string& yaml, const std::string& source_name) {
  require_yaml_text(yaml, source_name);
  try {
    return Scenario(to_json(YAML::Load(yaml), source_name), source_name);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source_name + ": YAML syntax error: " + e.what());
  }
}

Scenario Scenario::load(const std::string& name_or_path) {
  std::string path;
  const bool is_path = name_or_path.find('/') != std::string::npos ||
                       (name_or_path.size() > 5 && (name_or_path.rfind(".yaml") == name_or_path.size() - 5)) ||
                       (name_or_path.size() > 4 && (name_or_path.rfind(".yml") == name_or_path.size() - 4));
  if (is_path) {
    path = name_or_path;
    if (!file_exists(path)) throw ConfigError("scenario file '" + path + "' not found");
  } else {
    const auto dirs = scenario_search_dirs();
    const std::string file_name = "/" + name_or_path + ".yaml";
    for (const auto& d : dirs) {
      if (file_exists(d + file_name)) {
        path = d + file_name;
        break;
      }
    }
    if (path.empty())
      throw ConfigError("scenario '" + name_or_path + "' not found (searched: " + join(dirs, ", ") +
                        "); give a shipped name or a path to a .yaml file");
  }
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  Scenario s = from_yaml_string(ss.str(), is_path ? path : name_or_path);
  return s;
}

void Scenario::apply_override(const std::string& assignment) {
  require_yaml_text(assignment, "--set");
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ConfigError("--set '" + assignment + "': expected key.path=value");
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  json value;
  try {
    value = to_json(YAML::Load(text), "--set " + key);
  } catch (const YAML::Exception& e) {
    throw ConfigError("--set " + key + ": cannot parse value '" + text + "': " + e.what());
  }
  if (value.is_null()) value = json(text);
  json* cur = &tree_;
  const auto parts = split_key(key);
  const auto component_error = [&key](const std::string& p, const std::string& what) {
    return ConfigError("--set " + key + ": '" + p + "' " + what);
  };
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& p = parts[i];
    if (p.empty()) throw ConfigError("--set '" + assignment + "': empty key component");
    const bool last = i + 1 == parts.size();
    if (cur->is_array()) {
      if (!is_index(p) || std::stoul(p) >= cur->size())
        throw component_error(p, "is not an index of a list of " + std::to_string(cur->size()));
      cur = &(*cur)[std::stoul(p)];
    } else {
      if (!cur->is_object()) {
        if (!cur->is_null()) throw component_error(p, "is below a value, not a mapping");
        *cur = json::object();
      }
      cur = &(*cur)[p];
    }
    if (last) *cur = value;
  }
}

const nlohmann::json* Scenario::find(const std::string& key) const {
  const json* cur = &tree_;
  for (const auto& p : split_key(key)) {
    if (cur->is_object()) {
      auto it = cur->find(p);
      if (it == cur->end()) return nullptr;
      cur = &*it;
    } else if (cur->is_array() && is_index(p)) {
      const auto idx = std::stoul(p);
      if (idx >= cur->size()) return nullptr;
      cur = &(*cur)[idx];
    } else {
      return nullptr;
    }
  }
  return cur->is_null() ? nullptr : cur;
}

void Scenario::fail(const std::string& key, const std::string& value, const std::string& allowed) const {
  throw ConfigError(source_ + ": key '" + key + "' = '" + value + "' is invalid: expected " + allowed);
}

std::string Scenario::scalar_text(const std::string& key, const json& node) const {
  if (!node.is_string()) fail(key, node.dump(), "a single value, not a list or mapping");
  return node.get<std::string>();
}

void Scenario::record(const std::string& key, const json& value) const {
  mark_used(key);
  json* cur = &used_;
  const auto parts = split_key(key);
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) cur = &(*cur)[parts[i]];
  (*cur)[parts.back()] = value;
}

void Scenario::mark_used(const std::string& key) const {
  if (std::find(used_keys_.begin(), used_keys_.end(), key) == used_keys_.end())
    used_keys_.push_back(key);
}

bool Scenario::has(const std::string& key) const { return typed(key) != nullptr || find(key) != nullptr; }

std::size_t Scenario::list_size(const std::string& key) const {
  const json* n = find(key);
  if (!n) return 0;
  if (!n->is_array()) fail(key, n->dump(), "a list");
  return n->size();
}

namespace {

// True when leaf is key or lies below it (a list read whole marks its elements used).
bool covered_by(const std::string& leaf, const std::string& key) {
  return leaf == key || (leaf.size() > key.size() && leaf.compare(0, key.size(), key) == 0 &&
                         leaf[key.size()] == '.');
}

// The keys read below parent ("a.b."), deeper levels folded as "name.…", sorted.
std::vector<std::string> used_siblings(const std::vector<std::string>& used,
                                       const std::string& parent) {
  std::vector<std::string> siblings;
  for (const auto& u : used) {
    if (u.compare(0, parent.size(), parent) != 0) continue;
    std::string rest = u.substr(parent.size());
    const auto d = rest.find('.');
    if (d != std::string::npos) rest.replace(d, std::string::npos, ".…");
    if (std::find(siblings.begin(), siblings.end(), rest) == siblings.end()) siblings.push_back(rest);
  }
  std::sort(siblings.begin(), siblings.end());
  return siblings;
}

}  // namespace

void Scenario::check_all_used() const {
  std::vector<std::string> leaves;
  collect_leaves(tree_, "", leaves);
  for (const ParamValue& t : typed_) leaves.push_back(t.key);  // a typed value nobody read
  std::vector<std::string> unknown;
  for (const auto& leaf : leaves) {
    if (leaf.empty()) continue;
    const bool known = std::any_of(used_keys_.begin(), used_keys_.end(),
                                   [&](const std::string& u) { return covered_by(leaf, u); });
    if (!known && std::find(unknown.begin(), unknown.end(), leaf) == unknown.end()) {
      unknown.push_back(leaf);
    }
  }
  if (unknown.empty()) return;
  // For the first unknown key, list the allowed keys beside it (same parent), so the message
  // stays readable for large scenarios.
  const std::string& first = unknown.front();
  const auto dot = first.rfind('.');
  const std::string parent = dot == std::string::npos ? "" : first.substr(0, dot + 1);
  const std::vector<std::string> siblings = used_siblings(used_keys_, parent);
  throw ConfigError(source_ + ": unknown key" + (unknown.size() > 1 ? "s '" : " '") +
                    join(unknown, "', '") + "' (allowed " +
                    (parent.empty() ? std::string("top-level keys") : "keys under '" + parent.substr(0, parent.size() - 1) + "'") +
                    ": " + (siblings.empty() ? std::string("none") : join(siblings, ", ")) + ")");
}

}  // namespace evade::config
