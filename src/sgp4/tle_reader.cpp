// Two-line element sets: the fixed-column format of the NORAD two-line element definition
// (Hoots & Roehrich 1980, STR#3 appendix; Vallado et al. 2006, AIAA 2006-6753, sec. on the
// TLE format and the Alpha-5 extension of the catalog number). Every field is checked for
// its column range, its characters and its physical range; the checksum is the modulo-10
// sum of the digits, counting 1 for each '-', over columns 1-68.
#include "evade/sgp4/tle_reader.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "evade/sgp4/text_fields.hpp"

namespace evade::sgp4 {
namespace {

// One TLE line with 1-based column access and errors that name the column.
class TleLine {
 public:
  TleLine(const std::string& text, const std::string& source, int line_no)
      : s_(text), source_(source), line_no_(line_no) {}

  std::string cols(int first, int last) const {
    std::string out;
    for (int c = first; c <= last; ++c) {
      const std::size_t i = static_cast<std::size_t>(c - 1);
      out += i < s_.size() ? s_[i] : ' ';
    }
    return out;
  }
  [[noreturn]] void fail(int col, const std::string& expected, const std::string& found) const {
    throw ReadError(ReadIssue{source_, line_no_, col, expected, found});
  }
  void expect_blank(int col) const {
    if (cols(col, col) != " ") fail(col, "a blank in column " + std::to_string(col), cols(col, col));
  }
  double number(int first, int last, const std::string& what, double lo, double hi) const {
    const std::string f = cols(first, last);
    double v = 0.0;
    if (!parse_plain_decimal(f, v) || !(v >= lo && v <= hi)) fail(first, what, trim(f));
    return v;
  }
  // "±nnnnn±e": an implied leading decimal point and a power of ten (columns first..first+7).
  double implied(int first, const std::string& what) const {
    const std::string f = cols(first, first + 7);
    const char sign = f[0];
    const std::string mant = f.substr(1, 5), exps = f.substr(6, 1), expd = f.substr(7, 1);
    bool ok = (sign == ' ' || sign == '+' || sign == '-') && (exps == "+" || exps == "-" || exps == " ") &&
              std::isdigit(static_cast<unsigned char>(expd[0]));
    for (char c : mant) ok = ok && (std::isdigit(static_cast<unsigned char>(c)) || c == ' ');
    if (!ok) fail(first, what + " as an implied-decimal field like ' 12345-4'", f);
    std::string digits = mant;
    for (char& c : digits) if (c == ' ') c = '0';
    // strtod as atof is defined (C11 7.22.1.2); the digits are checked above.
    const double m = std::strtod(("0." + digits).c_str(), nullptr) * (sign == '-' ? -1.0 : 1.0);
    const int e = (expd[0] - '0') * (exps == "-" ? -1 : 1);
    return m * std::pow(10.0, e);
  }
  int digits_or_blank(int first, int last, const std::string& what) const {
    const std::string f = cols(first, last);
    const std::string t = trim(f);
    for (char c : t) if (!std::isdigit(static_cast<unsigned char>(c))) fail(first, what, f);
    return static_cast<int>(digits_value(t));  // a digits-only field of at most 5 columns
  }
  long catalog_number(int first) const {
    const std::string f = cols(first, first + 4);
    long n = 0;
    if (!parse_alpha5(f, n))
      fail(first, "a catalog number (5 digits, or Alpha-5: a letter A-Z but I, O, then 4 digits)", f);
    return n;
  }
  const std::string& text() const { return s_; }
  int line_no() const { return line_no_; }

