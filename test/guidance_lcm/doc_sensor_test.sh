#!/usr/bin/env bash
# docs/INTEGRATION.md "Time base": a sensor written from the .lcm comments alone (doc_sensor:
# utime = CLOCK_REALTIME µs, seq +1) feeds a fixed-rate evade_guidance_node over udpm in a
# private network namespace; the node must consume every message it receives (none stale,
# from the future or rejected) and keep its accounting identity; without the multicast route
# the node stops at start (docs/INTEGRATION.md "Running the node").
#   doc_sensor_test.sh NODE DOC_SENSOR      exit 0 pass, 1 fail, 77 no namespace here
set -euo pipefail
node=$1 sensor=$2
if ! unshare -rn sh -c 'ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo' >/dev/null 2>&1; then
  echo "doc_sensor_test: no private network namespace here (unshare -rn): skipped" >&2
  exit 77
fi
# docs/INTEGRATION.md "Running the node": without the multicast route the node stops at start,
# exit 1, LCM's "No route" and the node's own line on stderr (issue 46).
rc=0
noroute=$(unshare -rn sh -c 'ip link set lo up; timeout 10 "$0" --lcm-url "udpm://239.255.76.67:7667?ttl=0" --max-cycles 5' "$node" 2>&1) || rc=$?
if [ "$rc" != 1 ] || ! grep -q "No route" <<<"$noroute" || ! grep -q "cannot open LCM provider" <<<"$noroute"; then
  echo "doc_sensor_test: without the multicast route: exit $rc, expected 1 with LCM's 'No route' and 'cannot open LCM provider':" >&2
  echo "$noroute" >&2
  exit 1
fi
dir=$(mktemp -d "${TMPDIR:-/tmp}/evade-doc-sensor-XXXXXX")
trap 'rm -rf "$dir"' EXIT
NODE=$node SENSOR=$sensor D=$dir unshare -rn bash -c '
  set -e
  ip link set lo up; ip link set lo multicast on; ip route add 224.0.0.0/4 dev lo
  url="udpm://239.255.76.67:7667?ttl=0"
  "$NODE" --lcm-url "$url" --max-cycles 150 --stats-json --quiet > "$D/node.json" 2> "$D/node.err" &
  n=$!
  sleep 0.5
  "$SENSOR" "$url" 50 2 > "$D/sensor.json"
  wait $n
'
python3 - "$dir" <<'PY'
import json, sys
d = sys.argv[1]
node = json.load(open(f"{d}/node.json"))
sent = json.load(open(f"{d}/sensor.json"))["published"]
i = node["inputs"]
print(json.dumps({"published": sent, "inputs": i}))
ok = (i["received"] > 0.9 * sent and i["identity"] and i["rejected"] == 0 and i["stale"] == 0
      and i["by_reason"].get("from_future", 0) == 0
      and i["consumed"] + i["superseded"] == i["received"])
if not ok:
    print("doc_sensor_test: FAILED: the node did not use the documented sensor's messages", file=sys.stderr)
sys.exit(0 if ok else 1)
PY
