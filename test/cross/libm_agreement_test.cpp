// The platform half of the floating-point contract (docs/GUIDANCE_NODE.md NODE-RT-5): flight
// code's own arithmetic is the same on every target (-ffp-contract=off), but sin, cos, atan2,
// pow and sqrt are the C library's. This test pins what each target's library does with them:
// 200,000 arguments each over the ranges the guidance law and the simulator use them on
// (libm_digests.hpp), one digest per function against x86-64's (x86-64 with FMA: glibc runs
// its FMA variants there). Measured and required: aarch64's and s390x's glibc (compiled with
// fused multiply-adds, like x86-64's FMA variants) give x86-64's results bit for bit for all
// five; armhf's (VFPv3-D16, no fused multiply-add) gives its own sin, cos, atan2 and pow, and
// the same sqrt (IEEE-754 rounds it correctly everywhere). A target's library changing either
// way fails the test, and docs/GUIDANCE_NODE.md with it. hypot differs already on aarch64
// (glibc's FMA kernel: 257,692 of 2,000,000 arguments a last bit apart from x86-64's), so
// flight code does not call it (src/guidance/los_geometry.cpp); its digest is printed only.
// Runs on the host and under qemu-user on each cross target (label flight).
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "libm_digests.hpp"

namespace {

using namespace evade::test;

// armhf's C library rounds sin, cos, atan2 and pow its own way (header comment).
#if defined(__arm__)
constexpr bool kLikeX86[kHypot] = {false, false, false, false, true};
#else
constexpr bool kLikeX86[kHypot] = {true, true, true, true, true};
#endif

TEST(LibmAgreement, EachTargetsCLibraryRoundsAsDocumented) {
  std::uint64_t d[kCount];
  digests(d);
  for (int k = 0; k < kCount; ++k) std::printf("%-5s %016" PRIx64 "\n", kNames[k], d[k]);
  if (std::getenv("EVADE_PRINT_LIBM_DIGESTS") != nullptr) return;
  for (int k = 0; k < kHypot; ++k)
    EXPECT_EQ(d[k] == kX86Digest[k], kLikeX86[k])
        << kNames[k] << (kLikeX86[k] ? ": documented to round like x86-64's here, and does not"
                                     : ": documented to round its own way here, and rounds like x86-64's")
        << " (docs/GUIDANCE_NODE.md NODE-RT-5)";
}

}  // namespace
