// Strict scalar parsing for the catalog readers (see internal/text_fields.hpp).
#include "evade/sgp4/text_fields.hpp"

#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace evade::sgp4 {
namespace {

bool all_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

int cumulative_days(int year, int month) {
  static const int kDays[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  const bool leap = year % 4 == 0 && (year % 100 != 0 || year % 400 == 0);
  return kDays[month - 1] + (leap && month > 2 ? 1 : 0);
}

int month_length(int year, int month) {
  static const int kLen[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = year % 4 == 0 && (year % 100 != 0 || year % 400 == 0);
  return kLen[month - 1] + (leap && month == 2 ? 1 : 0);
}

}  // namespace

long digits_value(const std::string& digits) {
  long v = 0;
  for (char c : digits) v = v * 10 + (c - '0');
  return v;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

namespace {

// Advances i past the digits of t from i; returns how many there were.
std::size_t skip_digits(const std::string& t, std::size_t& i) {
  const std::size_t from = i;
  while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i;
  return i - from;
}

// Advances i past one '+' or '-' at i, if there is one.
void skip_sign(const std::string& t, std::size_t& i) {
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
}

}  // namespace

bool parse_plain_decimal(const std::string& field, double& out) {
  const std::string t = trim(field);
  std::size_t i = 0;
  skip_sign(t, i);
  std::size_t digits = skip_digits(t, i);
  if (i < t.size() && t[i] == '.') {
    ++i;
    digits += skip_digits(t, i);
  }
  if (digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    skip_sign(t, i);
    if (skip_digits(t, i) == 0) return false;
  }
  if (i != t.size()) return false;
  out = std::strtod(t.c_str(), nullptr);
  return true;
}

bool parse_plain_integer(const std::string& field, long& out) {
  std::string t = trim(field);
  const bool neg = !t.empty() && t[0] == '-';
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) t = t.substr(1);
  if (!all_digits(t) || t.size() > 12) return false;
  out = digits_value(t) * (neg ? -1 : 1);
  return true;
}

bool parse_alpha5(const std::string& field, long& out) {
  if (field.size() != 5) return false;
  const char c = field[0];
  if (std::isupper(static_cast<unsigned char>(c))) {
    if (c == 'I' || c == 'O' || !all_digits(field.substr(1))) return false;
    int v = c - 'A' + 10;
    if (c > 'I') --v;
    if (c > 'O') --v;
    out = v * 10000L + digits_value(field.substr(1));
    return true;
  }
  const std::string t = trim(field);
  if (!all_digits(t) || field.back() == ' ') return false;
  out = digits_value(t);
  return true;
}

namespace {

// "YYYY-MM-DD" into the year and the day of the year (1 = 1 January).
bool parse_calendar_date(const std::string& date, int& year, int& doy) {
  if (date.size() != 10 || date[4] != '-' || date[7] != '-' || !all_digits(date.substr(0, 4)) ||
      !all_digits(date.substr(5, 2)) || !all_digits(date.substr(8, 2)))
    return false;
  year = static_cast<int>(digits_value(date.substr(0, 4)));
  const auto month = static_cast<int>(digits_value(date.substr(5, 2)));
  const auto day = static_cast<int>(digits_value(date.substr(8, 2)));
  if (month < 1 || month > 12 || day < 1 || day > month_length(year, month)) return false;
  doy = cumulative_days(year, month) + day;
  return true;
}

// "YYYY-DDD" (ordinal date) into the year and the day of the year.
bool parse_ordinal_date(const std::string& date, int& year, int& doy) {
  if (date.size() != 8 || date[4] != '-' || !all_digits(date.substr(0, 4)) ||
      !all_digits(date.substr(5, 3)))
    return false;
  year = static_cast<int>(digits_value(date.substr(0, 4)));
  doy = static_cast<int>(digits_value(date.substr(5, 3)));
  return doy >= 1 && doy <= cumulative_days(year, 12) + 31;
}

// "YYYY-MM-DD" or "YYYY-DDD" into the year and the day of the year (1 = 1 January).
bool parse_iso_date(const std::string& date, int& year, int& doy) {
  return date.size() == 10 ? parse_calendar_date(date, year, doy)
                           : parse_ordinal_date(date, year, doy);
}

// "hh:mm:ss[.fff]" into seconds of the day [s].
bool parse_iso_time(const std::string& time, double& seconds_of_day) {
  if (time.size() < 8 || time[2] != ':' || time[5] != ':' || !all_digits(time.substr(0, 2)) ||
      !all_digits(time.substr(3, 2)))
    return false;
  double sec = 0.0;
  const std::string secs = time.substr(6);
  if (!all_digits(secs.substr(0, 2)) || !parse_plain_decimal(secs, sec) ||
      secs.find_first_of("eE+-") != std::string::npos)
    return false;
  const auto hh = static_cast<int>(digits_value(time.substr(0, 2)));
  const auto mm = static_cast<int>(digits_value(time.substr(3, 2)));
  if (hh > 23 || mm > 59 || !(sec >= 0.0 && sec < 60.0)) return false;
  seconds_of_day = hh * 3600.0 + mm * 60.0 + sec;
  return true;
}

// The code point of the UTF-8 sequence at s[i] (advancing i), or -1 if it is not well-formed
// UTF-8 (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF).
long utf8_code_point(const std::string& s, std::size_t& i) {
  const auto b0 = static_cast<unsigned char>(s[i]);
  int n = 0;
  long cp = 0;
  if (b0 < 0x80) { ++i; return b0; }
  if (b0 >= 0xC2 && b0 <= 0xDF) { n = 1; cp = b0 & 0x1F; }
  else if (b0 >= 0xE0 && b0 <= 0xEF) { n = 2; cp = b0 & 0x0F; }
  else if (b0 >= 0xF0 && b0 <= 0xF4) { n = 3; cp = b0 & 0x07; }
  else return -1;
  if (i + static_cast<std::size_t>(n) >= s.size()) return -1;  // the sequence is cut
  for (int k = 1; k <= n; ++k) {
    const auto b = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
    if ((b & 0xC0) != 0x80) return -1;
    cp = (cp << 6) | (b & 0x3F);
  }
  static const long kMin[] = {0, 0x80, 0x800, 0x10000};
  if (cp < kMin[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return -1;
  i += static_cast<std::size_t>(n) + 1;
  return cp;
}

bool is_control(long cp, const char* allowed) {
  if (cp >= 0x20 && !(cp >= 0x7F && cp <= 0x9F)) return false;
  for (const char* a = allowed; *a != '\0'; ++a) {
    if (cp == static_cast<unsigned char>(*a)) return false;
  }
  return true;
}

bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    if (utf8_code_point(s, i) < 0) return false;
  }
  return true;
}

int refuse(std::string* out, long* control, long cp, std::size_t at) {
  out->clear();
  if (control != nullptr) *control = cp;
  return static_cast<int>(at) + 1;
}

// Appends the code point cp (at most U+10FFFF) to out in UTF-8.
void append_utf8(long cp, std::string* out) {
  const auto byte = [&](long v) { out->push_back(static_cast<char>(v)); };
  if (cp < 0x80) {
    byte(cp);
  } else if (cp < 0x800) {
    byte(0xC0 | (cp >> 6));
    byte(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    byte(0xE0 | (cp >> 12));
    byte(0x80 | ((cp >> 6) & 0x3F));
    byte(0x80 | (cp & 0x3F));
  } else {
    byte(0xF0 | (cp >> 18));
    byte(0x80 | ((cp >> 12) & 0x3F));
    byte(0x80 | ((cp >> 6) & 0x3F));
    byte(0x80 | (cp & 0x3F));
  }
}

}  // namespace

std::string code_point_name(long cp) {
  char b[16];
  (void)std::snprintf(b, sizeof b, "U+%04lX", static_cast<unsigned long>(cp));
  return b;
}

std::string printable_utf8(const std::string& raw) {
  const bool utf8 = valid_utf8(raw);
  std::string out;
  for (std::size_t i = 0; i < raw.size();) {
    const long cp = utf8 ? utf8_code_point(raw, i) : static_cast<unsigned char>(raw[i++]);
    if (is_control(cp, "")) {
      out += "<" + code_point_name(cp) + ">";
    } else {
      append_utf8(cp, &out);
    }
  }
  return out;
}

int text_to_utf8(const std::string& raw, std::string* out, long* control, const char* allowed) {
  out->clear();
  if (valid_utf8(raw)) {
    for (std::size_t i = 0; i < raw.size();) {
      const std::size_t at = i;
      const long cp = utf8_code_point(raw, i);
      if (is_control(cp, allowed)) return refuse(out, control, cp, at);
    }
    *out = raw;
    return 0;
  }
  out->reserve(raw.size() * 2);
  for (std::size_t i = 0; i < raw.size(); ++i) {  // Latin-1: the byte is the code point
    const auto b = static_cast<unsigned char>(raw[i]);
    if (is_control(b, allowed)) return refuse(out, control, b, i);
    append_utf8(b, out);
  }
  return 0;
}

int title_to_utf8(const std::string& raw, std::string* out, long* control) {
  return text_to_utf8(raw, out, control, "");
}

bool parse_iso_epoch(const std::string& text, int& year, double& day_of_year) {
  std::string t = trim(text);
  if (!t.empty() && t.back() == 'Z') t.pop_back();
  const std::size_t tpos = t.find('T');
  if (tpos == std::string::npos) return false;
  int doy = 0;
  double sod = 0.0;
  if (!parse_iso_date(t.substr(0, tpos), year, doy)) return false;
  if (year < 1957 || year > 2099) return false;
  if (!parse_iso_time(t.substr(tpos + 1), sod)) return false;
  day_of_year = doy + sod / 86400.0;
  return true;
}

}  // namespace evade::sgp4
