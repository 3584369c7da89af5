// CDM XML reader and writer (include/evade/ccsds/cdm_xml.hpp).
#include "evade/ccsds/cdm_xml.hpp"

#include <cctype>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

namespace evade::ccsds {
namespace {

struct Node {
  std::string name, text;
  std::map<std::string, std::string> attrs;
  std::vector<Node> children;
  int line = 0;
};

[[noreturn]] void xml_fail(int line, const std::string& key, const std::string& what) {
  throw CdmError("CDM line " + std::to_string(line) + ": keyword '" + key + "': " + what);
}

std::string unescape(const std::string& s, int line) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') { out += s[i]; continue; }
    const auto semi = s.find(';', i);
    if (semi == std::string::npos) xml_fail(line, "&", "unterminated entity");
    const std::string e = s.substr(i + 1, semi - i - 1);
    static const std::map<std::string, char> ents = {
        {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
    const auto f = ents.find(e);
    if (f == ents.end()) xml_fail(line, "&" + e + ";", "unknown entity");
    out += f->second;
    i = semi;
  }
  return out;
}

// Leading and trailing blanks and line ends of XML text.
std::string trim_xml(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

class Parser {
 public:
  explicit Parser(const std::string& t) : t_(t) {}
  Node document() {
    skip_misc();
    Node root = element();
    skip_misc();
    if (p_ < t_.size()) xml_fail(line_, root.name, "text after the root element");
    return root;
  }

 private:
  const std::string& t_;
  std::size_t p_ = 0;
  int line_ = 1;

  void advance(std::size_t n) {
    for (std::size_t i = 0; i < n && p_ < t_.size(); ++i, ++p_)
      if (t_[p_] == '\n') ++line_;
  }
  bool starts(const char* s) const { return t_.compare(p_, std::char_traits<char>::length(s), s) == 0; }
  void skip_to(const char* end) {
    const auto e = t_.find(end, p_);
    if (e == std::string::npos) xml_fail(line_, "XML", std::string("expected '") + end + "'");
    advance(e - p_ + std::char_traits<char>::length(end));
  }
  void skip_ws() {
    while (p_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[p_]))) advance(1);
  }
  void skip_misc() {
    for (;;) {
      skip_ws();
      if (starts("<?")) skip_to("?>");
      else if (starts("<!--")) skip_to("-->");
      else return;
    }
  }
  std::string name() {
    const std::size_t a = p_;
    while (p_ < t_.size() && (std::isalnum(static_cast<unsigned char>(t_[p_])) ||
                              t_[p_] == '_' || t_[p_] == ':' || t_[p_] == '-' || t_[p_] == '.'))
      advance(1);
    if (a == p_) xml_fail(line_, "XML", "expected an element or attribute name");
    return t_.substr(a, p_ - a);
  }
  Node element() {
    if (!starts("<")) xml_fail(line_, "XML", "expected '<'");
    advance(1);
    Node n;
    n.line = line_;
    n.name = name();
    for (;;) {
      skip_ws();
      if (starts("/>")) { advance(2); return n; }
      if (starts(">")) { advance(1); break; }
      const std::string a = name();
      skip_ws();
      if (!starts("=")) xml_fail(line_, n.name, "expected '=' after attribute " + a);
      advance(1);
      skip_ws();
      const char q = p_ < t_.size() ? t_[p_] : '\0';
      if (q != '"' && q != '\'') xml_fail(line_, n.name, "expected a quoted attribute value");
      const auto e = t_.find(q, p_ + 1);
      if (e == std::string::npos) xml_fail(line_, n.name, "unterminated attribute value");
      n.attrs[a] = unescape(t_.substr(p_ + 1, e - p_ - 1), line_);
      advance(e - p_ + 1);
    }
    content(n);
    return n;
  }
  void content(Node& n) {
    for (;;) {
      if (p_ >= t_.size()) xml_fail(n.line, n.name, "element not closed");
      if (starts("<!--")) { skip_to("-->"); continue; }
      if (starts("</")) {
        advance(2);
        const std::string c = name();
        if (c != n.name) xml_fail(line_, n.name, "closed by </" + c + ">");
        skip_ws();
        if (!starts(">")) xml_fail(line_, n.name, "expected '>'");
        advance(1);
        n.text = unescape(trim_xml(n.text), n.line);
        return;
      }
      if (starts("<")) { n.children.push_back(element()); continue; }
      n.text += t_[p_];
      advance(1);
    }
  }
};

CdmItem leaf(const Node& n) {
  if (!n.children.empty()) xml_fail(n.line, n.name, "expected a value, found child elements");
  const auto u = n.attrs.find("units");
  return {n.name, n.text, u == n.attrs.end() ? "" : u->second, n.line};
}

void leaves(const Node& n, CdmSection& s) {
  for (const Node& c : n.children) s.items.push_back(leaf(c));
}

void read_segment(const Node& seg, CdmObject& o) {
  for (const Node& part : seg.children) {
    if (part.name == "metadata") {
      leaves(part, o.metadata);
    } else if (part.name == "data") {
      for (const Node& d : part.children) {
        if (d.name == "COMMENT") o.state_vector.items.insert(o.state_vector.items.begin(), leaf(d));
        else if (d.name == "odParameters") leaves(d, o.od_parameters);
        else if (d.name == "additionalParameters") leaves(d, o.additional_parameters);
        else if (d.name == "stateVector") leaves(d, o.state_vector);
        else if (d.name == "covarianceMatrix") leaves(d, o.covariance);
        else xml_fail(d.line, d.name, "not an element of <data>");
      }
    } else {
      xml_fail(part.line, part.name, "expected <metadata> or <data>");
    }
  }
}

void read_body(const Node& body, Cdm& cdm) {
  int segments = 0;
  for (const Node& b : body.children) {
    if (b.name == "relativeMetadataData") {
      for (const Node& r : b.children) {
        if (r.name == "relativeStateVector") leaves(r, cdm.relative);
        else cdm.relative.items.push_back(leaf(r));
      }
    } else if (b.name == "segment") {
      if (segments == 2) xml_fail(b.line, "segment", "a CDM has exactly two segments");
      read_segment(b, cdm.object[segments++]);
    } else {
      xml_fail(b.line, b.name, "expected <relativeMetadataData> or <segment>");
    }
  }
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

void write_items(std::ostringstream& os, const CdmSection& s, const std::string& indent) {
  bool in_rel = false;
  for (const CdmItem& it : s.items) {
    const bool rel = it.key.rfind("RELATIVE_POSITION_", 0) == 0 ||
                     it.key.rfind("RELATIVE_VELOCITY_", 0) == 0;
    if (rel && !in_rel) os << indent << "<relativeStateVector>\n";
    if (!rel && in_rel) os << indent << "</relativeStateVector>\n";
    in_rel = rel;
    os << indent << (rel ? "  " : "") << "<" << it.key;
    if (!it.unit.empty()) os << " units=\"" << escape(it.unit) << "\"";
    os << ">" << escape(it.value) << "</" << it.key << ">\n";
  }
  if (in_rel) os << indent << "</relativeStateVector>\n";
}

void write_block(std::ostringstream& os, const char* tag, const CdmSection& s,
                 const std::string& indent) {
  if (s.items.empty()) return;
  os << indent << "<" << tag << ">\n";
  write_items(os, s, indent + "  ");
  os << indent << "</" << tag << ">\n";
}

}  // namespace

Cdm read_cdm_xml(const std::string& raw_text) {
  const std::string text = cdm_text_as_utf8(raw_text);
  const Node root = Parser(text).document();
  if (root.name != "cdm") xml_fail(root.line, root.name, "expected the root element <cdm>");
  const auto v = root.attrs.find("version");
  if (v == root.attrs.end()) xml_fail(root.line, "CCSDS_CDM_VERS", "<cdm version=\"..\"> missing");
  Cdm cdm;
  cdm.header.items.push_back({"CCSDS_CDM_VERS", v->second, "", root.line});
  for (const Node& c : root.children) {
    if (c.name == "header") leaves(c, cdm.header);
    else if (c.name == "body") read_body(c, cdm);
    else xml_fail(c.line, c.name, "expected <header> or <body>");
  }
  validate_cdm(cdm);
  return cdm;
}

std::string write_cdm_xml(const Cdm& cdm) {
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<cdm xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
        "xsi:noNamespaceSchemaLocation=\"http://sanaregistry.org/r/ndmxml/ndmxml-1.0-master.xsd\" "
        "id=\"CCSDS_CDM_VERS\" version=\""
     << escape(cdm_value(cdm.header, "CCSDS_CDM_VERS")) << "\">\n";
  CdmSection header;
  for (const auto& it : cdm.header.items)
    if (it.key != "CCSDS_CDM_VERS") header.items.push_back(it);
  write_block(os, "header", header, "  ");
  os << "  <body>\n";
  write_block(os, "relativeMetadataData", cdm.relative, "    ");
  for (const CdmObject& o : cdm.object) {
    os << "    <segment>\n";
    write_block(os, "metadata", o.metadata, "      ");
    os << "      <data>\n";
    write_block(os, "odParameters", o.od_parameters, "        ");
    write_block(os, "additionalParameters", o.additional_parameters, "        ");
    write_block(os, "stateVector", o.state_vector, "        ");
    write_block(os, "covarianceMatrix", o.covariance, "        ");
    os << "      </data>\n    </segment>\n";
  }
  os << "  </body>\n</cdm>\n";
  return os.str();
}

}  // namespace evade::ccsds
