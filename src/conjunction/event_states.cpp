// States of an event's two objects at its TCA (include/evade/conjunction/event_states.hpp).
#include "evade/conjunction/event_states.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "evade/conjunction/ephemeris.hpp"

namespace evade::conjunction {

std::array<StateEci, 2> event_states(const std::vector<SpaceObject>& objects,
                                     const Conjunction& c, const ScreenOptions& opt) {
  if (c.i >= objects.size() || c.j >= objects.size())
    throw std::invalid_argument("event_states: object index " + std::to_string(std::max(c.i, c.j)) +
                                " out of range (" + std::to_string(objects.size()) + " objects)");
  if (opt.motion) return {opt.motion->state_at(c.i, c.tca_s), opt.motion->state_at(c.j, c.tca_s)};
  Ephemeris eph({objects[c.i], objects[c.j]}, opt.gravity, opt.earth, opt.integ);
  std::vector<StateEci> s;
  eph.states_at(c.tca_s, s);
  return {s[0], s[1]};
}

}  // namespace evade::conjunction
