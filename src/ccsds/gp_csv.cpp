// CSV "GP" element sets: a header of OMM keywords (CCSDS 502.0-B-2) and one row per element
// set, split by the RFC 4180 rules (comma separator, double quotes, "" inside quotes).
#include "evade/ccsds/gp_csv.hpp"

#include <sstream>
#include <vector>

#include "evade/sgp4/text_fields.hpp"
#include "evade/ccsds/omm_record.hpp"

namespace evade::ccsds {

using sgp4::Catalog;
using sgp4::trim;
namespace {

struct Cell {
  std::string text;
  int column = 1;
};

// Splits one line; false when a quote is not closed.
bool split_csv(const std::string& line, std::vector<Cell>& out) {
  out.clear();
  Cell cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cur.text += '"', ++i;
      else if (c == '"') quoted = false;
      else cur.text += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(cur);
      cur = Cell{"", static_cast<int>(i) + 2};
    } else if (c != '\r') {
      cur.text += c;
    }
  }
  out.push_back(cur);
  return !quoted;
}

}  // namespace

Catalog read_gp_csv(const std::string& text, const std::string& source) {
  Catalog cat;
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  std::vector<Cell> cells;
  for (int no = 1; std::getline(in, line); ++no) {
    if (trim(line).empty()) continue;
    if (!split_csv(line, cells)) {
      cat.issues.push_back({source, no, static_cast<int>(line.size()), "a closing double quote", line.substr(0, 20)});
      ++cat.bad_entries;
      continue;
    }
    if (header.empty()) {
      for (const Cell& c : cells) header.push_back(trim(c.text));
      continue;
    }
    if (cells.size() != header.size()) {
      cat.issues.push_back({source, no, 1, std::to_string(header.size()) + " fields as in the header",
                            std::to_string(cells.size()) + " fields"});
      ++cat.bad_entries;
      continue;
    }
    OmmRecord rec;
    rec.line = no;
    for (std::size_t k = 0; k < cells.size(); ++k)
      if (is_omm_keyword(header[k]) && !trim(cells[k].text).empty())
        rec.values[header[k]] = OmmValue{cells[k].text, no, cells[k].column};
    add_omm_record(rec, source, &cat);
  }
  return cat;
}

}  // namespace evade::ccsds
