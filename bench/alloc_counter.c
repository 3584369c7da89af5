/* alloc_counter.c: an LD_PRELOAD allocation counter for the soak of evade_guidance_node
 * (scripts/soak, docs/PERFORMANCE.md "Soak"). It interposes malloc, calloc, realloc,
 * posix_memalign, aligned_alloc, memalign and the C++ operator new (which the node's code
 * calls; libstdc++'s own operator new would call malloc, counted too) and forwards to glibc's
 * __libc_* entry points, so it needs no dlsym (which itself allocates). Counters live in a
 * shared file (EVADE_ALLOC_COUNT_FILE, one page) that the soak script reads while the node runs:
 *
 *   offset 0   uint64 magic 0x45564144414c4c43 ("EVADALLC")
 *   offset 8   uint64 allocations since the process started
 *   offset 16  uint64 allocations after the arm time (EVADE_ALLOC_ARM_AFTER_S seconds of
 *              CLOCK_MONOTONIC after the library was loaded; default 60)
 *   offset 24  uint64 bytes requested after the arm time
 *   offset 32  uint64 number of call sites recorded (at most 64)
 *   offset 40  64 x { uint64 return address, uint64 count, uint64 kind } (kind 1 malloc-family
 *              called directly, 2 operator new)
 *
 * A call site is the return address of the allocation call: for operator new that is the
 * caller in the node's code, for malloc the caller (liblcm, libstdc++, libc...). The script
 * maps the addresses through /proc/PID/maps and addr2line. Build: cc -O2 -shared -fPIC.
 * Not thread-safe beyond atomic counter increments (the node is single-threaded). */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

extern void* __libc_malloc(size_t n);
extern void* __libc_calloc(size_t m, size_t n);
extern void* __libc_realloc(void* p, size_t n);
extern void* __libc_memalign(size_t a, size_t n);

enum { kMaxSites = 64 };
struct Site {
  uint64_t addr, count, kind;
};
struct Counters {
  uint64_t magic, total, after_arm, bytes_after_arm, n_sites;
  struct Site sites[kMaxSites];
};

static struct Counters g_local;          /* used until (or without) the shared file */
static struct Counters* g_c = &g_local;
static int64_t g_arm_ns = INT64_MAX;
static __thread int g_in_new;             /* inside our operator new: malloc is not a site */

static int64_t mono_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

__attribute__((constructor)) static void alloc_counter_init(void) {
  const char* path = getenv("EVADE_ALLOC_COUNT_FILE");
  const char* arm = getenv("EVADE_ALLOC_ARM_AFTER_S");
  const double arm_s = arm ? strtod(arm, NULL) : 60.0;
  g_arm_ns = mono_ns() + (int64_t)(arm_s * 1e9);
  if (path == NULL) return;
  const int fd = open(path, O_RDWR | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return;
  if (ftruncate(fd, 4096) == 0) {
    void* m = mmap(NULL, 4096, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    if (m != MAP_FAILED) {
      struct Counters* c = (struct Counters*)m;
      *c = g_local;
      c->magic = 0x45564144414c4c43ULL;
      g_c = c;
    }
  }
  close(fd);
}

static void count(size_t n, void* site, uint64_t kind) {
  __atomic_add_fetch(&g_c->total, 1, __ATOMIC_RELAXED);
  if (mono_ns() < g_arm_ns) return;
  __atomic_add_fetch(&g_c->after_arm, 1, __ATOMIC_RELAXED);
  __atomic_add_fetch(&g_c->bytes_after_arm, n, __ATOMIC_RELAXED);
  const uint64_t k = g_c->n_sites;
  for (uint64_t i = 0; i < k; ++i) {
    if (g_c->sites[i].addr == (uint64_t)(uintptr_t)site) {
      ++g_c->sites[i].count;
      return;
    }
  }
  if (k < kMaxSites) {
    g_c->sites[k].addr = (uint64_t)(uintptr_t)site;
    g_c->sites[k].count = 1;
    g_c->sites[k].kind = kind;
    g_c->n_sites = k + 1;
  }
}

static void count_c(size_t n, void* site) {
  if (!g_in_new) count(n, site, 1);
}

void* malloc(size_t n) {
  count_c(n, __builtin_return_address(0));
  return __libc_malloc(n);
}
void* calloc(size_t m, size_t n) {
  count_c(m * n, __builtin_return_address(0));
  return __libc_calloc(m, n);
}
void* realloc(void* p, size_t n) {
  count_c(n, __builtin_return_address(0));
  return __libc_realloc(p, n);
}
void* memalign(size_t a, size_t n) {
  count_c(n, __builtin_return_address(0));
  return __libc_memalign(a, n);
}
void* aligned_alloc(size_t a, size_t n) {
  count_c(n, __builtin_return_address(0));
  return __libc_memalign(a, n);
}
int posix_memalign(void** out, size_t a, size_t n) {
  count_c(n, __builtin_return_address(0));
  void* p = __libc_memalign(a, n);
  if (p == NULL) return ENOMEM;
  *out = p;
  return 0;
}

/* C++ operator new (mangled names): counted at the caller's site, then malloc'd. */
static void* new_impl(size_t n, void* site) {
  count(n, site, 2);
  g_in_new = 1;
  void* p = __libc_malloc(n == 0 ? 1 : n);
  g_in_new = 0;
  return p;
}
void* _Znwm(size_t n) {
  void* p = new_impl(n, __builtin_return_address(0));
  if (p == NULL) abort(); /* no exception machinery here: an out-of-memory soak is a failure */
  return p;
}
void* _Znam(size_t n) {
  void* p = new_impl(n, __builtin_return_address(0));
  if (p == NULL) abort();
  return p;
}
