// What the key-file tests share (key_file_test.cpp, key_file_malformed_lines_test.cpp,
// key_file_no_freed_key_text_test.cpp): two key texts no message may echo, their bytes, the
// check that a text holds neither, and the fixture (a fresh private directory per test).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "auth_file_test_support.hpp"
#include "evade/auth/key_file.hpp"
#include "evade/auth/keyring.hpp"

namespace evade::auth::test {

// 64 hex digits (32 distinct byte values) that appear in no message: key text errors must not echo.
inline std::string hex_a() { return "00112233445566778899aabbccddeeff0123456789abcdef0f1e2d3c4b5a6978"; }
inline std::string hex_b() { return "ffeeddccbbaa99887766554433221100fedcba98765432100123456789abcdef"; }

inline KeyBytes bytes_of(const std::string& hex) {
  KeyBytes k{};
  for (std::size_t i = 0; i < k.size(); ++i) {
    k[i] = static_cast<std::uint8_t>(std::stoul(hex.substr(2 * i, 2), nullptr, 16));
  }
  return k;
}

// Checks that text contains none of the key texts (nor a 16-digit window, either case).
inline void expect_no_key_text(const std::string& text, const std::vector<std::string>& hexes,
                               const std::string& what) {
  for (const std::string& h : hexes) {
    EXPECT_EQ(key_text_in(text, h), "") << what << ": " << text;
  }
}

using KeyFile = TempDir;

}  // namespace evade::auth::test
