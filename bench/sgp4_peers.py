#!/usr/bin/env python3
"""SGP4 states into arrays, side by side in one process: evade.sgp4.propagate against the
peers an analyst can install from PyPI (python-sgp4's SatrecArray, satkit, heyoka's SGP4
propagator, astroz), on the same element sets at the same instants, runs interleaved (each
repeat times every call once, in turn), the median of the repeats per call.

Threads: the process is pinned to one core (os.sched_setaffinity), then to two, so that every
library gets the same cores whatever its own threading; evade is asked for that many threads.
Agreement: the largest position difference from python-sgp4 (the reference implementation,
Vallado et al. 2006, improved mode) over the states both compute. heyoka's propagator takes
near-Earth element sets only (period < 225 min): its row times those and says so.

  python3 -m venv v && v/bin/pip install . sgp4==2.27 satkit heyoka astroz numpy
  v/bin/python bench/sgp4_peers.py [--catalog FILE] [--copies K] [--repeats 7] [--cores 1,2]

--copies K renumbers the catalog K times (K x N objects: the 12,000-object case is the shipped
1,200 with --copies 10). Prints a Markdown table per core count and one JSON line per call.
"""
import argparse
import datetime as dt
import json
import os
import statistics
import sys
import tempfile
import time

import numpy as np
from sgp4.api import Satrec, SatrecArray

import evade

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def checksum(line):
    s = sum(int(c) if c.isdigit() else (1 if c == "-" else 0) for c in line[:68])
    return line[:68] + str(s % 10)


def renumbered(lines, copies):
    """The 3LE element sets; with copies > 1, K times, the i-th set of the result numbered i
    (checksums redone), so that every copy is its own object."""
    sets = [(lines[i], lines[i + 1], lines[i + 2]) for i in range(0, len(lines) - 2, 3)
            if lines[i + 1].startswith("1 ") and lines[i + 2].startswith("2 ")]
    if copies == 1:
        return [x for s in sets for x in s]
    out = []
    for k in range(copies):
        for j, (name, l1, l2) in enumerate(sets):
            sat = "%05d" % (k * len(sets) + j + 1)
            out += [name, checksum(l1[:2] + sat + l1[7:]), checksum(l2[:2] + sat + l2[7:])]
    return out


