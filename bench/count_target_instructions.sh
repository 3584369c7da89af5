#!/usr/bin/env bash
# Instructions per guidance step and per node cycle on each flight CPU (docs/PERFORMANCE.md
# "Instructions on the flight CPUs"): runs test/cross/instruction_harness.cpp twice per
# workload, with N1 and N2 steps (or cycles), and divides the difference of the two runs'
# instruction counts by N2 - N1, so the program's start-up (the dynamic loader, libstdc++,
# LCM) cancels. Counters:
#   x86-64 (host): valgrind --tool=callgrind, the run's total instructions (Ir);
#   aarch64, armhf, s390x: qemu-user with one guest instruction per translation block
#     (-singlestep) and every block's execution logged (-d exec,nochain): one "Trace" line per
#     instruction executed. Debian's qemu-user-static has no plugins (no -plugin libinsn.so).
#   host-qemu: the x86-64 harness counted the qemu way (qemu-x86_64-static), the check of the
#     counter: it gives callgrind's count (step: 4,749 both, 2026-12-03).
# Workloads: step (GuidanceLaw::step, bench/guidance_bench.cpp's feed) and cycle/0, /1, /2 (the
# node's drain + run_cycle on memq:// after publishing that cycle's nav and angles: sensors
# unsigned, signed and required, and that with the status signed; bench/auth_bench.cpp's
# BM_NodeCycleAuth inputs). A cycle here includes the two lcm_publish calls into memq://, which
# bench/count_auth_instructions.sh leaves out.
#   bench/count_target_instructions.sh [host|host-qemu|aarch64|armhf|s390x ...]
#   (default: host aarch64 armhf s390x)
# Needs build/ (host) and build-cross-TARGET/ (scripts/cross TARGET) with the harness built.
# Prints "<target> <workload> <instructions per step or cycle>" per line.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(host aarch64 armhf s390x)
n1=${EVADE_COUNT_N1:-40}
n2=${EVADE_COUNT_N2:-140}

count_host() {  # args: harness arguments; prints the run's instruction count
  local out
  out=$(mktemp)
  valgrind --tool=callgrind --callgrind-out-file="$out" "$root/build/test/cross/cross_instruction_harness" \
    "$@" >/dev/null 2>&1
  grep -E '^(summary|totals):' "$out" | head -1 | awk '{print $2}'
  rm -f "$out"
}

count_qemu() {  # args: qemu sysroot harness arguments...
  local qemu=$1 sysroot=$2 exe=$3
  shift 3
  "$qemu" -L "$sysroot" -singlestep -d exec,nochain -D /dev/stdout "$exe" "$@" 2>/dev/null |
    grep -c '^Trace'
}

for t in "${targets[@]}"; do
  case "$t" in
    host) command -v valgrind >/dev/null || { echo "count_target_instructions: valgrind not installed" >&2; exit 2; }
          exe="$root/build/test/cross/cross_instruction_harness"; name=x86-64 ;;
    host-qemu) qemu=qemu-x86_64-static; name=x86-64-qemu; sysroot=/
               exe="$root/build/test/cross/cross_instruction_harness" ;;
    aarch64) qemu=qemu-aarch64-static; name=aarch64 ;;
    armhf) qemu=qemu-arm-static; name=armhf ;;
    s390x) qemu=qemu-s390x-static; name=s390x ;;
    *) echo "count_target_instructions: unknown target '$t' (host, host-qemu, aarch64, armhf, s390x)" >&2; exit 2 ;;
  esac
  if [ "$t" != host ] && [ "$t" != host-qemu ]; then
    exe="$root/build-cross-$t/test/cross/cross_instruction_harness"
    sysroot="$root/build-cross-sysroot-$t"
  fi
  [ -x "$exe" ] || { echo "count_target_instructions: $exe not built (scripts/cross $t, or the host build)" >&2; exit 2; }
  for w in "step" "cycle 0" "cycle 1" "cycle 2"; do
    read -r -a args <<<"$w"
    if [ "$t" = host ]; then
      a=$(count_host "${args[@]}" "$n1"); b=$(count_host "${args[@]}" "$n2")
    else
      a=$(count_qemu "$qemu" "$sysroot" "$exe" "${args[@]}" "$n1")
      b=$(count_qemu "$qemu" "$sysroot" "$exe" "${args[@]}" "$n2")
    fi
    echo "$name ${w// //} $(( (b - a) / (n2 - n1) ))"
  done
done
