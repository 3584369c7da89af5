// The ground's verified view of the node's telemetry (include/evade/lcm_link/internal/
// telemetry_watch.hpp).
#include "evade/lcm_link/internal/telemetry_watch.hpp"

#include "evade/auth/trailer.hpp"

namespace evade::lcm_link {

bool telemetry_authentic(const guidance_lcm::SigningKey& key, const char* channel,
                         const std::uint8_t* data, std::size_t size) noexcept {
  auth::TrailerView t;
  if (key.id == 0 || !auth::read_trailer(data, size, &t) || t.key_id != key.id) return false;
  return auth::mac_valid(key.key, channel, data, size);
}


void TelemetryWatch::on_ack(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept {
  auto* w = static_cast<TelemetryWatch*>(user);
  evade_cmd_ack_t m{};
  if (!decode_verified(w->key, rbuf, channel, &m) || w->n_acks == kMaxAcks) {
    ++w->ignored;
    return;
  }
  ++w->acks_verified;
  w->acks[w->n_acks++] = m;
}

void TelemetryWatch::on_status(const lcm_recv_buf_t* rbuf, const char* channel,
                               void* user) noexcept {
  auto* w = static_cast<TelemetryWatch*>(user);
  evade_guidance_status_t m{};
  if (!decode_verified(w->key, rbuf, channel, &m)) {
    ++w->ignored;
    return;
  }
  ++w->status_verified;
  w->status = m;
  w->have_status = true;
}

void TelemetryWatch::on_proposal(const lcm_recv_buf_t* rbuf, const char* channel,
                                 void* user) noexcept {
  auto* w = static_cast<TelemetryWatch*>(user);
  evade_cam_proposal_t m{};
  if (!decode_verified(w->key, rbuf, channel, &m)) {
    ++w->ignored;
    return;
  }
  ++w->proposals_verified;
  if (w->proposal_event == 0 || m.event_id != w->proposal_event) return;
  w->proposal = m;
  w->have_proposal = true;
}

}  // namespace evade::lcm_link
