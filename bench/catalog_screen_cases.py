#!/usr/bin/env python3
"""Whole-catalog SGP4 screening cases: one satellite against the catalog and all pairs.

Generates the catalog with the shipped generator (scripts/generate_tle_catalog.py, seeded),
runs each case with `evade screen --tle ... --json --quiet` under GNU time, and prints one
JSON line per case: wall and CPU time, peak RSS, the setup and screening times the command
reports, conjunctions, the prefilter's counts (objects set aside by the perigee/apogee
filter, deep-space ones bounded from samples, propagated) and the time filter's (objects
never within the threshold, objects screened, windows).

Usage (from the repository root, after building):
  python3 bench/catalog_screen_cases.py --evade build/apps/evade --count 30000 --seed 7 \\
      --span-s 604800 --cases primary            # primary, all, or both (comma-separated)
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time


def run_case(evade, tle, extra, span_s, threshold_m, threads):
    cmd = [evade, "screen", "--tle", tle, "--span-s", str(span_s), "--threshold-m",
           str(threshold_m), "--threads", str(threads), "--json", "--quiet"] + extra
    with tempfile.NamedTemporaryFile("r") as tm, tempfile.NamedTemporaryFile("r") as out:
        t0 = time.perf_counter()
        subprocess.run(["/usr/bin/time", "-o", tm.name, "-f", "%U %S %M"] + cmd, check=True,
                       stdout=open(out.name, "w"), stderr=subprocess.DEVNULL)
        wall = time.perf_counter() - t0
        user, sys_s, rss_kb = tm.read().split()[-3:]
        r = json.load(open(out.name))
    return {"wall_s": round(wall, 2), "cpu_s": round(float(user) + float(sys_s), 2),
            "peak_rss_mb": round(float(rss_kb) / 1024.0, 1),
            "setup_wall_s": round(r["motion_setup_wall_s"], 2),
            "screen_wall_s": round(r["screen_wall_s"], 2), "screened_objects": r["objects"],
            "conjunctions": len(r["events"]), "prefilter": r.get("prefilter"),
            "time_filter": r.get("time_filter"),
            "pairs_checked": r["stats"]["pairs_checked"], "candidates": r["stats"]["candidates"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--evade", required=True)
    ap.add_argument("--count", type=int, default=30000)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--span-s", type=float, default=604800.0)
    ap.add_argument("--threshold-m", type=float, default=5000.0)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--primary", type=int, default=90000)
    ap.add_argument("--cases", default="primary,all")
    a = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with tempfile.TemporaryDirectory() as d:
        tle = os.path.join(d, f"catalog-{a.count}-{a.seed}.tle")
        subprocess.run([sys.executable, os.path.join(root, "scripts", "generate_tle_catalog.py"),
                        "--count", str(a.count), "--seed", str(a.seed), tle], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        cases = {"primary": ["--primary", str(a.primary)], "all": []}
        for name in a.cases.split(","):
            r = run_case(a.evade, tle, cases[name], a.span_s, a.threshold_m, a.threads)
            print(json.dumps({"case": name, "objects": a.count, "seed": a.seed,
                              "span_s": a.span_s, "threshold_m": a.threshold_m,
                              "threads": a.threads, "load_avg_1min": os.getloadavg()[0], **r}),
                  flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
