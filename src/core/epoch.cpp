// UTC calendar <-> seconds since J2000. Julian date by Fliegel & Van Flandern (1968)
// integer algorithm (Vallado 4th ed. alg. 14 gives the same for 1900..2100).
#include "evade/core/epoch.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace evade {
namespace {

int days_in_month(int year, int month) {
  static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return (month == 2 && leap) ? 29 : kDays[month - 1];
}

// Julian day number of the civil date at 12:00 (Fliegel & Van Flandern).
std::int64_t julian_day_number(int y, int m, int d) {
  const std::int64_t a = (14 - m) / 12;
  const std::int64_t yy = y + 4800 - a;
  const std::int64_t mm = m + 12 * a - 3;
  return d + (153 * mm + 2) / 5 + 365 * yy + yy / 4 - yy / 100 + yy / 400 - 32045;
}

void validate(const CalendarUtc& c) {
  auto bad = [](const char* what, double v, const char* allowed) {
    char buf[160];
    // The field names and ranges are the short literals below: the text fits (at worst
    // snprintf truncates the message), so the count it returns is not needed.
    (void)std::snprintf(buf, sizeof buf, "calendar field %s = %g out of range (allowed %s)", what,
                        v, allowed);
    throw std::invalid_argument(buf);
  };
  if (c.year < 1900 || c.year > 2199) bad("year", c.year, "1900..2199");
  if (c.month < 1 || c.month > 12) bad("month", c.month, "1..12");
  if (c.day < 1 || c.day > days_in_month(c.year, c.month)) bad("day", c.day, "1..days in month");
  if (c.hour < 0 || c.hour > 23) bad("hour", c.hour, "0..23");
  if (c.minute < 0 || c.minute > 59) bad("minute", c.minute, "0..59");
  if (!std::isfinite(c.second) || c.second < 0.0 || c.second >= 60.0)
    bad("second", c.second, "[0, 60)");
}

}  // namespace

double julian_date_from_calendar(const CalendarUtc& c) {
  validate(c);
  const std::int64_t jdn = julian_day_number(c.year, c.month, c.day);
  return static_cast<double>(jdn) - 0.5 + (c.hour * 3600.0 + c.minute * 60.0 + c.second) / 86400.0;
}

double seconds_since_j2000_from_calendar(const CalendarUtc& c) {
  validate(c);
  // Integer days first so the seconds keep full precision (no 2.45e6-day offset rounding).
  const std::int64_t days = julian_day_number(c.year, c.month, c.day) - 2451545L;
  return static_cast<double>(days) * 86400.0 - 43200.0 + c.hour * 3600.0 + c.minute * 60.0 +
         c.second;
}

CalendarUtc calendar_from_seconds_since_j2000(double t_s) {
  if (!std::isfinite(t_s)) throw std::invalid_argument("calendar_from_seconds_since_j2000: non-finite time");
  // Shift to midnight-based day count.
  const double since_midnight_2000 = t_s + 43200.0;
  const double day_floor = std::floor(since_midnight_2000 / 86400.0);
  double sec_of_day = since_midnight_2000 - day_floor * 86400.0;
  std::int64_t jdn = static_cast<std::int64_t>(day_floor) + 2451545L;
  if (sec_of_day >= 86400.0) {  // rounding guard
    sec_of_day -= 86400.0;
    ++jdn;
  }
  // Inverse Fliegel & Van Flandern.
  std::int64_t l = jdn + 68569;
  const std::int64_t n = 4 * l / 146097;
  l = l - (146097 * n + 3) / 4;
  const std::int64_t i = 4000 * (l + 1) / 1461001;
  l = l - 1461 * i / 4 + 31;
  const std::int64_t j = 80 * l / 2447;
  const std::int64_t day = l - 2447 * j / 80;
  l = j / 11;
  const std::int64_t month = j + 2 - 12 * l;
  const std::int64_t year = 100 * (n - 49) + i + l;
  CalendarUtc c;
  c.year = static_cast<int>(year);
  c.month = static_cast<int>(month);
  c.day = static_cast<int>(day);
  c.hour = static_cast<int>(sec_of_day / 3600.0);
  sec_of_day -= c.hour * 3600.0;
  c.minute = static_cast<int>(sec_of_day / 60.0);
  c.second = sec_of_day - c.minute * 60.0;
  if (c.second < 0.0) c.second = 0.0;
  return c;
}