 private:
  const std::string& s_;
  const std::string& source_;
  int line_no_;
};

void check_frame(const TleLine& l, char first_char, const TleReadOptions& opt) {
  const std::string& s = l.text();
  if (s.empty() || s[0] != first_char) l.fail(1, std::string("line number '") + first_char + "' in column 1", l.cols(1, 1));
  l.expect_blank(2);
  if (s.size() < 69)
    l.fail(static_cast<int>(s.size()) + 1, "a 69-column line", "end of line after column " + std::to_string(s.size()));
  if (!opt.allow_trailing_text && !trim(s.substr(69)).empty()) l.fail(70, "nothing after column 69", s.substr(69));
  if (!opt.check_checksum) return;
  const char c = s[68];
  const int want = tle_checksum(s);
  if (!std::isdigit(static_cast<unsigned char>(c)) || c - '0' != want)
    l.fail(69, "checksum " + std::to_string(want), std::string(1, c));
}

int days_in_year(int y) { return (y % 4 == 0 && (y % 100 != 0 || y % 400 == 0)) ? 366 : 365; }

void read_line1(const TleLine& l, MeanElements& m) {
  m.norad_id = l.catalog_number(3);
  const char cls = l.cols(8, 8)[0];
  if (cls != 'U' && cls != 'C' && cls != 'S' && cls != ' ') l.fail(8, "classification U, C or S", l.cols(8, 8));
  m.classification = cls == ' ' ? 'U' : cls;
  l.expect_blank(9);
  m.object_id = trim(l.cols(10, 17));
  l.expect_blank(18);
  const int yy = l.digits_or_blank(19, 20, "a two-digit epoch year");
  if (trim(l.cols(19, 20)).size() != 2) l.fail(19, "a two-digit epoch year", l.cols(19, 20));
  m.epoch_year = yy < 57 ? 2000 + yy : 1900 + yy;
  const int end_day = days_in_year(m.epoch_year) + 1;
  const std::string day_range = "an epoch day of year in [1, " + std::to_string(end_day) + ")";
  m.epoch_day_of_year = l.number(21, 32, day_range, 1.0, end_day);
  if (m.epoch_day_of_year >= end_day) l.fail(21, day_range, l.cols(21, 32));
  l.expect_blank(33);
  m.mean_motion_dot_revpday2 = l.number(34, 43, "a mean motion derivative / 2 in (-1, 1) rev/day^2", -1.0, 1.0);
  l.expect_blank(44);
  m.mean_motion_ddot_revpday3 = l.implied(45, "a mean motion second derivative / 6");
  l.expect_blank(53);
  m.bstar_per_er = l.implied(54, "a B* drag term");
  l.expect_blank(62);
  m.ephemeris_type = l.digits_or_blank(63, 63, "an ephemeris type digit");
  l.expect_blank(64);
  m.element_set_no = l.digits_or_blank(65, 68, "an element set number (up to 4 digits)");
}

void read_line2(const TleLine& l, MeanElements& m) {
  if (l.catalog_number(3) != m.norad_id)
    l.fail(3, "the catalog number of line 1 (" + std::to_string(m.norad_id) + ")", l.cols(3, 7));
  l.expect_blank(8);
  m.inclination_deg = l.number(9, 16, "an inclination in [0, 180] deg", 0.0, 180.0);
  l.expect_blank(17);
  m.raan_deg = l.number(18, 25, "a right ascension of the node in [0, 360] deg", 0.0, 360.0);
  l.expect_blank(26);
  std::string e = l.cols(27, 33);
  for (char& c : e) if (c == ' ') c = '0';
  for (char c : e)
    if (!std::isdigit(static_cast<unsigned char>(c)))
      l.fail(27, "an eccentricity as 7 digits with an implied leading decimal point", l.cols(27, 33));
  m.eccentricity = std::strtod(("0." + e).c_str(), nullptr);  // atof's definition; digits checked
  l.expect_blank(34);
  m.arg_perigee_deg = l.number(35, 42, "an argument of perigee in [0, 360] deg", 0.0, 360.0);
  l.expect_blank(43);
  m.mean_anomaly_deg = l.number(44, 51, "a mean anomaly in [0, 360] deg", 0.0, 360.0);
  l.expect_blank(52);
  m.mean_motion_revpday = l.number(53, 63, "a mean motion in (0, 20) rev/day", 1e-9, 20.0);
  m.rev_at_epoch = l.digits_or_blank(64, 68, "a revolution number (up to 5 digits)");
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> out;
  std::string line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    out.push_back(line);
  }
  return out;
}

bool starts(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

void reject(Catalog& cat, ReadIssue issue) {
  cat.issues.push_back(std::move(issue));
  ++cat.bad_entries;
}

}  // namespace

int tle_checksum(const std::string& line) noexcept {
  int sum = 0;
  for (std::size_t i = 0; i < 68 && i < line.size(); ++i) {
    const char c = line[i];
    if (c >= '0' && c <= '9') sum += c - '0';
    if (c == '-') sum += 1;
  }
  return sum % 10;
}

MeanElements parse_tle(const std::string& line1, const std::string& line2, const std::string& name,
                       const std::string& source, int line1_no, const TleReadOptions& opt) {
  MeanElements m;
  m.name = name;
  m.source_line = line1_no;
  const TleLine l1(line1, source, line1_no);
  const TleLine l2(line2, source, line1_no + 1);
  check_frame(l1, '1', opt);
  check_frame(l2, '2', opt);
  read_line1(l1, m);
  read_line2(l2, m);
  return m;
}

namespace {

bool blank_or_comment(const std::string& line) { return trim(line).empty() || starts(line, "#"); }

// The element set whose line 1 is lines[i] (its line 2 the next line that is not blank or a
// comment) into cat, or its error as an issue. Returns the index of the line 2 it used (i
// when there is none).
std::size_t read_element_set(const std::vector<std::string>& lines, std::size_t i,
                             const std::string& name, const std::string& source,
                             const TleReadOptions& opt, Catalog& cat) {
  const int no = static_cast<int>(i) + 1;
  std::size_t j = i + 1;
  while (j < lines.size() && blank_or_comment(lines[j])) ++j;
  if (j >= lines.size() || !starts(lines[j], "2 ")) {
    reject(cat, {source, j < lines.size() ? static_cast<int>(j) + 1 : no + 1, 1,
                 "line 2 of the element set begun on line " + std::to_string(no) + " (starting '2 ')",
                 j < lines.size() ? lines[j].substr(0, 20) : "end of file"});
    return i;
  }
  try {
    cat.objects.push_back(parse_tle(lines[i], lines[j], name, source, no, opt));
    if (j != i + 1) cat.objects.back().source_line = no;
  } catch (const ReadError& e) {
    ReadIssue is = e.issue;
    if (is.line == no + 1) is.line = static_cast<int>(j) + 1;
    reject(cat, is);
  }
  return j;
}

}  // namespace

Catalog read_tle(const std::string& text, const std::string& source, const TleReadOptions& opt) {
  Catalog cat;
  const std::vector<std::string> lines = split_lines(text);
  std::string name;
  int name_line = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (blank_or_comment(lines[i])) continue;
    const std::string& l = lines[i];
    const int no = static_cast<int>(i) + 1;
    if (starts(l, "1 ")) {
      i = read_element_set(lines, i, name, source, opt, cat);
      name.clear();
    } else if (starts(l, "2 ")) {
      reject(cat, {source, no, 1, "line 1 of an element set (starting '1 ') before line 2", l.substr(0, 20)});
      name.clear();
    } else {
      if (!name.empty())
        reject(cat, {source, name_line, 1, "an element set (line starting '1 ') after the title line", name});
      const std::string raw = trim(starts(l, "0 ") ? l.substr(2) : l);
      long control = 0;
      const int bad_col = title_to_utf8(raw, &name, &control);
      if (bad_col > 0) {  // the column in the line, past a "0 " and the blanks trim removed
        reject(cat, {source, no, static_cast<int>(l.find(raw)) + bad_col,
                     "a title of printable characters (UTF-8 or Latin-1)", code_point_name(control)});
      }
      name_line = no;
    }
  }
  if (!name.empty()) reject(cat, {source, name_line, 1, "an element set (line starting '1 ') after the title line", name});
  return cat;
}

}  // namespace evade::sgp4
