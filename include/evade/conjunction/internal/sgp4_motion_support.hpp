// Internal (not installed): what the SGP4 motion's files share (src/conjunction/sgp4_motion.cpp,
// sgp4_motion_envelope.cpp, sgp4_catalog_builder.cpp): the labels of element sets and SGP4
// errors, the perturbation envelope of one element set and the envelopes of a catalog.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "evade/conjunction/sgp4_motion.hpp"

namespace evade::conjunction::internal {

inline std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

inline std::string label(long norad, const std::string& name) {
  return "NORAD " + std::to_string(norad) + (name.empty() ? "" : " (" + name + ")");
}

// "SGP4 error N (text)".
inline std::string sgp4_error_label(sgp4::Sgp4Error e) {
  return "SGP4 error " + std::to_string(static_cast<int>(e)) + " (" + sgp4::sgp4_error_text(e) + ")";
}

// Largest angular rate of an orbit, n (1 + e)^2 / (1 - e^2)^1.5 (at perigee) [rad/s].
inline double n_max_radps(const sgp4::MeanElements& m) {
  const double e = std::min(m.eccentricity, 0.99);
  const double n_radps = m.mean_motion_revpday * 2.0 * kPi / 86400.0;
  return n_radps * (1.0 + e) * (1.0 + e) / std::pow(1.0 - e * e, 1.5);
}

// Largest sampled |r'' - a(r)| of one object over [0, span] (t counted from the start) and
// the largest error of those samples, or the first SGP4 error met and its sample time.
struct Envelope {
  double p_max_mps2 = 0.0;
  double error_mps2 = 0.0;
  sgp4::Sgp4Error failure = sgp4::Sgp4Error::kNone;
  double failed_at_s = 0.0;
  std::string reason() const {
    if (failure == sgp4::Sgp4Error::kNone) return {};
    return sgp4_error_label(failure) + " at t = " + fmt(failed_at_s) + " s from the start";
  }
};

// The perturbation envelopes of a catalog's element sets (sgp4_motion_envelope.cpp).
std::vector<Envelope> envelopes(const std::vector<sgp4::MeanElements>& elements, double start_s,
                                const Sgp4MotionOptions& opt, long* sampled);

}  // namespace evade::conjunction::internal
