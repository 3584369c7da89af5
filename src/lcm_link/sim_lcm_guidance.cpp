// `evade sim --lcm URL`: the simulation's guidance in evade_guidance_node over LCM
// (sim_lcm_guidance.hpp; paper 000, Yao & Wang 2012).
#include "evade/lcm_link/sim_lcm_guidance.hpp"

#include "evade/lcm_link/command_uplink.hpp"
#include "evade/lcm_link/realtime_lcm_link.hpp"
#include "evade/lcm_link/sim_lcm_endpoint.hpp"

namespace evade::lcm_link {

sim::SimGuidanceLink sim_lcm_guidance(const SimLcmOptions& o) {
  guidance_lcm::SigningKey key;
  if (!o.key_file.empty()) key = load_signing_key(o.key_file, o.key_id, auth::KeyRole::kSensor);
  sim::SimGuidanceLink g;
  g.sensors_signed = !o.key_file.empty();
  if (o.realtime) {
    g.name = "lcm_realtime";
    g.make_realtime_link = [url = o.lcm_url, key]() { return make_realtime_lcm_link(url, key); };
  } else {
    g.name = "lcm";
    g.make_endpoint = [o, key]() {
      return make_lcm_endpoint(o.lcm_url, o.lockstep, o.timeout_s, key);
    };
  }
  return g;
}

}  // namespace evade::lcm_link
