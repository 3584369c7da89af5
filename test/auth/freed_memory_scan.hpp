// Replaces the global operator new and delete of a test executable so that a test can prove
// that no heap block is freed while it still holds secret bytes (docs/SECURITY.md KEY-1: every
// buffer that held key text is wiped before it is freed). New blocks are zero-filled and carry
// their size in a header, so that a block is scanned only over the bytes its owner was given
// and anything found there was written during its life. While a FreedMemoryScan is alive,
// every freed block is searched for each of its needles. Include in exactly one source file of
// the executable (it defines the replacement operators).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <new>
#include <string>
#include <vector>

namespace evade::auth::test {

struct FreedScanState {
  static constexpr std::size_t kMaxNeedles = 128;
  static constexpr std::size_t kMaxNeedleBytes = 64;
  std::atomic<bool> on{false};
  std::size_t n_needles = 0;
  std::size_t needle_len[kMaxNeedles] = {};
  unsigned char needles[kMaxNeedles][kMaxNeedleBytes] = {};
  std::atomic<long> hits{0};
  std::atomic<long> scanned{0};
};

inline FreedScanState& freed_scan_state() {
  static FreedScanState s;
  return s;
}

/// While alive, counts the freed blocks that contain any needle (hits(), one per block).
class FreedMemoryScan {
 public:
  explicit FreedMemoryScan(const std::vector<std::string>& needles) {
    FreedScanState& s = freed_scan_state();
    s.n_needles = 0;
    for (const std::string& n : needles) {
      if (s.n_needles == FreedScanState::kMaxNeedles || n.empty() ||
          n.size() > FreedScanState::kMaxNeedleBytes) {
        continue;
      }
      std::memcpy(s.needles[s.n_needles], n.data(), n.size());
      s.needle_len[s.n_needles++] = n.size();
    }
    s.hits = 0;
    s.scanned = 0;
    s.on = true;
  }
  ~FreedMemoryScan() { stop(); }
  FreedMemoryScan(const FreedMemoryScan&) = delete;
  FreedMemoryScan& operator=(const FreedMemoryScan&) = delete;

  void stop() { freed_scan_state().on = false; }
  long hits() const { return freed_scan_state().hits.load(); }
  long scanned() const { return freed_scan_state().scanned.load(); }
};

/// The needles for a secret: every 16-byte window of its bytes, and of its lower- and
/// upper-case hex text.
inline std::vector<std::string> secret_needles(const unsigned char* bytes, std::size_t n) {
  std::vector<std::string> out;
  static const char* const kLower = "0123456789abcdef";
  static const char* const kUpper = "0123456789ABCDEF";
  std::string lo, up;
  for (std::size_t i = 0; i < n; ++i) {
    lo.push_back(kLower[bytes[i] >> 4U]);
    lo.push_back(kLower[bytes[i] & 0x0FU]);
    up.push_back(kUpper[bytes[i] >> 4U]);
    up.push_back(kUpper[bytes[i] & 0x0FU]);
  }
  const std::string raw(reinterpret_cast<const char*>(bytes), n);
  for (const std::string* s : std::initializer_list<const std::string*>{&raw, &lo, &up}) {
    for (std::size_t i = 0; i + 16 <= s->size(); ++i) out.push_back(s->substr(i, 16));
  }
  return out;
}

namespace freed_scan_detail {

constexpr std::size_t kHeader = alignof(std::max_align_t);

inline void* allocate(std::size_t n) {
  void* raw = std::calloc(1, n + kHeader);
  if (raw == nullptr) throw std::bad_alloc();
  std::memcpy(raw, &n, sizeof(n));
  return static_cast<unsigned char*>(raw) + kHeader;
}

inline void release(void* p) noexcept {
  if (p == nullptr) return;
  unsigned char* raw = static_cast<unsigned char*>(p) - kHeader;
  FreedScanState& s = freed_scan_state();
  if (s.on.load()) {
    std::size_t n = 0;
    std::memcpy(&n, raw, sizeof(n));
    ++s.scanned;
    const unsigned char* b = static_cast<const unsigned char*>(p);
    bool found = false;
    for (std::size_t k = 0; k < s.n_needles && !found; ++k) {
      const std::size_t len = s.needle_len[k];
      for (std::size_t i = 0; i + len <= n && !found; ++i) {
        found = b[i] == s.needles[k][0] && std::memcmp(b + i, s.needles[k], len) == 0;
      }
    }
    if (found) ++s.hits;  // blocks, not needles
  }
  std::free(raw);
}

}  // namespace freed_scan_detail
}  // namespace evade::auth::test

// GCC flags free() in a replaced operator delete as mismatched with `new` expressions; new and
// delete are both replaced here and pair calloc with free.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t n) { return evade::auth::test::freed_scan_detail::allocate(n); }
void* operator new[](std::size_t n) { return evade::auth::test::freed_scan_detail::allocate(n); }
void operator delete(void* p) noexcept { evade::auth::test::freed_scan_detail::release(p); }
void operator delete[](void* p) noexcept { evade::auth::test::freed_scan_detail::release(p); }
void operator delete(void* p, std::size_t) noexcept {
  evade::auth::test::freed_scan_detail::release(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  evade::auth::test::freed_scan_detail::release(p);
}
