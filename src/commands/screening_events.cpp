// Screening events as CDM inputs (see screening_events.hpp): states at the TCA in EME2000.
#include "evade/commands/screening_events.hpp"

#include <cctype>
#include <map>

#include "evade/conjunction/event_states.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"

namespace evade::commands {

using commands::EventObject;
using commands::ScreeningEvent;

std::string ccsds_international_designator(const std::string& id) {
  if (id.size() >= 6 && id[2] != '-' && std::isdigit(static_cast<unsigned char>(id[0])) &&
      std::isdigit(static_cast<unsigned char>(id[1]))) {
    const int yy = std::stoi(id.substr(0, 2));
    return std::to_string(yy < 57 ? 2000 + yy : 1900 + yy) + "-" + id.substr(2);
  }
  return id;
}

std::vector<ScreeningEvent> object_screening_events(const std::vector<conjunction::Conjunction>& events,
                                                    const std::vector<conjunction::SpaceObject>& objects,
                                                    const conjunction::ScreenOptions& so,
                                                    double epoch_utc_j2000_s) {
  const std::string how = so.gravity == GravityModel::kTwoBody
                              ? "state at TCA by two-body motion (Kepler) from the screening epoch; EME2000 = evade's ECI"
                              : "state at TCA by two-body + J2 motion (DOP853) from the screening epoch; EME2000 = evade's ECI";
  std::vector<ScreeningEvent> out;
  out.reserve(events.size());
  for (const auto& c : events) {
    const auto st = conjunction::event_states(objects, c, so);
    ScreeningEvent ev;
    const std::size_t idx[2] = {c.i, c.j};
    for (int k = 0; k < 2; ++k) {
      EventObject& ob = ev.obj[k];
      ob.designator = ob.name = objects[idx[k]].name;
      ob.catalog_name = "EVADE";
      ob.state_eme2000 = st[k];
      ob.radius_m = objects[idx[k]].size_m;
      ob.state_comment = how;
    }
    ev.tca_utc_j2000_s = c.tca_s + epoch_utc_j2000_s;
    ev.miss_m = c.miss_m;
    ev.rel_speed_mps = c.rel_speed_mps;
    out.push_back(std::move(ev));
  }
  return out;
}

std::vector<ScreeningEvent> catalog_screening_events(const std::vector<conjunction::Conjunction>& events,
                                                     const conjunction::Sgp4Screening& s,
                                                     const std::vector<sgp4::MeanElements>& elements,
                                                     const conjunction::ScreenOptions& so) {
  std::map<long, const sgp4::MeanElements*> by_id;
  for (const auto& m : elements) by_id.emplace(m.norad_id, &m);
  std::vector<ScreeningEvent> out;
  out.reserve(events.size());
  for (const auto& c : events) {
    const auto st = conjunction::event_states(s.objects, c, so);
    ScreeningEvent ev;
    const std::size_t idx[2] = {c.i, c.j};
    for (int k = 0; k < 2; ++k) {
      EventObject& ob = ev.obj[k];
      const long id = s.norad_ids[idx[k]];
      const sgp4::MeanElements* m = by_id.count(id) ? by_id.at(id) : nullptr;
      ob.designator = std::to_string(id);
      ob.name = m && !m->name.empty() ? m->name : ob.designator;
      ob.international_designator = m ? ccsds_international_designator(m->object_id) : "";
      sgp4::teme_to_j2000(s.start_j2000_s + c.tca_s, st[k].r_eci_m, st[k].v_eci_mps,
                          ob.state_eme2000.r_eci_m, ob.state_eme2000.v_eci_mps);
      ob.state_comment = "state at TCA by SGP4 (TEME, velocity = derivative of the position) "
                         "rotated to EME2000 (IAU-76/80, docs/ASSESSMENT.md)";
    }
    ev.tca_utc_j2000_s = c.tca_s + s.start_j2000_s;
    ev.miss_m = c.miss_m;
    ev.rel_speed_mps = c.rel_speed_mps;
    out.push_back(std::move(ev));
  }
  return out;
}

}  // namespace evade::commands
