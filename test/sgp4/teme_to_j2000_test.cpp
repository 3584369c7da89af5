// TEME -> J2000 against the worked example of Vallado et al. (2006), AIAA 2006-6753 (and
// Vallado, Fundamentals of Astrodynamics, Example 3-15): 2004-04-06 07:51:28.386009 UTC,
// TT - UTC = 64.184 s. The tolerance is the truncation bound of the 10-term IAU-1980 series
// measured against the longer series (0.034 arcsec) times |r|, plus the example's 0.1 m
// rounding: not a fitted number.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/LU>

#include "evade/core/epoch.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"

namespace evade::sgp4 {
namespace {

TEST(TemeToJ2000, Vallado2006WorkedExample) {
  const double t = seconds_since_j2000_from_calendar(CalendarUtc{2004, 4, 6, 7, 51, 28.386009}) + 64.184;
  const Eigen::Vector3d r_teme(5094180.16210, 6127644.65950, 6380344.53270);
  const Eigen::Vector3d v_teme(-4746.131487, 785.818041, 5531.931288);
  Eigen::Vector3d r, v;
  teme_to_j2000(t, r_teme, v_teme, r, v);
  const Eigen::Vector3d r_ref(5102509.6, 6123011.52, 6378136.3);
  const Eigen::Vector3d v_ref(-4743.2196, 790.5366, 5533.7561);
  const double bound_rad = 0.034 / 206264.806;
  EXPECT_LT((r - r_ref).norm(), bound_rad * r_teme.norm() + 0.1);
  EXPECT_LT((v - v_ref).norm(), bound_rad * v_teme.norm() + 1e-4);
  // The rotation is proper and orthonormal, and TEME and J2000 differ by precession (~0.2
  // deg over 4 years): the example's shift is 8.3 km.
  const Eigen::Matrix3d m = teme_to_j2000_matrix(t);
  EXPECT_LT((m * m.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
  EXPECT_GT((r - r_teme).norm(), 8000.0);
}

TEST(TemeToJ2000, NutationLeadingTermAtJ2000) {
  // At J2000.0 the IAU-1980 nutation is dpsi = -13.93", deps = -5.77" (the series' value,
  // dominated by the 18.6-year term with Omega = 125.04 deg).
  const Nutation n = nutation_iau80(0.0);
  EXPECT_NEAR(n.dpsi_rad / (3.14159265358979 / 648000.0), -13.93, 0.08);
  EXPECT_NEAR(n.deps_rad / (3.14159265358979 / 648000.0), -5.77, 0.04);
  EXPECT_NEAR(n.eps_mean_rad / (3.14159265358979 / 648000.0), 84381.448, 1e-9);
}

}  // namespace
}  // namespace evade::sgp4
