#!/usr/bin/env python3
"""evade.sgp4.propagate against python sgp4's SatrecArray, in one process, side by side.

The issue's benchmark: the shipped 1,200-object catalog x 1,441 instants (1 day at 60 s from
the latest element epoch: 1.73 M states) through both, on the same element sets and instants,
both returning (N, T, 3) numpy arrays. Repeats each call and reports the best and the median
wall time, ns per state and the ratio; checks the two agree (largest |dr|, |dv| over every
state). Prints one JSON document.

Usage (python sgp4 2.27 from PyPI, evade installed with pip in the same environment):
  python3 -m venv v && v/bin/pip install . sgp4==2.27
  v/bin/python bench/python_sgp4_vs_evade.py --tle scenarios/catalogs/synthetic-1200.tle
"""
import argparse
import json
import os
import statistics
import time

import numpy as np
import sgp4
from sgp4.api import Satrec, SatrecArray

import evade


def timed(fn, repeats):
    walls = []
    out = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        walls.append(time.perf_counter() - t0)
    return out, walls


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tle", required=True)
    ap.add_argument("--span-s", type=float, default=86400.0)
    ap.add_argument("--step-s", type=float, default=60.0)
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()

    lines = open(args.tle).read().splitlines()
    sats = [Satrec.twoline2rv(a, b) for a, b in zip(lines, lines[1:])
            if a.startswith("1 ") and b.startswith("2 ")]
    arr = SatrecArray(sats)
    cat = evade.sgp4.read_catalog(args.tle)
    assert len(cat) == len(sats), "both read every element set"
    t_s = np.arange(0.0, args.span_s + 1e-9, args.step_s)
    # The start: the latest element epoch, as a (whole day, fraction) pair for python sgp4 and
    # as its UTC text for evade (the same instant; evade's default start is that epoch too).
    last = max(sats, key=lambda s: (s.jdsatepoch + s.jdsatepochF, s.jdsatepochF))
    jd = np.full(t_s.shape, last.jdsatepoch)
    fr = last.jdsatepochF + t_s / 86400.0
    states = len(sats) * len(t_s)

    (e_py, r_km, v_kmps), py_walls = timed(lambda: arr.sgp4(jd, fr), args.repeats)
    runs = {"python_sgp4_satrec_array": py_walls}
    result = None
    for threads in (1, 2):
        result, walls = timed(lambda: evade.sgp4.propagate(cat, None, t_s, threads=threads), args.repeats)
        runs[f"evade_threads_{threads}"] = walls
    ok = (e_py == 0) & (result.error == 0)
    report = {
        "objects": len(sats), "instants": len(t_s), "states": states,
        "python_sgp4": sgp4.__version__, "evade": evade.__version__,
        "load_1min": os.getloadavg()[0], "cpus": os.cpu_count(),
        "max_dr_m": float(np.max(np.abs(result.r_m[ok] - r_km[ok] * 1e3))),
        "max_dv_mps": float(np.max(np.abs(result.v_mps[ok] - v_kmps[ok] * 1e3))),
        "same_error_codes": bool(np.array_equal(result.error, e_py.astype(np.int32))),
        "runs": {},
    }
    py_best = min(py_walls)
    for name, walls in runs.items():
        report["runs"][name] = {
            "best_s": round(min(walls), 4), "median_s": round(statistics.median(walls), 4),
            "ns_per_state_best": round(min(walls) / states * 1e9, 1),
            "speedup_vs_python_best": round(py_best / min(walls), 2)}
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
