// Reads typed values from fuzz bytes (little-endian, raw: a double can be NaN, Inf or a
// denormal); past the end every read gives zero bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace evade::fuzz {

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  template <typename T>
  T get() {
    unsigned char buf[sizeof(T)] = {};
    const std::size_t n = pos_ < size_ ? (size_ - pos_ < sizeof(T) ? size_ - pos_ : sizeof(T)) : 0;
    if (n > 0) std::memcpy(buf, data_ + pos_, n);
    pos_ += sizeof(T);
    T v;
    std::memcpy(&v, buf, sizeof(T));
    return v;
  }
  bool flag() { return (get<std::uint8_t>() & 1U) != 0; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace evade::fuzz
