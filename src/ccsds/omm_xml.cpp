// CCSDS OMM, XML form: CCSDS 505.0-B-1 (NDM/XML), the OMM schema's structure
// omm/header, omm/body/segment/{metadata, data/{meanElements, tleParameters, ...}}, read by a
// small strict recursive-descent XML reader (W3C XML 1.0 subset: elements, attributes,
// character data, comments, processing instructions, the five predefined entities and
// numeric character references below 128).
#include "evade/ccsds/omm_xml.hpp"

#include <cctype>
#include <memory>
#include <vector>

#include "evade/sgp4/text_fields.hpp"
#include "evade/ccsds/omm_record.hpp"

namespace evade::ccsds {

using sgp4::Catalog;
using sgp4::ReadError;
using sgp4::ReadIssue;
using sgp4::trim;
using sgp4::parse_plain_integer;
namespace {

struct XmlNode {
  std::string name;  // local name (namespace prefix removed)
  std::string text;
  int line = 0, column = 0;            // of the '<'
  int text_line = 0, text_column = 0;  // of the first character of the text
  std::vector<std::unique_ptr<XmlNode>> children;
};

class XmlParser {
 public:
  XmlParser(const std::string& s, const std::string& source) : s_(s), source_(source) {}

  std::unique_ptr<XmlNode> document() {
    skip_misc();
    if (!at("<")) fail("an XML element ('<')");
    auto root = element(0);
    skip_misc();
    if (i_ < s_.size()) fail("end of document after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& expected) const {
    const std::string found = i_ < s_.size() ? s_.substr(i_, 12) : "end of file";
    throw ReadError(ReadIssue{source_, line_, col_, expected, found});
  }
  bool at(const char* p) const { return s_.compare(i_, std::char_traits<char>::length(p), p) == 0; }
  void adv(std::size_t n = 1) {
    for (; n > 0 && i_ < s_.size(); --n, ++i_) {
      if (s_[i_] == '\n') ++line_, col_ = 1;
      else ++col_;
    }
  }
  void skip_ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) adv();
  }
  void skip_until(const char* end, const std::string& what) {
    const std::size_t e = s_.find(end, i_);
    if (e == std::string::npos) fail(what);
    adv(e - i_ + std::char_traits<char>::length(end));
  }
  void skip_misc() {
    for (;;) {
      skip_ws();
      if (at("<?")) skip_until("?>", "'?>' closing the processing instruction");
      else if (at("<!--")) skip_until("-->", "'-->' closing the comment");
      else if (at("<!")) fail("no DTD or CDATA section (not part of the OMM subset)");
      else return;
    }
  }
  std::string name() {
    const std::size_t b = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == ':' ||
                              s_[i_] == '-' || s_[i_] == '.'))
      adv();
    if (i_ == b || std::isdigit(static_cast<unsigned char>(s_[b]))) fail("an XML name");
    return s_.substr(b, i_ - b);
  }
  static std::string local(const std::string& n) {
    const std::size_t c = n.find(':');
    return c == std::string::npos ? n : n.substr(c + 1);
  }
  std::string entity() {
    static const std::pair<const char*, char> kEnt[] = {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'},
                                                         {"&quot;", '"'}, {"&apos;", '\''}};
    for (const auto& [e, c] : kEnt)
      if (at(e)) {
        adv(std::char_traits<char>::length(e));
        return std::string(1, c);
      }
    if (at("&#")) {
      const std::size_t semi = s_.find(';', i_);
      long v = 0;
      if (semi != std::string::npos && parse_plain_integer(s_.substr(i_ + 2, semi - i_ - 2), v) && v > 8 && v < 128) {
        adv(semi - i_ + 1);
        return std::string(1, static_cast<char>(v));
      }
    }
    fail("one of &amp; &lt; &gt; &quot; &apos; or a character reference below 128");
  }
  void attributes() {
    for (;;) {
      skip_ws();
      if (at("/>") || at(">")) return;
      name();
      skip_ws();
      if (!at("=")) fail("'=' after the attribute name");
      adv();
      skip_ws();
      if (!at("\"") && !at("'")) fail("a quoted attribute value");
      const char q = s_[i_];
      adv();
      while (i_ < s_.size() && s_[i_] != q) {
        if (s_[i_] == '<') fail("no '<' inside an attribute value");
        if (s_[i_] == '&') entity();
        else adv();
      }
      if (i_ >= s_.size()) fail("the closing quote of the attribute value");
      adv();
    }
  }
  std::unique_ptr<XmlNode> element(int depth) {
    if (depth > 32) fail("at most 32 nested elements");
    auto n = std::make_unique<XmlNode>();
    n->line = line_;
    n->column = col_;
    adv();  // '<'
    const std::string qname = name();
    n->name = local(qname);
    attributes();
    if (at("/>")) {
      adv(2);
      return n;
    }
    adv();  // '>'
    content(*n, depth);
    if (!at("</")) fail("'</" + qname + ">'");
    adv(2);
    if (name() != qname) fail("'</" + qname + ">' closing the element opened at line " + std::to_string(n->line));
    skip_ws();
    if (!at(">")) fail("'>'");
    adv();
    return n;
  }
  void content(XmlNode& n, int depth) {
    for (;;) {
      if (i_ >= s_.size()) fail("'</" + n.name + ">' before the end of the file");
      if (at("</")) return;
      if (at("<!--")) skip_until("-->", "'-->' closing the comment");
      else if (at("<?")) skip_until("?>", "'?>' closing the processing instruction");
      else if (at("<!")) fail("no DTD or CDATA section (not part of the OMM subset)");
      else if (at("<")) n.children.push_back(element(depth + 1));
      else {
        if (n.text_line == 0 && !std::isspace(static_cast<unsigned char>(s_[i_]))) n.text_line = line_, n.text_column = col_;
        if (s_[i_] == '&') n.text += entity();
        else n.text += s_[i_], adv();
      }
    }
  }

  const std::string& s_;
  const std::string& source_;
  std::size_t i_ = 0;
  int line_ = 1, col_ = 1;
};

