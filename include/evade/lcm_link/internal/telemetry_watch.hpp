// Internal (not installed): the ground's receiver of the node's telemetry (docs/SECURITY.md
// TM-1..3). Every evade_cmd_ack_t and evade_guidance_status_t is verified under the telemetry
// key before anything in it is read: the MAC over the channel name and the message (the node
// signs both, auth::channel_mac), the key id of the trailer, then an exact decode. What fails is
// counted (ignored) and never looked at: a peer on the bus cannot make the ground believe a
// command was accepted or refused. Verified acknowledgements are kept in arrival order (at most
// kMaxAcks between two looks; the rest are counted ignored), the newest verified status is kept,
// and the newest verified proposal of the conjunction the ground asks about (proposal_event).
// The callbacks run inside LCM's C dispatch: nothing in them throws.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <lcm/lcm.h>

#include "evade/evade_cam_proposal_t.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"

namespace evade::lcm_link {

/// True when data[0, size) carries a trailer of key.id whose MAC is valid on channel.
bool telemetry_authentic(const guidance_lcm::SigningKey& key, const char* channel,
                         const std::uint8_t* data, std::size_t size) noexcept;

/// Decodes rbuf into *m when it is authentic under key on channel and decodes exactly.
template <typename Msg>
bool decode_verified(const guidance_lcm::SigningKey& key, const lcm_recv_buf_t* rbuf, const char* channel,
                     Msg* m) noexcept {
  const auto* data = static_cast<const std::uint8_t*>(rbuf->data);
  if (!telemetry_authentic(key, channel, data, rbuf->data_size)) return false;
  return m->decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) == static_cast<int>(rbuf->data_size);
}

struct TelemetryWatch {
  static constexpr std::size_t kMaxAcks = 256;

  guidance_lcm::SigningKey key{};
  std::array<evade_cmd_ack_t, kMaxAcks> acks{};
  std::size_t n_acks = 0;          ///< verified acknowledgements not yet taken
  evade_guidance_status_t status{};
  bool have_status = false;        ///< a verified status arrived since the last take
  std::int64_t proposal_event = 0;  ///< the event whose proposals are kept (0: none)
  evade_cam_proposal_t proposal{};
  bool have_proposal = false;      ///< a verified proposal of proposal_event arrived since the last take
  int acks_verified = 0;
  int status_verified = 0;
  int proposals_verified = 0;
  int ignored = 0;

  static void on_ack(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept;
  static void on_status(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept;
  static void on_proposal(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept;
};

}  // namespace evade::lcm_link
