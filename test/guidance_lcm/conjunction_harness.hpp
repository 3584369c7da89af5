// Test harness for the onboard conjunction response through the node (docs/AUTONOMY.md): the
// constructed LEO conjunction of test/autonomy/cam_example_event.hpp moved onto the node's
// clock, the node's navigation flown along the very orbit the event's own state is on (two-body
// + J2, the onboard propagator, so the nav check passes), the uplinked evade_conjunction_t and
// evade_cam_decision_t, and a recorder of the node's proposals that verifies each under the
// telemetry key exactly as the ground does; Flight, the node flying that orbit with the ground's
// signer and recorders.
#pragma once

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "../autonomy/cam_example_event.hpp"
#include "command_harness.hpp"
#include "evade/autonomy/orbit_stm.hpp"
#include "evade/core/constants.hpp"
#include "evade/evade_cam_decision_t.hpp"
#include "evade/evade_cam_proposal_t.hpp"
#include "evade/evade_conjunction_t.hpp"

namespace evade::guidance_lcm::test {

/// The example event with its times moved from test_example::kNow to kT0.
inline autonomy::ConjunctionEvent node_event(std::int64_t id = 7, std::int32_t version = 1) {
  autonomy::ConjunctionEvent e = autonomy::test_example::example_event(id);
  const std::int64_t shift = kT0 - autonomy::test_example::kNow;
  e.version = version;
  e.tca_us += shift;
  e.burn_start_us += shift;
  e.burn_end_us += shift;
  e.veto_deadline_us += shift;
  return e;
}

inline evade_conjunction_t conjunction_msg(const autonomy::ConjunctionEvent& e, std::int64_t seq,
                                           std::int64_t utime = kT0) {
  evade_conjunction_t m{};
  m.utime = utime;
  m.seq = seq;
  m.event_id = e.event_id;
  m.version = e.version;
  m.tca_utime = e.tca_us;
  for (int i = 0; i < 3; ++i) {
    m.r1_eci_m[i] = e.x1_eci(i);
    m.v1_eci_mps[i] = e.x1_eci(i + 3);
    m.r2_eci_m[i] = e.x2_eci(i);
    m.v2_eci_mps[i] = e.x2_eci(i + 3);
  }
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      m.cov1_eci[i][j] = e.cov1_eci(i, j);
      m.cov2_eci[i][j] = e.cov2_eci(i, j);
    }
  }
  m.hbr_m = e.hbr_m;
  m.pc_red = e.pc_red;
  m.pc_target = e.pc_target;
  m.burn_window_start_utime = e.burn_start_us;
  m.burn_window_end_utime = e.burn_end_us;
  m.veto_deadline_utime = e.veto_deadline_us;
  return m;
}

inline evade_cam_decision_t decision_msg(std::int8_t decision, std::int64_t event_id,
                                         std::int64_t proposal_id, std::int8_t autonomy = 0) {
  evade_cam_decision_t m{};
  m.utime = kT0;
  m.seq = 1;
  m.decision = decision;
  m.event_id = event_id;
  m.proposal_id = proposal_id;
  m.autonomy = autonomy;
  return m;
}

/// The own orbit: the event's own state at TCA flown back to t_us (RK4, 10 s steps; the
/// node's check propagates forward with its own step, and RK4's difference is millimetres
/// against the 20-150 m sigmas of the example).
class OrbitNav {
 public:
  explicit OrbitNav(const autonomy::ConjunctionEvent& e) : x_(e.x1_eci), t_us_(e.tca_us) {}
  /// Nav at t_us (t_us not before the previous call's: the orbit is flown forward from there).
  evade_nav_state_t at(std::int64_t t_us, std::int64_t seq) {
    const double dt_s = 1e-6 * static_cast<double>(t_us - t_us_);
    EXPECT_TRUE(autonomy::propagate(&x_, dt_s, 10.0, kEarthDefault));
    t_us_ = t_us;
    evade_nav_state_t m{};
    m.utime = t_us;
    m.seq = seq;
    m.valid = true;
    for (int i = 0; i < 3; ++i) {
      m.r_eci_m[i] = x_(i);
      m.v_eci_mps[i] = x_(i + 3);
    }
    return m;
  }

 private:
  Vec6 x_;
  std::int64_t t_us_;
};

