// The SGP4 motion of a catalog built from its element sets (sgp4_screening): each element set
// accepted or rejected with its reason, its perturbation bound and its error allowances.
// SGP4 motion of a catalog for the screeners (issue 12; see sgp4_motion.hpp). SGP4/SDP4:
// Vallado, Crawford, Hujsak & Kelso (2006), AIAA 2006-6753 (evade/sgp4). Central and second
// differences: e.g. Atkinson, An Introduction to Numerical Analysis, 2nd ed., sec. 5.7.
// The perturbation envelope and what it assumes: docs/VALIDATION.md, "Robust mode with SGP4
// motion".
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/conjunction/internal/sgp4_motion_support.hpp"
#include "evade/conjunction/sgp4_motion.hpp"

namespace evade::conjunction {
namespace {

using internal::Envelope;
using internal::envelopes;
using internal::fmt;
using internal::n_max_radps;
using internal::sgp4_error_label;

}  // namespace

// Builds Sgp4Motion (a friend, so the motion's vectors stay private).
struct Sgp4CatalogBuilder {
  static Sgp4Screening build(const std::vector<sgp4::MeanElements>& elements,
                             const Sgp4MotionOptions& opt);
  static std::string accept(Sgp4Motion& mo, const sgp4::MeanElements& m, double start_s,
                            const Sgp4MotionOptions& opt, const Envelope& env, SpaceObject& obj);
};

// Adds one element set to the motion, or returns why it is rejected.
std::string Sgp4CatalogBuilder::accept(Sgp4Motion& mo, const sgp4::MeanElements& m,
                                       double start_s, const Sgp4MotionOptions& opt,
                                       const Envelope& env, SpaceObject& obj) {
  const sgp4::Sgp4Propagator prop(m, opt.mode);
  if (prop.init_error() != sgp4::Sgp4Error::kNone) {
    return sgp4_error_label(prop.init_error()) + " at the element epoch";
  }
  if (!(m.mean_motion_revpday > 0.0)) return "mean motion " + fmt(m.mean_motion_revpday) + " rev/day <= 0";
  const EarthModel earth = wgs72_earth();
  const double offset_s = start_s - sgp4::epoch_seconds_since_j2000(m);
  if (env.failure != sgp4::Sgp4Error::kNone) return env.reason();
  mo.props_.push_back(prop);
  mo.offset_s_.push_back(offset_s);
  const char lanes = !sgp4::sgp4_x4_vectorized() ? char{0} : prop.deep_space() ? char{2} : char{1};
  mo.four_lane_.push_back(lanes);
  mo.norad_.push_back(m.norad_id);
  mo.names_.push_back(m.name);
  const std::size_t i = mo.props_.size() - 1;
  obj.name = std::to_string(m.norad_id) + (m.name.empty() ? "" : " " + m.name);
  obj.size_m = opt.object_size_m;
  obj.state = mo.state_at(i, 0.0);
  std::string bad;
  try {
    const OrbitShape shape = orbit_shape(obj.state, earth.mu_m3ps2);
    if (shape.perigee_radius_m <= earth.re_m)
      bad = "osculating perigee radius " + fmt(shape.perigee_radius_m) +
            " m at the start is below the Earth radius";
  } catch (const std::invalid_argument& ex) {
    bad = std::string("osculating orbit at the start: ") + ex.what();
  }
  if (!bad.empty()) {
    mo.props_.pop_back();
    mo.offset_s_.pop_back();
    mo.four_lane_.pop_back();
    mo.norad_.pop_back();
    mo.names_.pop_back();
    return bad;
  }
  const double e = std::min(m.eccentricity, 0.99);
  const double n_radps = m.mean_motion_revpday * 2.0 * kPi / 86400.0;
  const double n_max = n_max_radps(m);
  PerturbationBound b;
  b.accel_mps2 = opt.envelope_factor * (env.p_max_mps2 + env.error_mps2) + opt.envelope_floor_mps2;
  b.rate_mps3 = 4.0 * n_max * b.accel_mps2;
  if (!opt.envelopes) b.accel_mps2 = b.rate_mps3 = std::numeric_limits<double>::infinity();
  mo.bounds_.push_back(b);
  mo.sampled_.push_back(env.p_max_mps2);
  mo.n_max_radps_.push_back(n_max);
  // Largest radius: the mean semi-major axis from n (Kepler's third law) times (1 + e), +10 %.
  const double a_m = std::cbrt(earth.mu_m3ps2 / (n_radps * n_radps));
  const double r_max = 1.1 * a_m * (1.0 + e), tau = opt.velocity_step_s;
  mo.v_err_mps_.push_back(tau * tau * n_max * n_max * n_max * r_max / 3.0 + 4e-12 * r_max / tau);
  mo.grid_err_m_.push_back(!mo.four_lane(i) ? 0.0
                           : mo.deep_lane(i) ? std::max(sgp4::kSgp4X4PositionError_m,
                                                        10.0 * sgp4::kSgp4X4DeepPositionErrorRel * r_max)
                                             : sgp4::kSgp4X4PositionError_m);
  return {};
}

Sgp4Screening Sgp4CatalogBuilder::build(const std::vector<sgp4::MeanElements>& elements,
                                        const Sgp4MotionOptions& opt) {
  opt.validate();
  Sgp4Screening out;
  out.start_j2000_s = opt.start_j2000_s;
  if (opt.start_at_latest_epoch) out.start_j2000_s = sgp4::latest_epoch_seconds_since_j2000(elements);
  auto motion = std::make_shared<Sgp4Motion>();
  motion->velocity_step_s_ = opt.velocity_step_s;
  motion->accel_step_s_ = opt.accel_step_s;
  const std::vector<Envelope> env = envelopes(elements, out.start_j2000_s, opt, &out.envelopes_sampled);
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const sgp4::MeanElements& m = elements[k];
    SpaceObject obj;
    const std::string why = accept(*motion, m, out.start_j2000_s, opt, env[k], obj);
    if (!why.empty()) {
      out.rejected.push_back(RejectedElementSet{m.norad_id, m.name, why});
      continue;
    }
    out.objects.push_back(obj);
    out.norad_ids.push_back(m.norad_id);
    out.element_index.push_back(k);
  }
  motion->build_lane_groups();
  out.motion = std::move(motion);
  return out;
}

Sgp4Screening sgp4_screening(const std::vector<sgp4::MeanElements>& elements,
                             const Sgp4MotionOptions& opt) {
  return Sgp4CatalogBuilder::build(elements, opt);
}

}  // namespace evade::conjunction
