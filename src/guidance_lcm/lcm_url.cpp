// LCM URL with the node's receive buffer (include/evade/guidance_lcm/lcm_url.hpp).
#include "evade/guidance_lcm/lcm_url.hpp"

namespace evade::guidance_lcm {

std::string lcm_url_with_recv_buf(const std::string& url, const char* env_default_url,
                                  std::size_t recv_buf_bytes) {
  std::string u = url;
  if (u.empty()) {
    u = (env_default_url != nullptr && *env_default_url != '\0') ? env_default_url
                                                                  : kLcmDefaultUrl;
  }
  if (u.rfind("udpm://", 0) != 0) return u;
  if (u.find("recv_buf_size=") != std::string::npos) return u;  // the user's choice wins
  u += (u.find('?') == std::string::npos) ? "?" : "&";
  u += "recv_buf_size=" + std::to_string(recv_buf_bytes);
  return u;
}

}  // namespace evade::guidance_lcm
