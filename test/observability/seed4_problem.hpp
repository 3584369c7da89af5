// The seed4 problem (paper 004 §3) built in code for the tests, with the numbers of
// scenarios/seed4.yaml.
#pragma once

#include <cmath>

#include "evade/observability/problem.hpp"

namespace evade::observability::test {

inline constexpr double kMu = 3.986004418e14;
inline constexpr double kRe = 6378137.0;
inline constexpr double kPaperThetaRad = -3.231;  // paper's optimum [ε, θ] = [0, −3.231]
inline constexpr double kThetaA = -2.231;         // paper's direction A
inline constexpr double kThetaB = -1.571;         // paper's direction B

inline ObservabilityProblem seed4() {
  ObservabilityProblem p;
  p.n_radps = std::sqrt(kMu / std::pow(kRe + 400e3, 3));
  p.x_chaser_p0 << 79933.5, -57232.0, 0.0, -11.135, 2.38, 0.0;
  p.dv_mps = 3.0;
  p.dt_obs_s = 10.0;
  p.t_obs_s = 1000.0;
  return p;
}

}  // namespace evade::observability::test