namespace {

[[noreturn]] void bad_time(const std::string& text) {
  throw std::invalid_argument("cannot parse UTC time '" + text +
                              "' (expected ISO 8601: YYYY-MM-DD, YYYY-MM-DD hh:mm:ss[.fff] or "
                              "YYYY-MM-DDThh:mm:ss[.fff], optionally followed by Z or +hh:mm/-hh:mm)");
}

// "hh", "hhmm" or "hh:mm" as hours 0..23 and minutes 0..59; false for anything else.
bool offset_hours_minutes(std::string digits, int* hh, int* mm) {
  if (digits.size() == 5 && digits[2] == ':') digits.erase(2, 1);
  if (digits.size() != 2 && digits.size() != 4) return false;
  for (const char ch : digits) {
    if (ch < '0' || ch > '9') return false;
  }
  const auto two = [&](std::size_t i) { return (digits[i] - '0') * 10 + (digits[i + 1] - '0'); };
  *hh = two(0);
  *mm = digits.size() == 4 ? two(2) : 0;
  return *hh <= 23 && *mm <= 59;
}

// The offset from UTC of a suffix "" / "Z" / "+hh:mm" / "-hh:mm" / "+hhmm" / "+hh" [s]; false
// for anything else.
bool utc_offset_s(const std::string& suffix, int* offset_s) {
  *offset_s = 0;
  if (suffix.empty() || suffix == "Z") return true;
  int hh = 0;
  int mm = 0;
  if ((suffix[0] != '+' && suffix[0] != '-') || !offset_hours_minutes(suffix.substr(1), &hh, &mm))
    return false;
  *offset_s = (suffix[0] == '-' ? -1 : 1) * (hh * 3600 + mm * 60);
  return true;
}

}  // namespace

CalendarUtc parse_calendar_utc(const std::string& text) {
  CalendarUtc c;
  char sep = 0;
  int consumed = 0;
  // NOLINTNEXTLINE(cert-err34-c,bugprone-unchecked-string-to-number-conversion): %4d/%2d cannot overflow; validate() range-checks the %lf
  const int n = std::sscanf(text.c_str(), "%4d-%2d-%2d%c%2d:%2d:%lf%n", &c.year, &c.month, &c.day,
                            &sep, &c.hour, &c.minute, &c.second, &consumed);
  if (n == 3 && text.size() == 10) {  // a date alone: its midnight
    validate(c);
    return c;
  }
  int offset_s = 0;
  if (n != 7 || (sep != ' ' && sep != 'T') || consumed <= 0 ||
      !utc_offset_s(text.substr(static_cast<std::size_t>(consumed)), &offset_s)) {
    bad_time(text);
  }
  validate(c);
  if (offset_s == 0) return c;
  // Local time minus the offset, in whole minutes (exact in double), the seconds kept as read.
  const double second = c.second;
  c.second = 0.0;
  CalendarUtc utc = calendar_from_seconds_since_j2000(seconds_since_j2000_from_calendar(c) - offset_s);
  utc.second = second;
  return utc;
}

std::string format_calendar_utc(const CalendarUtc& c) {
  char buf[64];
  // A valid calendar (validate()) is 29 characters; snprintf never overruns the buffer, so
  // its returned count is not needed.
  (void)std::snprintf(buf, sizeof buf, "%04d-%02d-%02d %02d:%02d:%012.9f", c.year, c.month, c.day,
                      c.hour, c.minute, c.second);
  return buf;
}

}  // namespace evade
