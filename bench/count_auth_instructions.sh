#!/usr/bin/env bash
# Instructions of the node's authentication path (docs/PERFORMANCE.md "Authentication"): runs
# bench/auth_bench under valgrind's callgrind, counting only inside the node's drain() and
# run_cycle() (callees included: the receive callbacks, the MAC verification, the cycle, the
# status and its signature), and divides by the benchmark's fixed iteration count. Instruction
# counts repeat exactly for the same binary and inputs whatever the machine's load, so two
# builds can be compared where wall time on a shared 2-core machine cannot.
#   bench/count_auth_instructions.sh [BUILD_DIR] [ARG...]   (default: build, args 0 1 2)
# Prints one line per BM_NodeCycleAuth argument: "node_cycle_auth/<arg> <instructions per cycle>".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
args=("$@")
[ ${#args[@]} -gt 0 ] || args=(0 1 2)
exe=$build/bench/auth_bench
[ -x "$exe" ] || { echo "count_auth_instructions: $exe not built" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "count_auth_instructions: valgrind not installed" >&2; exit 2; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for a in "${args[@]}"; do
  valgrind --tool=callgrind --callgrind-out-file="$out" --collect-atstart=no \
    --toggle-collect='*GuidanceNode::drain*' --toggle-collect='*GuidanceNode::run_cycle*' \
    "$exe" --benchmark_filter="BM_NodeCycleAuth/$a/" >/dev/null 2>&1
  total=$(grep -E '^(summary|totals):' "$out" | head -1 | awk '{print $2}')
  python3 -c "print('node_cycle_auth/$a', round($total / 20000))"
done
