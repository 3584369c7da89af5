// NodeConfig parameter table (include/evade/guidance_lcm/node_params.hpp).
#include "evade/guidance_lcm/node_params.hpp"

namespace evade::guidance_lcm {
namespace {

using C = NodeConfig;

const Param<C> kRows[] = {
    EVADE_PARAM_REAL(C, future_tolerance_s, "s", 0.0, 10.0, false,
                     "accept an input stamped up to this far in the future (clock skew)"),
    with_flag(EVADE_PARAM_INT(C, queue_capacity, "-", 1, 4096,
                              "bounded input queue: the oldest message is dropped (and counted) beyond it"),
              "--queue-capacity", "--queue"),
    EVADE_PARAM_INT(C, max_drain_per_cycle, "-", 1, 1000000,
                    "LCM messages handled per drain (bounds one cycle's input work)"),
    EVADE_PARAM_REAL(C, max_drain_s, "s", 0.0, 1.0, true,
                     "wall time one drain may take; what is left waits in LCM's queue for the "
                     "next cycle (bounds the cycle's input work in time under a flood)"),
    with_flag(EVADE_PARAM_INT(C, status_divider, "-", 1, 10000, "publish the status every N cycles"),
              "--status-divider"),
    EVADE_PARAM_INT(C, recv_buf_bytes, "B", 65536, 1073741824,
                    "kernel UDP receive buffer requested for a udpm:// input (NODE-IN-6)"),
    EVADE_PARAM_INT(C, max_seq_jump, "-", 1, 1000000,
                    "largest plausible forward seq step; beyond it a sender restart must be "
                    "confirmed by the next message (NODE-IN-4)"),
    EVADE_PARAM_BOOL(C, auth.plan_required,
                     "EVADE_BURN_PLAN messages must be signed by an active command key (AUTH-2)"),
    EVADE_PARAM_BOOL(C, auth.arm_required,
                     "EVADE_ARM messages must be signed by an active command key (AUTH-2)"),
    EVADE_PARAM_BOOL(C, auth.nav_required,
                     "EVADE_NAV messages must be signed by a sensor key (AUTH-3)"),
    EVADE_PARAM_BOOL(C, auth.angles_required,
                     "EVADE_ANGLES messages must be signed by a sensor key (AUTH-3)"),
    EVADE_PARAM_BOOL(C, auth.clock_required,
                     "EVADE_SIM_CLOCK ticks must be signed by a sensor key (AUTH-3)"),
    EVADE_PARAM_INT(C, auth.verify_per_cycle_command, "-", 1, 100000,
                    "MAC verifications per cycle on each command channel (plan, arm, key "
                    "command); messages past it are dropped and counted (verify_budget, AUTH-5)"),
    EVADE_PARAM_INT(C, auth.verify_per_cycle_sensor, "-", 1, 100000,
                    "MAC verifications per cycle on each sensor channel (nav, angles, sim "
                    "clock); messages past it are dropped and counted (verify_budget, AUTH-5)"),
};

}  // namespace

ParamTable<NodeConfig> node_params() noexcept { return make_param_table(kRows); }

}  // namespace evade::guidance_lcm
