// LCM channel names used by the guidance node and the simulator link (docs/GUIDANCE_NODE.md
// NODE-IF-1). The node subscribes and publishes through the C API with these C strings.
#pragma once

namespace evade::guidance_lcm {

inline constexpr const char* kChanAngles = "EVADE_ANGLES";        ///< evade_angles_t, in
inline constexpr const char* kChanNav = "EVADE_NAV";              ///< evade_nav_state_t, in
inline constexpr const char* kChanArm = "EVADE_ARM";              ///< evade_arm_t, in
inline constexpr const char* kChanPlan = "EVADE_BURN_PLAN";   ///< evade_burn_plan_t, in
inline constexpr const char* kChanClock = "EVADE_SIM_CLOCK";      ///< evade_sim_clock_t, in
inline constexpr const char* kChanKeyCmd = "EVADE_KEY_CMD";       ///< evade_key_cmd_t, in
inline constexpr const char* kChanConjunction = "EVADE_CONJUNCTION";  ///< evade_conjunction_t, in
inline constexpr const char* kChanCamDecision = "EVADE_CAM_DECISION"; ///< evade_cam_decision_t, in
inline constexpr const char* kChanCmd = "EVADE_THRUST_CMD";       ///< evade_thrust_cmd_t, out
inline constexpr const char* kChanStatus = "EVADE_GUID_STATUS";   ///< evade_guidance_status_t, out
inline constexpr const char* kChanCmdAck = "EVADE_CMD_ACK";       ///< evade_cmd_ack_t, out
inline constexpr const char* kChanCamProposal = "EVADE_CAM_PROPOSAL"; ///< evade_cam_proposal_t, out

}  // namespace evade::guidance_lcm
