#!/usr/bin/env bash
# Instructions per guidance step: runs the BM_GuidanceStep benchmark under valgrind's
# callgrind and divides the inclusive instruction count of GuidanceLaw::step by the number
# of calls (flight processors such as a 50-MIPS LEON3 pay per instruction, so this is the
# figure that transfers; wall time on this machine does not).
#   bench/count_instructions.sh [BUILD_DIR]     (default: build; needs bench/guidance_bench)
# Prints: "instructions_per_step <N> over <calls> calls".
# Another function of another benchmark the same way (the onboard conjunction response's
# decision, docs/PERFORMANCE.md):
#   EVADE_COUNT_BENCH=autonomy_bench EVADE_COUNT_FILTER=BM_AssessEventProposesABurn \
#   EVADE_COUNT_FUNCTION='evade::autonomy::assess_event(' EVADE_COUNT_LABEL=instructions_per_decision \
#   bench/count_instructions.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
bench=${EVADE_COUNT_BENCH:-guidance_bench}
filter=${EVADE_COUNT_FILTER:-BM_GuidanceStep}
export EVADE_COUNT_FUNCTION=${EVADE_COUNT_FUNCTION:-'evade::guidance::GuidanceLaw::step('}
export EVADE_COUNT_LABEL=${EVADE_COUNT_LABEL:-instructions_per_step}
exe=$build/bench/$bench
[ -x "$exe" ] || { echo "count_instructions: $exe not built (cmake --build $build --target $bench)" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "count_instructions: valgrind not installed (apt-get install valgrind)" >&2; exit 2; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
valgrind --tool=callgrind --callgrind-out-file="$out" --collect-atstart=no \
  --toggle-collect="*$filter*" "$exe" --benchmark_filter="$filter\$" \
  --benchmark_min_time=0.2 >/dev/null 2>&1
python3 - "$out" <<'PY'
import os, re, sys
names, calls, ir = {}, 0, 0
want = os.environ["EVADE_COUNT_FUNCTION"]
pending = None
with open(sys.argv[1]) as f:
    lines = f.read().splitlines()
i = 0
while i < len(lines):
    line = lines[i]
    m = re.match(r'cfn=\((\d+)\)(?: (.*))?', line)
    if m:
        if m.group(2): names[m.group(1)] = m.group(2)
        pending = names.get(m.group(1), "")
    elif line.startswith('calls=') and pending is not None and pending.startswith(want):
        calls += int(line.split('=')[1].split()[0])
        cost = lines[i + 1].split()
        ir += int(cost[1]) if len(cost) > 1 else 0
        i += 1
        pending = None
    else:
        m = re.match(r'fn=\((\d+)\)(?: (.*))?', line)
        if m and m.group(2): names[m.group(1)] = m.group(2)
    i += 1
if calls == 0:
    sys.exit(f"count_instructions: no call of {want} recorded")
print(f"{os.environ['EVADE_COUNT_LABEL']} {ir / calls:.0f} over {calls} calls")
PY
