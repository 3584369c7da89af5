// fmod_two_pi (include/evade/sgp4/internal/fmod_two_pi.hpp) is std::fmod(x, 2 pi) bit for bit:
// random angles over the range SGP4 forms and far past it, the doubles nearest every multiple
// of 2 pi up to 2^20 of them (where x / 2 pi rounds across an integer and the quotient is off
// by one), signed zeros, the switch to std::fmod at 2^40, NaN and the infinities.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "evade/sgp4/internal/fmod_two_pi.hpp"

namespace evade::sgp4::detail {
namespace {

constexpr double kTwoPiDouble = 2.0 * 3.14159265358979323846;

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// 0 when fmod_two_pi(x) and std::fmod(x, 2 pi) are the same double (both NaN counts as same).
int differs(double x) {
  const double a = fmod_two_pi(x), b = std::fmod(x, kTwoPiDouble);
  if (std::isnan(a) && std::isnan(b)) return 0;
  return bits(a) == bits(b) ? 0 : 1;
}

TEST(FmodTwoPi, EqualsStdFmodOnRandomAngles) {
  std::mt19937_64 rng(2026);
  long bad = 0, n = 0;
  for (const double scale : {1.0, 10.0, 1e3, 1e6, 1e9, 1e12, 1e15}) {
    std::uniform_real_distribution<double> u(-scale, scale);
    for (int i = 0; i < 200000; ++i, ++n) bad += differs(u(rng));
  }
  EXPECT_EQ(bad, 0) << "of " << n;
}

TEST(FmodTwoPi, EqualsStdFmodBesideEveryMultipleOfTwoPi) {
  long bad = 0, n = 0;
  for (std::int64_t k = -(1 << 20); k <= (1 << 20); ++k) {
    const double m = static_cast<double>(k) * kTwoPiDouble;
    double lo = m, hi = m;
    for (int j = 0; j < 3; ++j) {  // m and the three doubles on each side of it
      lo = std::nextafter(lo, -INFINITY);
      hi = std::nextafter(hi, INFINITY);
      bad += differs(lo) + differs(hi);
      n += 2;
    }
    bad += differs(m);
    ++n;
  }
  EXPECT_EQ(bad, 0) << "of " << n;
}

TEST(FmodTwoPi, SignedZerosSwitchPointAndNonFinite) {
  for (const double x : {0.0, -0.0, kTwoPiDouble, -kTwoPiDouble, 0x1p40, -0x1p40,
                         std::nextafter(0x1p40, 0.0), 1e300, -1e300,
                         std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN()})
    EXPECT_EQ(differs(x), 0) << x;
  EXPECT_TRUE(std::signbit(fmod_two_pi(-0.0)));
  EXPECT_TRUE(std::signbit(fmod_two_pi(-kTwoPiDouble)));
}

}  // namespace
}  // namespace evade::sgp4::detail
