// CCSDS OMM, KVN form: CCSDS 502.0-B-2 "Orbit Data Messages", sections 4 (OMM content) and
// 7 (KVN syntax: one keyword per line, '=' separator, optional [unit], COMMENT lines).
#include "evade/ccsds/omm_kvn.hpp"

#include <sstream>

#include "evade/sgp4/text_fields.hpp"
#include "evade/ccsds/omm_record.hpp"

namespace evade::ccsds {

using sgp4::Catalog;
using sgp4::ReadError;
using sgp4::ReadIssue;
using sgp4::trim;
namespace {

struct KvnState {
  OmmRecord rec;
  bool open = false;
  bool bad = false;  // the current message already failed: skip to the next header
};

void finish(KvnState& st, Catalog& cat, const std::string& source) {
  if (st.open && !st.bad) {
    try {
      cat.objects.push_back(mean_elements_from_omm(st.rec, source));
    } catch (const ReadError& e) {
      cat.issues.push_back(e.issue);
      ++cat.bad_entries;
    }
  }
  st = KvnState{};
}

void reject(KvnState& st, Catalog& cat, ReadIssue issue) {
  if (!st.bad) {
    cat.issues.push_back(std::move(issue));
    ++cat.bad_entries;
  }
  st.bad = true;
  st.open = true;
}

}  // namespace

Catalog read_omm_kvn(const std::string& text, const std::string& source) {
  Catalog cat;
  KvnState st;
  std::istringstream in(text);
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    const std::string t = trim(line);
    if (t.empty() || t.rfind("COMMENT", 0) == 0) continue;
    const std::size_t eq = line.find('=');
    const std::size_t first = line.find_first_not_of(" \t");
    if (eq == std::string::npos) {
      reject(st, cat, {source, no, static_cast<int>(first) + 1, "KEYWORD = value", t});
      continue;
    }
    const std::string key = trim(line.substr(0, eq));
    std::string value = line.substr(eq + 1);
    const std::size_t vstart = value.find_first_not_of(" \t");
    const std::size_t vcol = eq + 2 + (vstart == std::string::npos ? 0 : vstart);
    const std::size_t bracket = value.find('[');
    if (bracket != std::string::npos) value.resize(bracket);  // "[rev/day]"
    value = trim(value);
    if (key == "CCSDS_OMM_VERS") {
      finish(st, cat, source);
      st.open = true;
      st.rec.line = no;
    }
    if (!st.open) {
      reject(st, cat, {source, no, static_cast<int>(first) + 1, "CCSDS_OMM_VERS = 2.0 (or 3.0) opening the message", key});
      continue;
    }
    if (st.bad) continue;
    if (!is_omm_keyword(key)) {
      reject(st, cat, {source, no, static_cast<int>(first) + 1, "an OMM keyword", key});
    } else if (st.rec.values.count(key)) {
      reject(st, cat, {source, no, static_cast<int>(first) + 1, "each keyword once per message (" + key + " repeated)", key});
    } else {
      st.rec.values[key] = OmmValue{value, no, static_cast<int>(vcol)};
    }
  }
  finish(st, cat, source);
  return cat;
}

}  // namespace evade::ccsds
