// UTC calendar <-> seconds since J2000, checked on published Julian dates.
#include <gtest/gtest.h>

#include "evade/core/epoch.hpp"

namespace evade {
namespace {

TEST(Epoch, J2000IsZeroAndJulianDateMatchesVallado) {
  EXPECT_EQ(seconds_since_j2000_from_calendar({2000, 1, 1, 12, 0, 0.0}), 0.0);
  EXPECT_DOUBLE_EQ(julian_date_from_calendar({2000, 1, 1, 12, 0, 0.0}), 2451545.0);
  // Vallado 4th ed. example 3-4: 1996-10-26 14:20:00 UT -> JD 2450383.09722222.
  EXPECT_NEAR(julian_date_from_calendar({1996, 10, 26, 14, 20, 0.0}), 2450383.09722222, 1e-8);
}

TEST(Epoch, PaperEpochsRoundTripToTheNanosecond) {
  for (const char* text : {"1999-10-01 00:00:00", "2016-02-29 23:59:59.5", "2017-06-15T06:30:00.123456789"}) {
    const CalendarUtc c = parse_calendar_utc(text);
    const double t = seconds_since_j2000_from_calendar(c);
    const CalendarUtc back = calendar_from_seconds_since_j2000(t);
    EXPECT_EQ(back.year, c.year);
    EXPECT_EQ(back.month, c.month);
    EXPECT_EQ(back.day, c.day);
    EXPECT_EQ(back.hour, c.hour);
    EXPECT_EQ(back.minute, c.minute);
    // |t| ~ 5e8 s: one ulp is 6e-8 s, so the seconds come back to ~1e-7 s.
    EXPECT_NEAR(back.second, c.second, 2e-7) << text;
  }
  EXPECT_EQ(seconds_since_j2000_from_calendar({1999, 10, 1, 0, 0, 0.0}), -7948800.0 - 43200.0);
}

TEST(Epoch, RejectsOutOfRangeFieldsAndGarbage) {
  EXPECT_THROW(parse_calendar_utc("1999-13-01 00:00:00"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("1999-02-30 00:00:00"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("1999-10-01 00:00:61"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("yesterday"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("1999-10-01 00:00:00 junk"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("1999-10-01T00:00:00+24:00"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("1999-10-01T00:00:00+01:60"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("1999-10-01T00:00:00+1"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("1999-10-01T00:00:00ZZ"), std::invalid_argument);
  EXPECT_THROW(parse_calendar_utc("1999-10-0"), std::invalid_argument);
}

// Issue 46: every time flag takes ISO 8601 as Python's start_utc does: 'T' or ' ', a trailing
// Z, an offset from UTC (subtracted, across midnight and the year's end), a date alone.
TEST(Epoch, Iso8601WithZOffsetsAndDateAloneIsTheSameUtcInstant) {
  const auto same = [](const std::string& text, const CalendarUtc& want) {
    const CalendarUtc c = parse_calendar_utc(text);
    EXPECT_EQ(c.year, want.year) << text;
    EXPECT_EQ(c.month, want.month) << text;
    EXPECT_EQ(c.day, want.day) << text;
    EXPECT_EQ(c.hour, want.hour) << text;
    EXPECT_EQ(c.minute, want.minute) << text;
    EXPECT_EQ(c.second, want.second) << text;  // exact: the seconds are kept as read
  };
  same("2026-11-15T00:00:00Z", {2026, 11, 15, 0, 0, 0.0});
  same("2026-11-15 00:00:00.104192019Z", {2026, 11, 15, 0, 0, 0.104192019});
  same("2026-11-15T01:30:00+01:30", {2026, 11, 15, 0, 0, 0.0});
  same("2026-11-15T01:30:00+0130", {2026, 11, 15, 0, 0, 0.0});
  same("2026-11-15T01:00:07.25+01", {2026, 11, 15, 0, 0, 7.25});
  same("2026-12-31T23:00:00-05:00", {2027, 1, 1, 4, 0, 0.0});
  same("2026-03-01T00:30:00+02:00", {2026, 2, 28, 22, 30, 0.0});
  same("2026-11-15", {2026, 11, 15, 0, 0, 0.0});
}

}  // namespace
}  // namespace evade
