#!/usr/bin/env python3
"""`evade plan formation --plan-out FILE` then `evade sim --plan FILE`: the simulator loads the
plan the planner wrote and delivers every impulse: |dv| as planned (to 1e-12 relative: a
one-cycle burn at |dv|/T carries the magnitude exactly), each burn centred within one cycle
of its planned time. Usage: plan_file_cli_test.py EVADE_EXE WORK_DIR"""
import json
import math
import os
import subprocess
import sys


def main():
    exe, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "seed3_plan.json")
    subprocess.run([exe, "plan", "formation", "--scenario", "seed3", "--plan-out", path, "--json"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(path) as f:
        plan = json.load(f)
    out = subprocess.run([exe, "sim", "--plan", path, "--guidance-hz", "1", "--json"],
                         check=True, stdout=subprocess.PIPE, text=True).stdout
    res = json.loads(out)
    n = len(plan["impulses"])
    assert n == 2, plan
    assert res["burns_delivered"] == n, res
    cycle_s = 1.0 / res["guidance_rate_hz"]
    for p, r in zip(plan["impulses"], res["impulses"]):
        planned = math.sqrt(sum(x * x for x in p["dv_rsw_mps"]))
        print(f"t {p['t_s']:.1f} s: planned {planned:.15g} m/s, delivered "
              f"{r['dv_delivered_mps']:.15g} m/s, centre offset {r['centre_offset_s']:+.3f} s")
        assert r["t_planned_s"] == p["t_s"], (r, p)
        assert abs(r["dv_delivered_mps"] / planned - 1.0) < 1e-12, (r, p)
        assert abs(r["centre_offset_s"]) <= cycle_s, r
    return 0


if __name__ == "__main__":
    sys.exit(main())
