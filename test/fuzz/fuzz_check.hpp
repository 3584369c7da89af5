// Property checks inside the fuzz harnesses. A violated property prints what was violated and
// aborts, which libFuzzer reports as a crash (and saves the input) and ctest, replaying the
// corpus through the same harness compiled with g++, reports as a failed test.
#pragma once

#include <cstdio>
#include <cstdlib>

#define EVADE_FUZZ_CHECK(cond, what)                                                      \
  do {                                                                                    \
    if (!(cond)) {                                                                        \
      std::fprintf(stderr, "fuzz property violated at %s:%d: %s (%s)\n", __FILE__,        \
                   __LINE__, what, #cond);                                                \
      std::abort();                                                                       \
    }                                                                                     \
  } while (0)