/// Every proposal the node publishes on EVADE_CAM_PROPOSAL, verified under the telemetry key.
class ProposalRecorder {
 public:
  explicit ProposalRecorder(lcm_t* lcm) : lcm_(lcm) {
    sub_ = lcm_subscribe(lcm, kChanCamProposal, &ProposalRecorder::on_msg, this);
  }
  ~ProposalRecorder() { lcm_unsubscribe(lcm_, sub_); }
  ProposalRecorder(const ProposalRecorder&) = delete;
  ProposalRecorder& operator=(const ProposalRecorder&) = delete;
  const std::vector<evade_cam_proposal_t>& all() const { return msgs_; }
  int unverified() const { return unverified_; }
  /// The last proposal of event_id (version 0: any), or nullptr.
  const evade_cam_proposal_t* last(std::int64_t event_id, std::int32_t version = 0) const {
    for (auto it = msgs_.rbegin(); it != msgs_.rend(); ++it) {
      if (it->event_id == event_id && (version == 0 || it->version == version)) return &*it;
    }
    return nullptr;
  }

 private:
  static void on_msg(const lcm_recv_buf_t* rbuf, const char* channel, void* user) {
    auto* self = static_cast<ProposalRecorder*>(user);
    const auto* d = static_cast<const std::uint8_t*>(rbuf->data);
    const SigningKey k = test_telemetry_key();
    auth::TrailerView t;
    evade_cam_proposal_t m{};
    const bool ok = auth::read_trailer(d, rbuf->data_size, &t) && t.key_id == k.id &&
                    auth::mac_valid(k.key, channel, d, rbuf->data_size) &&
                    m.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) ==
                        static_cast<int>(rbuf->data_size);
    if (!ok) {
      ++self->unverified_;
      return;
    }
    self->msgs_.push_back(m);
  }
  lcm_t* lcm_;
  lcm_subscription_t* sub_ = nullptr;
  std::vector<evade_cam_proposal_t> msgs_;
  int unverified_ = 0;
};

/// The node with policy p. Its burn search looks at 2 candidate times of the window instead of
/// 8 (node.autonomy.cam.burn_times): these tests prove the node's handling of the response
/// (authority, accounting, the burn flown or withdrawn), not the search's thoroughness, which
/// test/autonomy proves with the defaults (OnboardCam.*, Response.*); the assessment is most of
/// their time, a quarter of it so, under qemu in the cross stage. The allocation test
/// (alloc_test.cpp) keeps the defaults.
inline NodeConfig config(autonomy::Policy p = autonomy::Policy::kVeto) {
  NodeConfig c;
  c.autonomy = p;
  c.response.cam.burn_times = 2;
  return c;
}

// The node flying the example's own orbit, the ground's signer, and what the ground receives.
struct Flight {
  explicit Flight(autonomy::Policy p = autonomy::Policy::kVeto) : Flight(config(p)) {}
  explicit Flight(const NodeConfig& c)
      : rig(c), nav(node_event()), acks(rig.lcm.get()), proposals(rig.lcm.get()) {}
  /// One cycle at t_us with the nav of that instant.
  const evade_thrust_cmd_t& step(std::int64_t t_us) {
    rig.pub.send(kChanNav, nav.at(t_us, ++nav_seq));
    return rig.cycle(t_us);
  }
  /// Regular cycles over [t0, t1); returns how many thrust.
  int steps(std::int64_t t0, std::int64_t t1) {
    int n = 0;
    for (std::int64_t t = t0; t < t1; t += kPeriodUs) n += step(t).accel_mps2 > 0.0 ? 1 : 0;
    last_t = t1;
    return n;
  }
  /// The event uplinked at kT0, assessed by the worker (this thread, in its place), proposed.
  const evade_cam_proposal_t* propose(const autonomy::ConjunctionEvent& e = node_event()) {
    rig.pub.send(kChanConjunction, conjunction_msg(e, 1));
    step(kT0);
    EXPECT_TRUE(rig.node.plan_once()) << "the cycle handed out no job";
    steps(kT0 + kPeriodUs, kT0 + 3 * kPeriodUs);  // collect, publish, and deliver the proposal
    return proposals.last(e.event_id, e.version);
  }
  void decide(const evade_cam_decision_t& d) { rig.pub.send(kChanCamDecision, d); }
  std::int64_t state(std::int64_t id) const {
    const evade_cam_proposal_t* p = proposals.last(id);
    return p == nullptr ? -1 : p->state;
  }

  Rig rig;
  OrbitNav nav;
  AckRecorder acks;
  ProposalRecorder proposals;
  std::int64_t nav_seq = 0;
  std::int64_t last_t = kT0;
};

}  // namespace evade::guidance_lcm::test
