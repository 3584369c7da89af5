// The conjunctions the node tracks (docs/AUTONOMY.md AUT-1): a fixed table of kMaxEvents
// slots. An uplinked event goes into the slot of its id when its version is newer (the older
// version is superseded and reported), into a free slot when its id is new, or, when every slot
// is taken, into the slot of an event that is over (TCA passed); a table of live events refuses
// it (table_full). The tracked version again, field for field, is a retransmission (same_version). Flight code: no allocation, no exceptions, loops bounded by kMaxEvents.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "evade/autonomy/conjunction_event.hpp"

namespace evade::autonomy {

inline constexpr std::size_t kMaxEvents = 8;

enum class InsertResult : std::uint8_t {
  kNew = 0,        ///< a new event id in a slot of its own
  kNewVersion,     ///< a newer version replaced the slot's older one (superseded)
  kNotNewer,       ///< the event id is tracked with this version or a newer one: refused
  kSameVersion,    ///< the very event tracked, sent again (a retransmission): nothing changes
  kTableFull,      ///< every slot holds a live event: refused
};

class EventTable {
 public:
  struct Slot {
    bool used = false;
    ConjunctionEvent event{};
    std::int32_t superseded_version = 0;  ///< kNewVersion: the version it replaced
  };

  /// Puts e in (see the file comment); *slot (if given) is its slot index on kNew/kNewVersion.
  InsertResult insert(const ConjunctionEvent& e, std::int64_t now_us,
                      std::size_t* slot = nullptr) noexcept;
  /// Frees the slots whose TCA is before now_us; returns how many.
  std::size_t expire(std::int64_t now_us) noexcept;
  void release(std::size_t i) noexcept { slots_[i].used = false; }

  const Slot& slot(std::size_t i) const noexcept { return slots_[i]; }
  std::size_t size() const noexcept;
  /// The slot of event_id, or kMaxEvents when it is not tracked.
  std::size_t find(std::int64_t event_id) const noexcept;

 private:
  std::array<Slot, kMaxEvents> slots_{};
};

}  // namespace evade::autonomy
