// HMAC-SHA-256, key derivation and key check values through libsodium
// (include/evade/auth/mac.hpp; docs/SECURITY.md AUTH-1, AUTH-4, KEY-1).
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

KeyBytes derive_subkey(const KeyBytes& master, std::uint64_t subkey_id,
                       const char (&context)[9]) noexcept {
  static_assert(crypto_kdf_KEYBYTES == kKeyBytes, "a master key is an evade key");
  static_assert(crypto_kdf_CONTEXTBYTES == sizeof(context) - 1, "8 characters and the NUL");
  static_assert(kKeyBytes >= crypto_kdf_BYTES_MIN && kKeyBytes <= crypto_kdf_BYTES_MAX,
                "libsodium derives 32-byte subkeys");
  KeyBytes out{};
  if (crypto_kdf_derive_from_key(out.data(), out.size(), subkey_id, context, master.data()) != 0) {
    out.fill(0);  // refused: the documented all-zero subkey, which every caller refuses
  }
  return out;
}

KeyCheckValue key_check_value(const KeyBytes& key) noexcept {
  static const char kLabel[] = "evade key check value";
  Mac full = hmac_sha256(key.data(), key.size(), reinterpret_cast<const std::uint8_t*>(kLabel),
                         sizeof(kLabel) - 1);
  KeyCheckValue kcv{};
  (void)std::memcpy(kcv.data(), full.data(), kcv.size());  // returns its destination
  sodium_memzero(full.data(), full.size());
  return kcv;
}

}  // namespace evade::auth
