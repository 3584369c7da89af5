// Epoch arithmetic for catalog entries (Vallado 2013, Fundamentals of Astrodynamics,
// Algorithm 14 "JD from a Gregorian date", here for 0 January of the epoch year).
#include "evade/sgp4/mean_elements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace evade::sgp4 {

double julian_date_jan0(int year) noexcept {
  // JD = 367 y - floor(7 (y + floor((m + 9) / 12)) / 4) + floor(275 m / 9) + d + 1721013.5,
  // valid 1900..2099; for m = 1, d = 0 (0 January 00:00): floor(275 / 9) = 30.
  const double y = static_cast<double>(year);
  return 367.0 * y - std::floor(7.0 * y / 4.0) + 30.0 + 1721013.5;
}

SplitJulianDate epoch_julian_date(const MeanElements& m) noexcept {
  double whole = 0.0;
  const double frac = std::modf(m.epoch_day_of_year, &whole);
  SplitJulianDate j;
  j.day = julian_date_jan0(m.epoch_year) + whole;  // ends in .5: midnight
  j.fraction = frac;
  return j;
}

double epoch_seconds_since_j2000(const MeanElements& m) noexcept {
  const SplitJulianDate j = epoch_julian_date(m);
  return ((j.day - 2451545.0) + j.fraction) * 86400.0;
}

double latest_epoch_seconds_since_j2000(const std::vector<MeanElements>& elements) noexcept {
  if (elements.empty()) return 0.0;
  double latest = -std::numeric_limits<double>::infinity();
  for (const MeanElements& m : elements) latest = std::max(latest, epoch_seconds_since_j2000(m));
  return latest;
}

}  // namespace evade::sgp4