// Collects the leaf elements under a segment as OMM keywords.
void collect(const XmlNode& n, OmmRecord& rec, const std::string& source) {
  for (const auto& c : n.children) {
    if (!c->children.empty()) {
      collect(*c, rec, source);
      continue;
    }
    if (c->name == "COMMENT") continue;
    if (!is_omm_keyword(c->name)) throw ReadError(ReadIssue{source, c->line, c->column, "an OMM keyword element", c->name});
    if (rec.values.count(c->name))
      throw ReadError(ReadIssue{source, c->line, c->column, "each keyword once per segment", c->name});
    const int l = c->text_line ? c->text_line : c->line, col = c->text_line ? c->text_column : c->column;
    rec.values[c->name] = OmmValue{trim(c->text), l, col};
  }
}

void segments(const XmlNode& n, std::vector<const XmlNode*>& out) {
  if (n.name == "segment") {
    out.push_back(&n);
    return;
  }
  for (const auto& c : n.children) segments(*c, out);
}

}  // namespace

Catalog read_omm_xml(const std::string& text, const std::string& source) {
  Catalog cat;
  std::unique_ptr<XmlNode> root;
  try {
    root = XmlParser(text, source).document();
  } catch (const ReadError& e) {
    cat.issues.push_back(e.issue);
    ++cat.bad_entries;
    return cat;
  }
  std::vector<const XmlNode*> segs;
  segments(*root, segs);
  if (segs.empty() || (root->name != "ndm" && root->name != "omm")) {
    cat.issues.push_back(
        {source, root->line, root->column, "an <omm> (or <ndm>) document with at least one <segment>", root->name});
    ++cat.bad_entries;
  }
  for (const XmlNode* seg : segs) {
    OmmRecord rec;
    rec.line = seg->line;
    try {
      collect(*seg, rec, source);
    } catch (const ReadError& e) {
      cat.issues.push_back(e.issue);
      ++cat.bad_entries;
      continue;
    }
    add_omm_record(rec, source, &cat);
  }
  return cat;
}

}  // namespace evade::ccsds
