// What the auth file tests share (docs/SECURITY.md KEY-1, AUTH-4, UPLINK-1): a fresh private
// directory per test (mkdtemp, mode 0700, removed afterwards), files written with an exact
// mode, the text of the std::runtime_error a call throws, hex text and the 16-character windows
// of it that no message may contain, and byte-for-byte file reads.
#pragma once

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/auth/mac.hpp"

namespace evade::auth::test {

inline std::string to_hex(const std::uint8_t* b, std::size_t n) {
  static const char* const kDigits = "0123456789abcdef";
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    s.push_back(kDigits[b[i] >> 4U]);
    s.push_back(kDigits[b[i] & 0x0FU]);
  }
  return s;
}
inline std::string to_hex(const KeyBytes& k) { return to_hex(k.data(), k.size()); }

inline std::string upper(std::string s) {
  for (char& ch : s) {
    if (ch >= 'a' && ch <= 'f') ch = static_cast<char>(ch - 'a' + 'A');
  }
  return s;
}

/// The first place in text where hex, or any 16-character window of it, appears in either case
/// ("" when none): what a message that never shows key text must not contain.
inline std::string key_text_in(const std::string& text, const std::string& hex) {
  const std::string lower_text = [&] {
    std::string t = text;
    for (char& ch : t) {
      if (ch >= 'A' && ch <= 'F') ch = static_cast<char>(ch - 'A' + 'a');
    }
    return t;
  }();
  for (std::size_t i = 0; i + 16 <= hex.size(); ++i) {
    if (lower_text.find(hex.substr(i, 16)) != std::string::npos) return hex.substr(i, 16);
  }
  return "";
}

inline bool exists(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0;
}

inline unsigned mode_of(const std::string& path) {
  struct stat st {};
  EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
  return static_cast<unsigned>(st.st_mode & 07777U);
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// The text of the std::runtime_error that f throws ("" and a test failure if none).
template <typename F>
std::string runtime_error_text(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  } catch (...) {
    ADD_FAILURE() << "threw something other than std::runtime_error";
    return "";
  }
  ADD_FAILURE() << "did not throw";
  return "";
}

/// A fresh directory per test (mode 0700), removed with everything in it afterwards.
class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/evade_auth_test_XXXXXX";
    const char* d = ::mkdtemp(tmpl);
    ASSERT_NE(d, nullptr) << std::strerror(errno);
    dir_ = d;
    ASSERT_EQ(mode_of(dir_), 0700U);
  }
  void TearDown() override {
    if (dir_.empty()) return;
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
    EXPECT_FALSE(ec) << "cannot remove " << dir_ << ": " << ec.message();
  }

  std::string path(const std::string& name) const { return dir_ + "/" + name; }

  /// Writes text to a new file (replacing one) with the given mode (chmod: not the umask's).
  std::string write_file(const std::string& name, const std::string& text,
                         unsigned mode = 0600U) const {
    std::string p = path(name);
    (void)::unlink(p.c_str());  // may not exist
    {
      std::ofstream f(p, std::ios::binary | std::ios::trunc);
      EXPECT_TRUE(f.good()) << p;
      f << text;
      f.flush();
      EXPECT_TRUE(f.good()) << p;
    }
    EXPECT_EQ(::chmod(p.c_str(), static_cast<mode_t>(mode)), 0) << p << ": " << std::strerror(errno);
    return p;
  }

  std::string dir_;
};

}  // namespace evade::auth::test
