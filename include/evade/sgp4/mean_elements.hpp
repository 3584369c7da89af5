// One catalog entry: SGP4 mean elements as TLEs and CCSDS OMMs carry them (TEME, Kozai mean
// motion, B*), in the catalog's own units (degrees, rev/day), plus where it was read.
#pragma once

#include <string>
#include <vector>

namespace evade::sgp4 {

struct MeanElements {
  std::string name;        ///< 3LE title line or OBJECT_NAME (may be empty)
  std::string object_id;   ///< international designator ("1958-002B"; TLE form "58002B")
  long norad_id = 0;       ///< NORAD catalog number (Alpha-5 decoded)
  char classification = 'U';
  int epoch_year = 2000;           ///< UTC year of the epoch
  double epoch_day_of_year = 1.0;  ///< 1.0 = Jan 1 00:00 UTC
  double mean_motion_revpday = 0.0;      ///< Kozai mean motion
  double eccentricity = 0.0;
  double inclination_deg = 0.0;
  double raan_deg = 0.0;
  double arg_perigee_deg = 0.0;
  double mean_anomaly_deg = 0.0;
  double bstar_per_er = 0.0;                 ///< B* drag term (1/Earth radii)
  double mean_motion_dot_revpday2 = 0.0;     ///< first derivative / 2, as the TLE field
  double mean_motion_ddot_revpday3 = 0.0;    ///< second derivative / 6, as the TLE field
  int ephemeris_type = 0;
  int element_set_no = 0;
  long rev_at_epoch = 0;
  int source_line = 0;  ///< 1-based line of the entry's first line in its text
};

/// Julian date (UTC) of the epoch, split into the day (x.5) and the fraction of a day.
struct SplitJulianDate {
  double day = 0.0;
  double fraction = 0.0;
};
SplitJulianDate epoch_julian_date(const MeanElements& m) noexcept;

/// Seconds since J2000 (2000-01-01 12:00:00 UTC, 86 400 s days, the project's convention).
double epoch_seconds_since_j2000(const MeanElements& m) noexcept;

/// The latest element epoch of a catalog, seconds since J2000 (0 for an empty one): the
/// start of every catalog propagation and screening unless another is given.
double latest_epoch_seconds_since_j2000(const std::vector<MeanElements>& elements) noexcept;

/// Julian date of 0 January 00:00 UTC of a Gregorian year (1900..2099).
double julian_date_jan0(int year) noexcept;

}  // namespace evade::sgp4
