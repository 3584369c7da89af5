#!/usr/bin/env python3
"""`evade propagate --tle` against python sgp4's SatrecArray, side by side in one run.

Both propagate the same element sets over the same instants (from the latest element epoch,
span and step as given): python sgp4 keeps every state in memory (its (N, T, 3) arrays, as
analysts use it); evade streams them (--csv, or --json) to a file or /dev/null. Prints one
JSON line per run: wall time, ns per state, peak resident memory (evade: GNU time's %M of
the child; python: this process's peak and growth), and the ratio. A check first compares a subsample: the
largest position and velocity difference between the two over span 1 day at 600 s.

Usage (python sgp4 2.27 from PyPI, e.g. in a virtual environment):
  python3 -m venv v && v/bin/pip install sgp4==2.27 numpy
  v/bin/python bench/propagate_vs_python_sgp4.py --evade build/apps/evade \
      --tle scenarios/catalogs/synthetic-1200.tle --span-s 518400 --step-s 60
"""
import argparse
import csv
import io
import json
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np
import sgp4
from sgp4.api import Satrec, SatrecArray


def read_tle(path):
    lines = open(path).read().splitlines()
    sats = []
    for a, b in zip(lines, lines[1:]):
        if a.startswith("1 ") and b.startswith("2 "):
            sats.append(Satrec.twoline2rv(a, b))
    return sats


def python_states(sats, span_s, step_s):
    arr = SatrecArray(sats)
    # The latest epoch as its (whole day, fraction) pair: their sum as one double would round
    # it to 5e-10 day (47 us, 35 cm in LEO).
    last = max(sats, key=lambda s: (s.jdsatepoch + s.jdsatepochF, s.jdsatepochF))
    t = np.arange(0.0, span_s + 1e-9, step_s)
    jd = np.full(t.shape, last.jdsatepoch)
    fr = last.jdsatepochF + t / 86400.0
    return t, arr.sgp4(jd, fr)


def check(evade, tle, sats):
    """Largest |dr| [m] and |dv| [m/s] between evade and python sgp4 over 1 day at 600 s."""
    out = subprocess.run([evade, "propagate", "--tle", tle, "--span-s", "86400", "--step-s",
                          "600", "--csv"], check=True, capture_output=True, text=True).stdout
    rows = list(csv.reader(io.StringIO(out)))[1:]
    t, (e, r, v) = python_states(sats, 86400.0, 600.0)
    nt = len(t)
    dr = dv = 0.0
    for i, row in enumerate(rows):
        n, k = divmod(i, nt)
        if e[n, k] != 0:
            continue
        dr = max(dr, float(np.linalg.norm(np.array(row[2:5], float) - 1e3 * r[n, k])))
        dv = max(dv, float(np.linalg.norm(np.array(row[5:8], float) - 1e3 * v[n, k])))
    return len(rows), dr, dv


def run_evade(evade, tle, span_s, step_s, fmt, out, threads):
    """Wall time [s] and peak RSS [MB] (GNU time's %M: the child's own, not this forked image)."""
    cmd = [evade, "propagate", "--tle", tle, "--span-s", str(span_s), "--step-s", str(step_s),
           "--" + fmt, "--threads", str(threads)]
    with tempfile.NamedTemporaryFile("r") as rss, open(out, "wb") as f:
        t0 = time.perf_counter()
        subprocess.run(["/usr/bin/time", "-o", rss.name, "-f", "%M"] + cmd, check=True, stdout=f)
        wall = time.perf_counter() - t0
        return wall, float(rss.read().split()[-1]) / 1024.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--evade", required=True)
    ap.add_argument("--tle", required=True)
    ap.add_argument("--span-s", type=float, default=518400.0)
    ap.add_argument("--step-s", type=float, default=60.0)
    ap.add_argument("--out", default="/dev/null", help="where evade writes (default /dev/null)")
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    sats = read_tle(a.tle)
    rows, dr, dv = check(a.evade, a.tle, sats)
    print(json.dumps({"case": "agreement", "states": rows, "max_dr_m": dr, "max_dv_mps": dv,
                      "python_sgp4": sgp4.__version__}))
    rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    t0 = time.perf_counter()
    t, (e, r, v) = python_states(sats, a.span_s, a.step_s)
    py_wall = time.perf_counter() - t0
    n_states = r.shape[0] * r.shape[1]
    py_rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print(json.dumps({"case": "python_sgp4_satrecarray", "objects": len(sats), "times": len(t),
                      "states": n_states, "wall_s": round(py_wall, 3),
                      "ns_per_state": round(1e9 * py_wall / n_states, 1),
                      "peak_rss_mb": round(py_rss, 1), "rss_growth_mb": round(py_rss - rss0, 1)}))
    del r, v, e
    for fmt in ("csv", "json"):
        wall, rss = run_evade(a.evade, a.tle, a.span_s, a.step_s, fmt, a.out, a.threads)
        print(json.dumps({"case": "evade_propagate_" + fmt, "threads": a.threads, "out": a.out,
                          "states": n_states, "wall_s": round(wall, 3),
                          "ns_per_state": round(1e9 * wall / n_states, 1),
                          "peak_rss_mb": round(rss, 1),
                          "ratio_to_python": round(wall / py_wall, 3)}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
