// Security trailer byte layout (include/evade/auth/trailer.hpp).
#include "evade/auth/trailer.hpp"

#include <cstring>

namespace evade::auth {
namespace {

std::uint64_t big_endian(const std::uint8_t* p, int bytes) noexcept {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8U) | p[i];
  return v;
}

}  // namespace

bool read_trailer(const std::uint8_t* data, std::size_t size, TrailerView* out) noexcept {
  if (data == nullptr || out == nullptr || size < kMinSignedBytes) return false;
  const std::uint8_t* t = data + (size - kTrailerBytes);
  // Two's complement reinterpretation of the wire's unsigned bit patterns (LCM encodes signed
  // integers as their two's complement, big-endian).
  out->key_id = static_cast<std::int32_t>(static_cast<std::uint32_t>(big_endian(t, 4)));
  out->arsn = static_cast<std::int64_t>(big_endian(t + 4, 8));
  out->mac = t + 12;
  return true;
}

bool sign_encoded(const KeyBytes& key, const char* channel, std::uint8_t* data,
                  std::size_t size) noexcept {
  if (data == nullptr || size < kMinSignedBytes) return false;
  const Mac m = channel_mac(key, channel, data, size - kMacBytes);
  std::memcpy(data + (size - kMacBytes), m.data(), kMacBytes);
  return true;
}

bool mac_valid(const KeyBytes& key, const char* channel, const std::uint8_t* data,
               std::size_t size) noexcept {
  if (data == nullptr || size < kMinSignedBytes) return false;
  const Mac m = channel_mac(key, channel, data, size - kMacBytes);
  return mac_equal(m.data(), data + (size - kMacBytes));
}

}  // namespace evade::auth