def timed(call):
    t0 = time.perf_counter()
    out = call()
    return time.perf_counter() - t0, out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--catalog", default=os.path.join(ROOT, "scenarios/catalogs/synthetic-1200.tle"))
    ap.add_argument("--copies", type=int, default=1)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--cores", default="1,2")
    ap.add_argument("--span-s", type=float, default=86400.0)
    ap.add_argument("--step-s", type=float, default=60.0)
    args = ap.parse_args()
    if args.copies < 1 or args.repeats < 1:
        sys.exit("sgp4_peers: --copies and --repeats must be at least 1")
    import astroz
    import heyoka as hy
    import satkit as sk

    with open(args.catalog) as f:
        lines = renumbered(f.read().splitlines(), args.copies)
    tmp = tempfile.NamedTemporaryFile("w", suffix=".tle", delete=False)
    tmp.write("\n".join(lines) + "\n")
    tmp.close()
    pairs = [(lines[i + 1], lines[i + 2]) for i in range(0, len(lines), 3)]
    sats = [Satrec.twoline2rv(a, b) for a, b in pairs]
    cat = evade.sgp4.read_catalog(tmp.name)
    n = len(sats)
    assert len(cat) == n, "evade read %d of %d element sets" % (len(cat), n)
    # t = 0 on the whole second after the latest epoch, so that every library gets it exactly
    # (a split Julian date, a datetime, ISO text); J2000 is JD 2451545.0, noon.
    start = float(np.ceil(cat.epochs_j2000_s.max()))
    day, sec = divmod(int(start) + 43200, 86400)
    start_dt = dt.datetime(2000, 1, 1, 12, tzinfo=dt.timezone.utc) + dt.timedelta(seconds=start)
    start_utc = start_dt.strftime("%Y-%m-%dT%H:%M:%SZ")
    t_s = np.arange(0.0, args.span_s + 0.5 * args.step_s, args.step_s)
    jd = np.full_like(t_s, 2451544.5 + day)
    fr = (sec + t_s) / 86400.0
    near = np.array([s.no_kozai > 2 * np.pi / 225.0 for s in sats])
    hy_prop = hy.model.sgp4_propagator([s for s, ok in zip(sats, near) if ok])
    ep_jd = np.array([s.jdsatepoch for s in sats])[near]
    ep_fr = np.array([s.jdsatepochF for s in sats])[near]
    hy_tsince = ((jd[:, None] - ep_jd[None, :]) + (fr[:, None] - ep_fr[None, :])) * 1440.0  # (T, n_near) min
    sk_tles = sk.TLE.from_file(tmp.name)
    sk_times = [sk.time.from_datetime(start_dt + dt.timedelta(seconds=float(t))) for t in t_s]
    az = astroz.Constellation(tmp.name)
    ids = [int(a[2:7]) for a, _ in pairs]
    az_order = {int(x): i for i, x in enumerate(az.satnums)}  # astroz groups near-Earth sets first
    az_rows = np.array([az_order[i] for i in ids])
    ref = SatrecArray(sats).sgp4(jd, fr)  # (err, r_km, v_kmps), each (N, T, ...)
    ref_r_m = ref[1] * 1e3
    states = n * len(t_s)

    def agreement(r_m, mask=None):
        d = np.linalg.norm(r_m - (ref_r_m if mask is None else ref_r_m[mask]), axis=-1)
        good = (ref[0] if mask is None else ref[0][mask]) == 0
        return float(np.nanmax(np.where(good, d, 0.0)))

    results = []
    for cores in [int(c) for c in args.cores.split(",")]:
        os.sched_setaffinity(0, set(range(cores)))
        calls = {
            "python-sgp4 SatrecArray.sgp4": (lambda: SatrecArray(sats).sgp4(jd, fr),
                                             lambda o: agreement(o[1] * 1e3), n),
            "satkit sgp4": (lambda: sk.sgp4(sk_tles, sk_times, opsmode=sk.sgp4_opsmode.improved),
                            lambda o: agreement(o[0]), n),
            "heyoka sgp4_propagator (tsince)": (lambda: hy_prop(hy_tsince),
                                                lambda o: agreement(np.transpose(o[:, 0:3, :], (2, 0, 1)) * 1e3, near),
                                                int(near.sum())),
            "astroz propagate": (lambda: astroz.propagate(az, t_s / 60.0, start_time=start_dt, output="teme",
                                                          velocities=True),
                                 lambda o: agreement(np.transpose(o[0], (1, 0, 2))[az_rows] * 1e3), n),
            "evade.sgp4.propagate": (lambda: evade.sgp4.propagate(cat, start_utc, t_s, threads=cores),
                                     lambda o: agreement(o.r_m), n),
        }
        times = {k: [] for k in calls}
        agree = {}
        for rep in range(args.repeats):
            for name, (call, check, _) in calls.items():
                t, out = timed(call)
                times[name].append(t)
                if rep == 0:
                    agree[name] = check(out)
                del out
        print("\n%d objects x %d instants (%d states), %d core%s, median of %d interleaved runs, load %.2f\n"
              % (n, len(t_s), states, cores, "" if cores == 1 else "s", args.repeats, os.getloadavg()[0]))
        print("| call | median | ns per state | max |r - python-sgp4| |")
        print("|---|---|---|---|")
        for name, (_, _, objects) in calls.items():
            med = statistics.median(times[name])
            per = med / (objects * len(t_s)) * 1e9
            print("| %s | %.3f s | %.0f%s | %.1e m |" % (name, med, per,
                  "" if objects == n else " (%d near-Earth objects)" % objects, agree[name]))
            results.append({"call": name, "cores": cores, "objects": objects, "instants": len(t_s),
                            "median_s": med, "ns_per_state": per, "max_dr_m": agree[name],
                            "runs_s": times[name]})
    for r in results:
        print(json.dumps(r))
    os.unlink(tmp.name)


if __name__ == "__main__":
    main()
