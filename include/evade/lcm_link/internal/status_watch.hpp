// The newest evade_guidance_status_t the node published, decoded in LCM's callback (bytes
// only: nothing throws through LCM's C dispatch). Subscribe with
//   lcm_subscribe(lcm, channel, &StatusWatch::on_status, &watch);
#pragma once

#include <lcm/lcm.h>

#include "evade/evade_guidance_status_t.hpp"

namespace evade::lcm_link {

struct StatusWatch {
  evade_guidance_status_t last{};
  bool have = false;  ///< a whole, well-formed status has arrived

  static void on_status(const lcm_recv_buf_t* rbuf, const char*, void* user) {
    auto* self = static_cast<StatusWatch*>(user);
    evade_guidance_status_t m{};
    if (m.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) ==
        static_cast<int>(rbuf->data_size)) {
      self->last = m;
      self->have = true;
    }
  }
};

}  // namespace evade::lcm_link
