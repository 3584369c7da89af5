// The tracked conjunctions (include/evade/autonomy/event_table.hpp).
#include "evade/autonomy/event_table.hpp"

namespace evade::autonomy {

std::size_t EventTable::find(std::int64_t event_id) const noexcept {
  for (std::size_t i = 0; i < kMaxEvents; ++i) {
    if (slots_[i].used && slots_[i].event.event_id == event_id) return i;
  }
  return kMaxEvents;
}

std::size_t EventTable::size() const noexcept {
  std::size_t n = 0;
  for (const Slot& s : slots_) n += s.used ? 1U : 0U;
  return n;
}

InsertResult EventTable::insert(const ConjunctionEvent& e, std::int64_t now_us,
                                std::size_t* slot) noexcept {
  std::size_t i = find(e.event_id);
  if (i < kMaxEvents) {
    Slot& s = slots_[i];
    if (e.version == s.event.version && same_event(e, s.event)) return InsertResult::kSameVersion;
    if (e.version <= s.event.version) return InsertResult::kNotNewer;
    s.superseded_version = s.event.version;
    s.event = e;
    if (slot != nullptr) *slot = i;
    return InsertResult::kNewVersion;
  }
  for (i = 0; i < kMaxEvents && slots_[i].used && slots_[i].event.tca_us >= now_us; ++i) {
  }
  if (i == kMaxEvents) return InsertResult::kTableFull;
  slots_[i] = Slot{true, e, 0};
  if (slot != nullptr) *slot = i;
  return InsertResult::kNew;
}

std::size_t EventTable::expire(std::int64_t now_us) noexcept {
  std::size_t n = 0;
  for (Slot& s : slots_) {
    if (s.used && s.event.tca_us < now_us) {
      s.used = false;
      ++n;
    }
  }
  return n;
}

}  // namespace evade::autonomy
