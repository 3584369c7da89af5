// The guidance node's LCM URL: for the UDP multicast provider, a kernel receive buffer large
// enough for the worst input burst the node documents (docs/GUIDANCE_NODE.md NODE-IN-6), so
// that the kernel does not drop datagrams before the node can count them. Pure string work.
#pragma once

#include <cstddef>
#include <string>

namespace evade::guidance_lcm {

/// LCM's default URL (what lcm_create(NULL) uses without LCM_DEFAULT_URL).
inline constexpr const char* kLcmDefaultUrl = "udpm://239.255.76.67:7667?ttl=0";

/// url ("" = $LCM_DEFAULT_URL, or LCM's default when that is unset too) with
/// recv_buf_size=recv_buf_bytes added when it is a udpm:// URL that does not set it already.
/// Other providers (memq://, file://, ...) are returned as they are.
std::string lcm_url_with_recv_buf(const std::string& url, const char* env_default_url,
                                  std::size_t recv_buf_bytes);

}  // namespace evade::guidance_lcm
