// HMAC-SHA-256 through libsodium (include/evade/auth/mac.hpp).
#include "evade/auth/mac.hpp"

#include <cstring>

#include <sodium.h>

namespace evade::auth {

bool crypto_ready() noexcept { return sodium_init() >= 0; }

Mac hmac_sha256(const std::uint8_t* key, std::size_t key_len, const std::uint8_t* msg,
                std::size_t len) noexcept {
  Mac out{};
  crypto_auth_hmacsha256_state st;
  // libsodium's HMAC functions return 0 and have no failure path (they only hash); the
  // results are checked all the same, and a failure gives an all-zero MAC that verifies
  // nothing (a signed message's MAC is never all zero but with probability 2^-256).
  if (crypto_auth_hmacsha256_init(&st, key, key_len) != 0 ||
      crypto_auth_hmacsha256_update(&st, msg, len) != 0 ||
      crypto_auth_hmacsha256_final(&st, out.data()) != 0) {
    out.fill(0);
  }
  sodium_memzero(&st, sizeof(st));
  return out;
}

Mac channel_mac(const KeyBytes& key, const char* channel, const std::uint8_t* body,
                std::size_t len) noexcept {
  Mac out{};
  const std::size_t n = channel == nullptr ? 0 : strnlen(channel, kMaxChannelChars);
  const std::uint8_t zero = 0;
  crypto_auth_hmacsha256_state st;
  if (crypto_auth_hmacsha256_init(&st, key.data(), key.size()) != 0 ||
      crypto_auth_hmacsha256_update(&st, reinterpret_cast<const std::uint8_t*>(channel), n) != 0 ||
      crypto_auth_hmacsha256_update(&st, &zero, 1) != 0 ||
      crypto_auth_hmacsha256_update(&st, body, len) != 0 ||
      crypto_auth_hmacsha256_final(&st, out.data()) != 0) {
    out.fill(0);
  }
  sodium_memzero(&st, sizeof(st));
  return out;
}

bool mac_equal(const std::uint8_t* a, const std::uint8_t* b) noexcept {
  return sodium_memcmp(a, b, kMacBytes) == 0;
}

bool random_bytes(std::uint8_t* out, std::size_t n) noexcept {
  if (!crypto_ready()) return false;
  randombytes_buf(out, n);
  return true;
}

void wipe(void* p, std::size_t n) noexcept { sodium_memzero(p, n); }

}  // namespace evade::auth
