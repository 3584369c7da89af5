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
}

}  // namespace
}  // namespace evade
