// The digests of libm_agreement_test.cpp (docs/GUIDANCE_NODE.md NODE-RT-5): 200,000 arguments
// each of sin, cos, atan2, pow, sqrt and hypot over the ranges flight code uses them on, one
// 64-bit digest per function, and x86-64's. same_guidance_test.cpp asks libm_like_x86() whether
// this target's C library rounds like x86-64's, and so whether its outputs must be x86-64's bit
// for bit.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace evade::test {

inline std::uint64_t libm_bits(double x) {
  std::uint64_t u = 0;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

// A portable generator (splitmix64): the same arguments on every target.
struct SplitMix {
  std::uint64_t s;
  double uniform(double lo, double hi) {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return lo + (hi - lo) * (static_cast<double>(z >> 11) * 0x1p-53);
  }
};

enum Fn { kSin, kCos, kAtan2, kPow, kSqrt, kHypot, kCount };
constexpr const char* kNames[kCount] = {"sin", "cos", "atan2", "pow", "sqrt", "hypot"};
// Recorded on x86-64 (GCC 12, glibc 2.36) by this test: EVADE_PRINT_LIBM_DIGESTS=1.
constexpr std::uint64_t kX86Digest[kCount - 1] = {0x4f3fa7c7f4252c04ull, 0xb364b01847ec0403ull,
                                                  0x6304afd6f47ab867ull, 0x4817562b6a86c59aull,
                                                  0xb55aafa5bedcea16ull};

inline void digests(std::uint64_t out[kCount]) {
  SplitMix g{1};
  for (int k = 0; k < kCount; ++k) out[k] = 0;
  auto mix = [&out](int k, double v) { out[k] = (out[k] ^ libm_bits(v)) * 0x100000001B3ull; };
  for (int i = 0; i < 200000; ++i) {
    const double x = g.uniform(-3.2, 3.2), y = g.uniform(-1.0, 1.0), b = g.uniform(1e-6, 10.0);
    mix(kSin, std::sin(x));
    mix(kCos, std::cos(x));
    mix(kAtan2, std::atan2(y, x));
    mix(kPow, std::pow(b, (i % 2 == 0) ? 0.125 : -0.2));  // dop853's 1/8 and its exponent
    mix(kSqrt, std::sqrt(b));
    mix(kHypot, std::hypot(x, y));
  }
}

/// True when sin, cos, atan2, pow and sqrt give x86-64's digests here.
inline bool libm_like_x86() {
  std::uint64_t d[kCount];
  digests(d);
  for (int k = 0; k < kHypot; ++k)
    if (d[k] != kX86Digest[k]) return false;
  return true;
}

}  // namespace evade::test
