// The truth geometry of one history row (range, range rate, true LOS rate and e_θ with the
// zenith convention), shared by the lockstep loop (simulator.cpp) and the real-time loop
// (realtime_simulator.cpp).
#pragma once

#include "evade/sim/simulator.hpp"

namespace evade::sim {

/// A SimSample holding only the truth at t_s (from the epoch); the measurement, command,
/// applied acceleration and status are left for the caller.
SimSample truth_sample(double t_s, const StateEci& satellite, const StateEci& debris);

}  // namespace evade::sim
