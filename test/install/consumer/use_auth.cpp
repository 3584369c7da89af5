// evade::auth: HMAC-SHA-256 of RFC 4231 test case 2 (key "Jefe").
#include <cstdio>
#include <cstring>

#include <evade/auth/mac.hpp>

int main() {
  const char* key = "Jefe";
  const char* msg = "what do ya want for nothing?";
  const evade::auth::Mac m = evade::auth::hmac_sha256(
      reinterpret_cast<const std::uint8_t*>(key), std::strlen(key),
      reinterpret_cast<const std::uint8_t*>(msg), std::strlen(msg));
  if (m[0] != 0x5b || m[1] != 0xdc || m[31] != 0x43) return 1;
  std::printf("auth ok\n");
  return 0;
}
