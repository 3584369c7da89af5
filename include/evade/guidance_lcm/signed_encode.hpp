// Signing an LCM message (docs/SECURITY.md AUTH-1): fills the message's security trailer
// (evade_auth_t auth, its last field) with the key id and the ARSN, encodes it, and writes the
// HMAC-SHA-256 of the encoding and the channel name into the trailer's MAC bytes. For every
// signer: the ground's commands (`evade plan --publish`, `evade arm`), the simulator's sensors
// (`evade sim --lcm --key`), a flight-software integrator's own sensor, the tests. No
// allocation, no exceptions.
//
// ArsnClock gives each signer's ARSNs: its CLOCK_REALTIME in microseconds, forced strictly
// increasing. A time base needs no counter file on the signer's side, survives the signer's
// restarts, and exceeds the node's sensor floor (its start time) for sensors.
#pragma once

#include <time.h>

#include <cstdint>
#include <cstring>

#include "evade/auth/mac.hpp"
#include "evade/auth/trailer.hpp"

namespace evade::guidance_lcm {

/// A signer's key: its id (the security association) and its bytes.
struct SigningKey {
  std::int32_t id = 0;
  auth::KeyBytes key{};
};

/// Encodes *m signed for channel into buf[0, cap). Returns the byte count, or < 0 when the
/// message does not fit or is too short to carry a trailer.
template <typename Msg>
int encode_signed(Msg* m, const char* channel, const SigningKey& key, std::int64_t arsn,
                  std::uint8_t* buf, int cap) noexcept {
  m->auth.key_id = key.id;
  m->auth.arsn = arsn;
  std::memset(m->auth.mac, 0, sizeof(m->auth.mac));
  const int n = m->encode(buf, 0, cap);
  if (n < 0) return n;
  if (!auth::sign_encoded(key.key, channel, buf, static_cast<std::size_t>(n))) return -1;
  std::memcpy(m->auth.mac, buf + (n - static_cast<int>(auth::kMacBytes)), auth::kMacBytes);
  return n;
}

/// Strictly increasing ARSNs from CLOCK_REALTIME [us].
class ArsnClock {
 public:
  std::int64_t next() noexcept {
    timespec ts{};
    (void)clock_gettime(CLOCK_REALTIME, &ts);  // CLOCK_REALTIME always exists: cannot fail
    const std::int64_t now = static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
    last_ = now > last_ ? now : last_ + 1;
    return last_;
  }

 private:
  std::int64_t last_ = 0;
};

}  // namespace evade::guidance_lcm
