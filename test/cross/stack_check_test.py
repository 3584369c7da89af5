#!/usr/bin/env python3
"""scripts/stack_check against call graphs GCC writes for small programs made to break it
(docs/GUIDANCE_NODE.md NODE-RT-6): an alloca on the path of GuidanceLaw::step, recursion, a
frame over the budget, the same code clean, an alloca on the planning worker's path, and a
tree without call graphs.
  stack_check_test.py SOURCE_DIR WORK_DIR CXX
Exit 0 when every case gives the expected verdict, 1 otherwise."""
import os
import shutil
import subprocess
import sys

# The entry points stack_check looks for, with a callee that each case varies.
ENTRIES = r"""
#include <cstddef>
#include <cstring>
namespace evade { namespace guidance { struct GuidanceLaw { int step(int n); }; } }
namespace evade { namespace auth { struct KeyRing { int verify(int n); }; } }
namespace evade { namespace autonomy { int assess_event(int n); } }
int worker_callee(int n);
int evade::autonomy::assess_event(int n) { return worker_callee(n); }
namespace evade { namespace guidance_lcm { namespace internal { struct NodeCore {
  int run_cycle(int n); int drain(); static void on_message(const void*, const char*, void*); }; } } }
int callee(int n);
int evade::guidance::GuidanceLaw::step(int n) { return callee(n); }
int evade::auth::KeyRing::verify(int n) { return n + 1; }
int evade::guidance_lcm::internal::NodeCore::run_cycle(int n) { return n; }
int evade::guidance_lcm::internal::NodeCore::drain() { return 0; }
void evade::guidance_lcm::internal::NodeCore::on_message(const void*, const char*, void*) {}
"""
CLEAN_WORKER = "int worker_callee(int n) { return n + 2; }\n"
CASES = {
    "clean": ("int callee(int n) { volatile char b[64]; b[0] = (char)n; return b[0]; }\n" +
              CLEAN_WORKER, 0, "0 unbounded frames on the checked paths"),
    "alloca_on_worker": ("int callee(int n) { return n; }\n"
                         "int worker_callee(int n) { char* p = (char*)__builtin_alloca((std::size_t)n);"
                         " std::memset(p, 1, (std::size_t)n); return p[n / 2]; }", 1,
                         "unbounded frame on a checked path"),
    "alloca_on_step": ("int callee(int n) { char* p = (char*)__builtin_alloca((std::size_t)n);"
                       " std::memset(p, 1, (std::size_t)n); return p[n / 2]; }" + "\n" + CLEAN_WORKER, 1,
                       "unbounded frame on a checked path"),
    "recursion": ("int callee(int n) { return n <= 0 ? 0 : 1 + callee(n - 1) + callee(n - 2); }" + "\n" + CLEAN_WORKER,
                  1, "recursion through"),
    "over_budget": ("int callee(int n) { volatile char b[20000]; b[n] = 1; return b[n / 2]; }" + "\n" + CLEAN_WORKER, 1,
                    "over its budget"),
}


def run_case(src, work, cxx, name, body):
    d = os.path.join(work, name)
    shutil.rmtree(d, ignore_errors=True)
    obj_dir = os.path.join(d, "src", "guidance")
    os.makedirs(obj_dir)
    cpp = os.path.join(obj_dir, "case.cpp")
    with open(cpp, "w") as f:
        f.write(ENTRIES + body + "\n")
    subprocess.run([cxx, "-std=c++17", "-O2", "-fno-inline", "-fstack-usage",
                    "-fcallgraph-info=su", "-c", cpp, "-o", os.path.join(obj_dir, "case.o")],
                   check=True)
    p = subprocess.run([sys.executable, os.path.join(src, "scripts", "stack_check"), d],
                       capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout + p.stderr


def main():
    src, work, cxx = sys.argv[1:4]
    bad = 0
    for name, (body, want_rc, want_text) in CASES.items():
        rc, out = run_case(src, work, cxx, name, body)
        ok = rc == want_rc and want_text in out
        print(f"{name}: exit {rc} (want {want_rc}), '{want_text}' {'found' if want_text in out else 'missing'}")
        if not ok:
            print(out)
            bad += 1
    empty = os.path.join(work, "no_call_graphs")
    os.makedirs(empty, exist_ok=True)
    p = subprocess.run([sys.executable, os.path.join(src, "scripts", "stack_check"), empty],
                       capture_output=True, text=True, timeout=60)
    print(f"no_call_graphs: exit {p.returncode} (want 2)")
    bad += p.returncode != 2
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
