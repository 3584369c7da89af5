// CDM KVN reader and writer (include/evade/ccsds/cdm_kvn.hpp).
#include "evade/ccsds/cdm_kvn.hpp"

#include <sstream>

namespace evade::ccsds {
namespace {

std::string trim_kvn(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

void insert_comment(CdmSection& s, CdmItem c) {
  auto pos = s.items.begin();
  while (pos != s.items.end() && (pos->key == "COMMENT" || pos->key == "CCSDS_CDM_VERS")) ++pos;
  s.items.insert(pos, std::move(c));
}

struct Reader {
  Cdm cdm;
  int object = -1;
  std::vector<CdmItem> pending;
  CdmSection* last = nullptr;

  CdmSection& target(const CdmItem& it, CdmSectionId id) {
    if (id == CdmSectionId::kHeader || id == CdmSectionId::kRelative) {
      if (object >= 0)
        throw CdmError("CDM line " + std::to_string(it.line) + ": keyword '" + it.key +
                       "': belongs before the first OBJECT");
      return id == CdmSectionId::kHeader ? cdm.header : cdm.relative;
    }
    if (it.key == "OBJECT" && ++object > 1)
      throw CdmError("CDM line " + std::to_string(it.line) +
                     ": keyword 'OBJECT': a CDM has exactly two objects");
    if (object < 0)
      throw CdmError("CDM line " + std::to_string(it.line) + ": keyword '" + it.key +
                     "': expected OBJECT = OBJECT1 before the object's keywords");
    return cdm.object[object].section(id);
  }

  void add(CdmItem it) {
    if (it.key == "COMMENT") {
      pending.push_back(std::move(it));
      return;
    }
    CdmSectionId id;
    if (!cdm_keyword_section(it.key, &id))
      throw CdmError("CDM line " + std::to_string(it.line) + ": keyword '" + it.key +
                     "': not a CDM keyword (CCSDS 508.0-B-1 tables 3-2 to 3-6)");
    CdmSection& s = target(it, id);
    for (auto& c : pending) insert_comment(s, std::move(c));
    pending.clear();
    s.items.push_back(std::move(it));
    last = &s;
  }
};

CdmItem parse_line(const std::string& raw, int line) {
  const std::string t = trim_kvn(raw);
  if (t.rfind("COMMENT", 0) == 0 && (t.size() == 7 || t[7] == ' ' || t[7] == '\t'))
    return {"COMMENT", trim_kvn(t.substr(7)), "", line};
  const auto eq = t.find('=');
  if (eq == std::string::npos)
    throw CdmError("CDM line " + std::to_string(line) + ": keyword '" + t.substr(0, 40) +
                   "': expected KEYWORD = value [unit]");
  CdmItem it{trim_kvn(t.substr(0, eq)), trim_kvn(t.substr(eq + 1)), "", line};
  if (!it.value.empty() && it.value.back() == ']') {
    const auto lb = it.value.rfind('[');
    if (lb == std::string::npos)
      throw CdmError("CDM line " + std::to_string(line) + ": keyword '" + it.key +
                     "': unit without its opening '['");
    it.unit = trim_kvn(it.value.substr(lb + 1, it.value.size() - lb - 2));
    it.value = trim_kvn(it.value.substr(0, lb));
  }
  return it;
}

}  // namespace

Cdm read_cdm_kvn(const std::string& raw_text) {
  const std::string text = cdm_text_as_utf8(raw_text);
  Reader r;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  bool first = true;
  while (std::getline(in, raw)) {
    ++line;
    if (trim_kvn(raw).empty()) continue;
    CdmItem it = parse_line(raw, line);
    if (first && it.key != "CCSDS_CDM_VERS")
      throw CdmError("CDM line " + std::to_string(line) + ": keyword '" + it.key +
                     "': expected CCSDS_CDM_VERS as the first keyword");
    first = false;
    r.add(std::move(it));
  }
  if (first) throw CdmError("CDM line 0: keyword 'CCSDS_CDM_VERS': empty message");
  if (!r.pending.empty() && r.last) {
    for (auto& c : r.pending) r.last->items.push_back(std::move(c));
  }
  validate_cdm(r.cdm);
  return r.cdm;
}

std::string write_cdm_kvn(const Cdm& cdm) {
  std::ostringstream os;
  auto section = [&os](const CdmSection& s) {
    for (const CdmItem& it : s.items) {
      if (it.key == "COMMENT") {
        os << "COMMENT " << it.value << "\n";
        continue;
      }
      std::string key = it.key;
      key.resize(std::max<std::size_t>(key.size(), 34), ' ');
      os << key << " = " << it.value;
      if (!it.unit.empty()) os << " [" << it.unit << "]";
      os << "\n";
    }
  };
  section(cdm.header);
  section(cdm.relative);
  for (const CdmObject& o : cdm.object) {
    for (auto id : {CdmSectionId::kMetadata, CdmSectionId::kOd, CdmSectionId::kAdditional,
                    CdmSectionId::kState, CdmSectionId::kCovariance})
      section(o.section(id));
  }
  return os.str();
}

}  // namespace evade::ccsds
