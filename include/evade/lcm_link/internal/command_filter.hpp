// Internal (not installed): how the simulator's side of the LCM link takes a command from
// evade_guidance_node, in lockstep and in real time alike (GUIDANCE_NODE.md NODE-IN-2): the
// message must decode exactly, pass validation (never thrust from a malformed command: it is
// reported on stderr and the previous command stays in force) and be newer than the last
// accepted one (duplicates and old ones are ignored).
#pragma once

#include <cstdint>

#include <lcm/lcm.h>

#include "evade/guidance/guidance_law.hpp"

namespace evade::lcm_link {

enum class CommandVerdict { kAccepted, kMalformed, kOld };

/// On kAccepted, *out holds the command and (*have_last, *last_seq) the new last seq.
CommandVerdict receive_command(const lcm_recv_buf_t* rbuf, bool* have_last,
                               std::int64_t* last_seq, guidance::ThrustCommand* out) noexcept;

}  // namespace evade::lcm_link
