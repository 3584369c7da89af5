// The security trailer on the wire (lcm_types/evade_auth_t.lcm, docs/SECURITY.md AUTH-1): every
// signed LCM type declares `evade_auth_t auth` as its last field, and LCM encodes a nested
// struct without a fingerprint, so the last kTrailerBytes of the message are
//   key_id (int32, big-endian) | arsn (int64, big-endian) | mac (32 bytes)
// and the MAC covers every byte before it (fingerprint, fields, key_id, arsn) plus the channel
// name. The node reads the key id and the ARSN from these bytes and checks the MAC before it
// decodes anything. Pure byte functions: no LCM, no allocation, no exceptions.
#pragma once

#include <cstddef>
#include <cstdint>

#include "evade/auth/mac.hpp"

namespace evade::auth {

inline constexpr std::size_t kTrailerBytes = 4 + 8 + kMacBytes;  ///< 44
/// Smallest signed message: the 8-byte LCM fingerprint and the trailer.
inline constexpr std::size_t kMinSignedBytes = 8 + kTrailerBytes;

struct TrailerView {
  std::int32_t key_id = 0;
  std::int64_t arsn = 0;
  const std::uint8_t* mac = nullptr;  ///< kMacBytes inside the message
};

/// The trailer of an encoded message. False (and *out untouched) when size < kMinSignedBytes.
bool read_trailer(const std::uint8_t* data, std::size_t size, TrailerView* out) noexcept;

/// Writes the MAC of data[0, size - kMacBytes) on channel into the last kMacBytes of data (the
/// key id and ARSN must already be encoded). False when size < kMinSignedBytes.
bool sign_encoded(const KeyBytes& key, const char* channel, std::uint8_t* data,
                  std::size_t size) noexcept;

/// True when the last kMacBytes of data are the MAC of the rest on channel under key
/// (constant-time comparison). False when size < kMinSignedBytes.
bool mac_valid(const KeyBytes& key, const char* channel, const std::uint8_t* data,
               std::size_t size) noexcept;

}  // namespace evade::auth
