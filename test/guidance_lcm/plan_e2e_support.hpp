// Shared by the end-to-end plan tests (PLAN-E2E-*): the guidance node on memq:// behind the
// simulator's endpoint interface, and the HCW matrices of the finite-burn bounds (PLAN-FB-*).
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>

#include <lcm/lcm.h>

#include "evade/core/state.hpp"
#include "evade/dynamics/hcw.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"
#include "evade/lcm_link/burn_plan_publisher.hpp"
#include "evade/sim/guidance_endpoint.hpp"
#include "guidance_lcm/node_harness.hpp"

namespace evade::test {

// The node on memq:// behind the simulator's endpoint interface: nav in as evade_nav_state_t,
// one run_cycle per exchange (lockstep at the simulator's utime), command out decoded. The
// node holds the test keys (node_harness.hpp): plans are published signed with
// signed_stamp(), as the ground signs them (docs/SECURITY.md).
class NodeEndpoint final : public sim::GuidanceEndpoint {
 public:
  explicit NodeEndpoint(const guidance_lcm::NodeConfig& cfg)
      : lcm_(lcm_create("memq://"), &lcm_destroy),
        node_(lcm_.get(), cfg, nullptr, guidance_lcm::test::test_security()) {}
  guidance::ThrustCommand exchange(std::int64_t utime, const guidance::NavState& nav,
                                   const guidance::AnglesMeasurement*) override {
    evade_nav_state_t m{};
    guidance_lcm::to_lcm(nav, ++seq_, &m);
    std::uint8_t buf[256];
    const int n = m.encode(buf, 0, sizeof buf);
    lcm_publish(lcm_.get(), guidance_lcm::kChanNav, buf, static_cast<unsigned>(n));
    node_.drain();
    guidance::ThrustCommand c;
    guidance_lcm::from_lcm(node_.run_cycle(utime), &c);
    return c;
  }
  lcm_t* lcm() { return lcm_.get(); }
  const guidance_lcm::GuidanceNode& node() const { return node_; }

 private:
  std::unique_ptr<lcm_t, void (*)(lcm_t*)> lcm_;
  guidance_lcm::GuidanceNode node_;
  std::int64_t seq_ = 0;
};

// The stamp of a plan signed with the test command key.
inline lcm_link::PlanStamp signed_stamp() {
  static std::int64_t arsn = 0;  // the ground's counter: each signed plan takes the next ARSN
  lcm_link::PlanStamp s;
  s.key = guidance_lcm::test::test_command_key();
  s.arsn = ++arsn;
  return s;
}

// HCW A (RSW): ẍ = 3n²x + 2nẏ, ÿ = −2nẋ, z̈ = −n²z.
inline Mat6 hcw_a(double n) {
  Mat6 a = Mat6::Zero();
  a.block<3, 3>(0, 3) = Mat3::Identity();
  a(3, 0) = 3.0 * n * n;
  a(5, 2) = -n * n;
  a(3, 4) = 2.0 * n;
  a(4, 3) = -2.0 * n;
  return a;
}

inline double angle_deg(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

struct Bound {
  double r_m = 0.0;
  double v_mps = 0.0;
};

// PLAN-FB-1 + PLAN-FB-3 at t − t_b after a burn of |Δv| planned at t_b, flown over τ in
// cycles of T, centred within T/2 of t_b, its direction fixed in ECI over each cycle (HCW
// about the circular orbit of mean motion n):
//   ‖ΦA²B‖ |Δv| τ²/24 + ‖ΦAB‖ |Δv| T/2 + ‖ΦB‖ |Δv| n T/2   (position and velocity rows).
inline Bound finite_burn_bound(double n, double t_minus_tb, double dv, double tau,
                               double cycle_s) {
  const Mat6 phi = hcw_stm(n, t_minus_tb);
  const Mat6 a = hcw_a(n);
  Eigen::Matrix<double, 6, 3> b = Eigen::Matrix<double, 6, 3>::Zero();
  b.block<3, 3>(3, 0) = Mat3::Identity();
  const Eigen::Matrix<double, 6, 3> m2 = phi * a * a * b, m1 = phi * a * b, m0 = phi * b;
  const double k2 = dv * tau * tau / 24.0, k1 = dv * 0.5 * cycle_s, k0 = dv * n * 0.5 * cycle_s;
  return {m2.topRows<3>().norm() * k2 + m1.topRows<3>().norm() * k1 + m0.topRows<3>().norm() * k0,
          m2.bottomRows<3>().norm() * k2 + m1.bottomRows<3>().norm() * k1 +
              m0.bottomRows<3>().norm() * k0};
}

}  // namespace evade::test
