// HMAC-SHA-256 (H. Krawczyk, M. Bellare, R. Canetti, "HMAC: Keyed-Hashing for Message
// Authentication", RFC 2104, 1997; FIPS 198-1) through libsodium, the message authentication
// code of evade's command link (docs/SECURITY.md). libsodium is Debian's libsodium-dev: a small,
// audited library whose HMAC-SHA-256, constant-time comparison (sodium_memcmp) and system random
// generator (randombytes_buf) are all this needs; no primitive is written here. The MAC of a
// message on an LCM channel binds the channel name (channel_mac), so a message signed for one
// channel fails on any other. Subkeys for other purposes (the node's state file, AUTH-4) come
// from libsodium's key derivation, and a key is named by its check value (key_check_value)
// where its bytes must not appear. Nothing here allocates or throws.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace evade::auth {

inline constexpr std::size_t kMacBytes = 32;  ///< HMAC-SHA-256 output, untruncated
inline constexpr std::size_t kKeyBytes = 32;  ///< evade keys: 256 random bits
inline constexpr std::size_t kMaxChannelChars = 63;  ///< LCM's channel name limit

using Mac = std::array<std::uint8_t, kMacBytes>;
using KeyBytes = std::array<std::uint8_t, kKeyBytes>;

/// Initializes libsodium once (thread-safe, idempotent). False if it cannot (then no key may be
/// generated; HMAC itself needs no initialization).
bool crypto_ready() noexcept;

/// HMAC-SHA-256 of msg[0, len) under a key of any length (RFC 4231 uses 4 to 131 bytes).
Mac hmac_sha256(const std::uint8_t* key, std::size_t key_len, const std::uint8_t* msg,
                std::size_t len) noexcept;

/// The link MAC: HMAC-SHA-256(key, channel || 0x00 || body[0, len)). A channel name longer
/// than kMaxChannelChars is cut there (LCM refuses such names anyway).
Mac channel_mac(const KeyBytes& key, const char* channel, const std::uint8_t* body,
                std::size_t len) noexcept;

/// Constant-time comparison of two kMacBytes-long MACs (sodium_memcmp).
bool mac_equal(const std::uint8_t* a, const std::uint8_t* b) noexcept;

/// Fills out with n bytes from the operating system's random generator (randombytes_buf).
/// False if libsodium could not be initialized.
bool random_bytes(std::uint8_t* out, std::size_t n) noexcept;

/// Overwrites n bytes so that the compiler cannot elide it (sodium_memzero).
void wipe(void* p, std::size_t n) noexcept;

/// A subkey of master for one purpose (libsodium's crypto_kdf_derive_from_key: BLAKE2b keyed
/// with master, salted with subkey_id, personalized with the 8-character context): knowing a
/// subkey reveals neither master nor any other subkey. All zero if libsodium refuses (it does
/// not for 32-byte subkeys); a caller refuses an all-zero subkey (key_weakness). The caller
/// wipes the subkey after use.
KeyBytes derive_subkey(const KeyBytes& master, std::uint64_t subkey_id,
                       const char (&context)[9]) noexcept;

inline constexpr std::size_t kCheckValueBytes = 8;
using KeyCheckValue = std::array<std::uint8_t, kCheckValueBytes>;

/// The key's check value: the first 8 bytes of HMAC-SHA-256(key, "evade key check value").
/// It tells keys apart (a state file names the keys it was written for) without revealing
/// them: finding the key from it is inverting HMAC-SHA-256.
KeyCheckValue key_check_value(const KeyBytes& key) noexcept;

}  // namespace evade::auth
