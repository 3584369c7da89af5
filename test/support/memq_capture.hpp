// One memq:// LCM instance with a raw C subscription to one channel, for the tests that
// publish a message and decode what a subscriber received. The callback only copies the
// bytes (nothing can throw through LCM's C dispatch); the test decodes them afterwards.
// (LCM 1.3.1's typed C++ subscription trips UBSan's member-access check inside
// lcm-cpp-impl.hpp, so the C API is used.) memq:// delivers only within one instance: the
// publisher must use get().
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <lcm/lcm.h>

namespace evade::test {

class MemqCapture {
 public:
  explicit MemqCapture(const std::string& channel) : lcm_(lcm_create("memq://")) {
    if (lcm_ != nullptr) sub_ = lcm_subscribe(lcm_, channel.c_str(), &MemqCapture::on_raw, this);
  }
  ~MemqCapture() {
    if (sub_ != nullptr) lcm_unsubscribe(lcm_, sub_);
    if (lcm_ != nullptr) lcm_destroy(lcm_);
  }
  MemqCapture(const MemqCapture&) = delete;
  MemqCapture& operator=(const MemqCapture&) = delete;
  bool good() const { return lcm_ != nullptr && sub_ != nullptr; }
  lcm_t* get() const { return lcm_; }
  /// Delivers everything queued and returns the frames received so far.
  const std::vector<std::vector<std::uint8_t>>& drain() {
    while (lcm_handle_timeout(lcm_, 100) > 0) {
    }
    return frames_;
  }

 private:
  static void on_raw(const lcm_recv_buf_t* rbuf, const char* /*channel*/, void* user) {
    auto* self = static_cast<MemqCapture*>(user);
    const auto* p = static_cast<const std::uint8_t*>(rbuf->data);
    self->frames_.emplace_back(p, p + rbuf->data_size);
  }
  lcm_t* lcm_;
  lcm_subscription_t* sub_ = nullptr;
  std::vector<std::vector<std::uint8_t>> frames_;
};

}  // namespace evade::test
