// Stepping DOP853 on a fixed-size state, using its dense output and propagating Kepler and
// HCW must not allocate (STYLE: no allocation in the loop, proved by a test). Global
// operator new is replaced to count calls while a guard is armed.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/hcw.hpp"
#include "evade/dynamics/kepler_propagator.hpp"
#include "test_orbits.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_news{0};
}  // namespace

// GCC flags free() of memory from the (replaced) operator new; here both sides are ours.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  if (g_counting.load()) ++g_news;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace evade {
namespace {

struct CountNew {
  CountNew() { g_news = 0; g_counting = true; }
  ~CountNew() { g_counting = false; }
  long count() const { return g_news.load(); }
};

// Control: the counter does see allocations (otherwise the tests below could not fail).
TEST(NoAllocation, CounterSeesAHeapAllocation) {
  long news = 0;
  {
    CountNew guard;
    auto* p = new std::vector<double>(100);
    news = guard.count();
    delete p;
  }
  EXPECT_GE(news, 2);
}

TEST(NoAllocation, Dop853StepsAndDenseOutputDoNotAllocateForFixedSizeStates) {
  auto f = [](double, const Vec6& x) {
    return orbit_derivative(x, GravityModel::kTwoBodyJ2, kEarthDefault);
  };
  Dop853<Vec6> integ(f);  // constructing (std::function) may allocate; stepping must not
  integ.reset(0.0, test::leo_e01().stacked());
  long news = 0;
  {
    CountNew guard;
    for (int k = 0; k < 500; ++k) {
      ASSERT_TRUE(integ.step(1e6));
      const Vec6 mid = integ.dense(0.5 * (integ.t_prev_s() + integ.t_s()));
      ASSERT_TRUE(mid.allFinite());
    }
    news = guard.count();
  }
  EXPECT_EQ(news, 0);
}

TEST(NoAllocation, KeplerAndHcwDoNotAllocate) {
  const StateEci s0 = test::leo_e01();
  long news = 0;
  {
    CountNew guard;
    StateEci s = s0;
    Vec6 x = Vec6::Ones();
    for (int k = 0; k < 1000; ++k) {
      s = propagate_kepler(s, 10.0, kEarthDefault.mu_m3ps2);
      x = hcw_propagate(1e-3, 10.0, x);
    }
    news = guard.count();
    ASSERT_TRUE(s.r_eci_m.allFinite() && x.allFinite());
  }
  EXPECT_EQ(news, 0);
}

}  // namespace
}  // namespace evade
