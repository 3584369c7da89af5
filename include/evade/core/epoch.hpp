// UTC calendar <-> seconds since J2000 (2000-01-01 12:00:00 UTC taken as the origin).
//
// Leap seconds are ignored: every day has 86 400 s. That is enough for the papers' epochs
// (1999-10-01, 2016-02, 2017), which only need consistent elapsed times, not UT1/TT.
// Proleptic Gregorian calendar, valid for years 1900..2199.
#pragma once

#include <cstdint>
#include <string>

namespace evade {

struct CalendarUtc {
  int year = 2000;
  int month = 1;   ///< 1..12
  int day = 1;     ///< 1..31
  int hour = 0;    ///< 0..23
  int minute = 0;  ///< 0..59
  double second = 0.0;  ///< [0, 60)
};

/// Julian date of a UTC calendar instant (days).
double julian_date_from_calendar(const CalendarUtc& c);
/// Seconds since J2000 (2000-01-01 12:00:00) of a UTC calendar instant. Throws
/// std::invalid_argument on a field out of range (month 13, day 32, second 61, ...).
double seconds_since_j2000_from_calendar(const CalendarUtc& c);
/// Inverse of seconds_since_j2000_from_calendar.
CalendarUtc calendar_from_seconds_since_j2000(double t_s);
/// Parses ISO 8601: "YYYY-MM-DD" (midnight), "YYYY-MM-DD hh:mm:ss[.fff]" or
/// "YYYY-MM-DDThh:mm:ss[.fff]", each time optionally followed by "Z" or an offset from UTC
/// ("+hh:mm", "-hh:mm", "+hhmm", "+hh"), which is subtracted (2026-11-15T01:00:00+01:00 is
/// 2026-11-15 00:00:00 UTC); throws std::invalid_argument naming the text on failure.
CalendarUtc parse_calendar_utc(const std::string& text);
/// J2000 (2000-01-01 12:00:00 UTC) in Unix seconds: the one offset between the two time bases.
inline constexpr double kJ2000UnixS = 946728000.0;
/// Seconds since J2000 of a Unix utime [us].
inline double seconds_since_j2000_from_unix_utime(std::int64_t utime_us) noexcept {
  return 1e-6 * static_cast<double>(utime_us) - kJ2000UnixS;
}
/// Formats as "YYYY-MM-DD hh:mm:ss.fffffffff".
std::string format_calendar_utc(const CalendarUtc& c);

}  // namespace evade
