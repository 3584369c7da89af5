// The simulator's command filter (include/evade/lcm_link/internal/command_filter.hpp).
#include "evade/lcm_link/internal/command_filter.hpp"

#include <cstdio>

#include "evade/evade_thrust_cmd_t.hpp"
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::lcm_link {

CommandVerdict receive_command(const lcm_recv_buf_t* rbuf, bool* have_last,
                               std::int64_t* last_seq, guidance::ThrustCommand* out) noexcept {
  evade_thrust_cmd_t m{};
  if (m.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) !=
      static_cast<int>(rbuf->data_size)) {
    return CommandVerdict::kMalformed;
  }
  const guidance_lcm::Reason r = guidance_lcm::validate(m);
  if (r != guidance_lcm::Reason::kOk) {
    // A diagnostic only: the command is rejected whether or not stderr takes the line.
    (void)std::fprintf(stderr, "evade sim: rejected a malformed command from the node (%s)\n",
                       guidance_lcm::reason_name(r));
    return CommandVerdict::kMalformed;
  }
  if (*have_last && m.seq <= *last_seq) return CommandVerdict::kOld;
  *have_last = true;
  *last_seq = m.seq;
  guidance_lcm::from_lcm(m, out);
  return CommandVerdict::kAccepted;
}

}  // namespace evade::lcm_link
