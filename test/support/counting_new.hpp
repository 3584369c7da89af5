// Replaces the global operator new / delete with versions that count every allocation, for
// the tests that prove code allocates nothing (real-time code allocates nothing after
// initialization: docs/ARCHITECTURE.md "Conventions"). Include it in exactly one source
// file of a test executable; read g_news before and after the code under test.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_news{0};
}  // namespace

// GCC (with inlining, e.g. -O2 + sanitizers) flags free() in a replaced operator delete as
// mismatched with `new` expressions; here new and delete are both replaced and both use
// malloc/free, so the pairing is correct.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t n) {
  ++g_news;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
