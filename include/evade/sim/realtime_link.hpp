// The real-time simulator's view of the guidance (realtime_simulator.hpp): a wall clock, the
// sensor box's and the navigation's outputs, and the commands the guidance sends on its own
// schedule. Unlike GuidanceEndpoint there is no exchange: the guidance runs at its own fixed
// rate and the simulator applies the newest command it has received (zero-order hold).
// The LCM implementation is evade::lcm_link::make_realtime_lcm_link; nothing here knows LCM.
//
// Time base: every utime here is the run's wall clock in µs, the same clock the guidance
// stamps its cycles with (for the LCM link: CLOCK_REALTIME µs; docs/VALIDATION.md, paper
// 000, "Real-time HIL").
#pragma once

#include <cstdint>

#include "evade/guidance/guidance_law.hpp"

namespace evade::sim {

/// A command as received: the guidance's own time stamp is cmd.utime_us (its cycle time).
struct ReceivedCommand {
  guidance::ThrustCommand cmd;
  std::int64_t received_utime_us = 0;  ///< wall clock when the simulator received it
};

class RealtimeLink {
 public:
  virtual ~RealtimeLink() = default;
  /// The wall clock now [µs].
  virtual std::int64_t now_us() = 0;
  /// Blocks until the wall clock reaches until_utime_us or a new command has been received,
  /// whichever is first. Returns true if a new command is waiting (take_newest_command).
  virtual bool wait_for_command(std::int64_t until_utime_us) = 0;
  /// The newest command received since the last call (older ones in between are replaced:
  /// zero-order hold of the newest). False if none arrived since.
  virtual bool take_newest_command(ReceivedCommand* out) = 0;
  /// Publishes the navigation state (time of validity nav.utime_us).
  virtual void send_nav(const guidance::NavState& nav) = 0;
  /// Publishes a measurement (time of validity meas.utime_us; sent when it is delivered).
  virtual void send_measurement(const guidance::AnglesMeasurement& meas) = 0;
  /// Latest guidance status if the link can see it.
  virtual bool status(guidance::GuidanceStatus* out) const {
    (void)out;
    return false;
  }
  /// Commands received in total (including those replaced before they were taken).
  virtual long commands_received() const = 0;
  /// Commands discarded on receipt because they were not newer than the newest one already
  /// received (duplicated or overtaken on the network): never applied.
  virtual long commands_discarded_old() const { return 0; }
  /// Commands discarded on receipt because they failed decoding or validation: never applied.
  virtual long commands_discarded_malformed() const { return 0; }
};

}  // namespace evade::sim
