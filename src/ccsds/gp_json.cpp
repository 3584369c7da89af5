// JSON "GP" element sets: the OMM keywords of CCSDS 502.0-B-2 as the keys of JSON objects
// (RFC 8259), one object per element set, as catalogue providers publish them.
#include "evade/ccsds/gp_json.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <vector>

#include "evade/ccsds/omm_record.hpp"

namespace evade::ccsds {

using sgp4::Catalog;
using sgp4::ReadIssue;
namespace {

struct Pos {
  int line = 1, column = 1;
};

Pos position_of(const std::string& text, std::size_t offset) {
  Pos p;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') ++p.line, p.column = 1;
    else ++p.column;
  }
  return p;
}

// Offsets of the '{' of each object at depth 1 of a top-level array (or of the root object).
std::vector<std::size_t> object_offsets(const std::string& text) {
  std::vector<std::size_t> out;
  int depth = 0;
  bool in_string = false, escape = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escape) escape = false;
      else if (c == '\\') escape = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '{' || c == '[') {
      if (c == '{' && (depth == 1 || (depth == 0 && out.empty()))) out.push_back(i);
      ++depth;
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return out;
}

}  // namespace

namespace {

// The issue of a number the parser refuses although the text is well formed: a number beyond
// double (out_of_range.406, "number overflow parsing '1e999'"; found by fuzzing,
// docs/ASSURANCE.md). The message quotes the number; its first occurrence in the text gives
// the line and column.
ReadIssue overflow_issue(const std::string& text, const std::string& source,
                         const std::string& what) {
  const std::size_t q0 = what.find('\'');
  const std::size_t q1 = what.rfind('\'');
  const std::string token = q0 < q1 ? what.substr(q0 + 1, q1 - q0 - 1) : std::string();
  const std::size_t at = token.empty() ? std::string::npos : text.find(token);
  const Pos p = position_of(text, at == std::string::npos ? 0 : at);
  return {source, p.line, p.column, "numbers within the range of a double (" + what + ")",
          token.empty() ? text.substr(0, 12) : token.substr(0, 24)};
}

// One JSON element set (found at text position p) into cat.
void add_gp_object(const nlohmann::json& o, const Pos& p, const std::string& source,
                   Catalog& cat) {
  if (!o.is_object()) {
    cat.issues.push_back({source, p.line, p.column, "a JSON object per element set", o.dump().substr(0, 20)});
    ++cat.bad_entries;
    return;
  }
  OmmRecord rec;
  rec.line = p.line;
  for (const auto& [key, v] : o.items()) {
    if (!is_omm_keyword(key) || v.is_null()) continue;
    const std::string t = v.is_string() ? v.get<std::string>() : v.dump();
    rec.values[key] = OmmValue{t, p.line, p.column};
  }
  add_omm_record(rec, source, &cat);
}

}  // namespace

Catalog read_gp_json(const std::string& text, const std::string& source) {
  Catalog cat;
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    const std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
    const Pos p = position_of(text, at);
    cat.issues.push_back({source, p.line, p.column, "well-formed JSON (" + std::string(e.what()) + ")",
                          text.substr(std::min(at, text.size()), 12)});
    ++cat.bad_entries;
    return cat;
  } catch (const nlohmann::json::exception& e) {
    cat.issues.push_back(overflow_issue(text, source, e.what()));
    ++cat.bad_entries;
    return cat;
  }
  const std::vector<std::size_t> offsets = object_offsets(text);
  const nlohmann::json items = doc.is_array() ? doc : nlohmann::json::array({doc});
  for (std::size_t k = 0; k < items.size(); ++k) {
    add_gp_object(items[k], position_of(text, k < offsets.size() ? offsets[k] : 0), source, cat);
  }
  return cat;
}

}  // namespace evade::ccsds
