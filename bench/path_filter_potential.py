#!/usr/bin/env python3
"""What an orbit-path filter could add to `evade screen --primary` (an estimate, not a filter).

The orbit-path filter of Hoots, Crawford & Roehrich ("An analytic method to determine future
close approaches between satellites", Celestial Mechanics 33, 1984) sets an object aside when,
where it crosses the primary's orbit plane, its radius differs from the primary's orbit
radius in that direction by more than D. This script asks how many objects *any* sound such
filter could set aside on a catalog, after the perigee/apogee filter, over the span:

  - every object is propagated with python `sgp4` (SatrecArray) every --radius-step-s seconds
    from the latest element epoch (the screen's start) over --span-s, and so is the primary;
  - perigee/apogee (sampled): objects whose sampled radius range overlaps the primary's
    within D survive (fewer than the shipped filter keeps: its proven bounds allow for the
    drift and one more orbit, so this count errs towards what a path filter could remove);
    the survivors are propagated again every --step-s seconds;
  - for each survivor, each crossing of the primary's instantaneous orbit plane (sign
    change of n_p . r_j, linearly interpolated) gives the object's radius |r_j| and the
    primary's osculating orbit radius p / (1 + e . u) in that direction u. If at some
    crossing the two are within D, the object is within D of the primary's orbit there, and
    no sound path filter can set it aside. The others are counted as "a path filter might
    set aside": an upper bound, since a proven filter must also allow for the drift of both
    orbits over the span, the short-period terms and the time between samples.

Prints one JSON line: objects, perigee/apogee survivors, crossings examined, survivors with a
crossing within D (kept by any path filter), and the upper bound on what a path filter sets
aside. Needs numpy and sgp4 (PyPI, accelerated). The proven filter evade runs is
include/evade/conjunction/primary_path_filter.hpp (docs/VALIDATION.md compares the two).

  python3 bench/path_filter_potential.py --tle CATALOG.tle --primary 90000 \\
      --span-s 604800 --threshold-m 5000
"""
import argparse
import json

import numpy as np
from sgp4.api import SatrecArray, Satrec


def read_tles(path):
    lines = [ln.rstrip("\n") for ln in open(path) if ln.strip()]
    out = []
    for i, ln in enumerate(lines):
        if ln.startswith("1 ") and i + 1 < len(lines) and lines[i + 1].startswith("2 "):
            out.append(Satrec.twoline2rv(ln, lines[i + 1]))
    return out


def propagate(sats, jd, fr):
    e, r, v = SatrecArray(sats).sgp4(jd, fr)
    return e, r * 1e3, v * 1e3  # m, m/s


def times(start_jd, span_s, step_s):
    t = np.arange(0.0, span_s + 0.5 * step_s, step_s)
    jd = np.full(t.size, np.floor(start_jd - 0.5) + 0.5)
    return jd, (start_jd - jd) + t / 86400.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tle", required=True)
    ap.add_argument("--primary", type=int, default=90000)
    ap.add_argument("--span-s", type=float, default=604800.0)
    ap.add_argument("--threshold-m", type=float, default=5000.0)
    ap.add_argument("--step-s", type=float, default=20.0)
    ap.add_argument("--radius-step-s", type=float, default=120.0)
    ap.add_argument("--chunk", type=int, default=200)
    a = ap.parse_args()
    mu = 398600.8e9  # WGS-72, the theory's constant [m^3/s^2]
    sats = read_tles(a.tle)
    prim = next((s for s in sats if s.satnum == a.primary), None)
    if prim is None:
        raise SystemExit(f"path_filter_potential: no element set with catalog number {a.primary} in {a.tle}")
    others = [s for s in sats if s.satnum != a.primary]
    start = max(s.jdsatepoch + s.jdsatepochF for s in sats)
    jd, fr = times(start, a.span_s, a.radius_step_s)
    _, rp_coarse, _ = propagate([prim], jd, fr)
    rpn = np.linalg.norm(rp_coarse[0], axis=1)
    d = a.threshold_m
    lo, hi = rpn.min() - d, rpn.max() + d
    cand, errors = [], 0
    for c0 in range(0, len(others), 4 * a.chunk):
        err, rj, _ = propagate(others[c0:c0 + 4 * a.chunk], jd, fr)
        rn = np.linalg.norm(rj, axis=2)
        for k in range(rn.shape[0]):
            if np.any(err[k] != 0):
                errors += 1  # an SGP4 error: kept, as the shipped filters keep it
            elif not (rn[k].max() < lo or rn[k].min() > hi):
                cand.append(others[c0 + k])
    jd, fr = times(start, a.span_s, a.step_s)
    _, rp, vp = propagate([prim], jd, fr)
    rp, vp = rp[0], vp[0]
    rp_norm = np.linalg.norm(rp, axis=1)
    h = np.cross(rp, vp)
    n_hat = h / np.linalg.norm(h, axis=1)[:, None]
    p_semi = np.linalg.norm(h, axis=1) ** 2 / mu
    e_vec = np.cross(vp, h) / mu - rp / rp_norm[:, None]
    survivors = kept = errors
    crossings = 0
    for c0 in range(0, len(cand), a.chunk):
        err, rj, _ = propagate(cand[c0:c0 + a.chunk], jd, fr)
        for k in range(rj.shape[0]):
            survivors += 1
            if np.any(err[k] != 0):
                kept += 1
                continue
            z = np.einsum("ij,ij->i", n_hat, rj[k])
            idx = np.nonzero(np.sign(z[:-1]) * np.sign(z[1:]) <= 0)[0]
            crossings += idx.size
            if idx.size == 0:
                kept += 1  # never crosses the plane in the samples: no path argument
                continue
            f = (z[idx] / (z[idx] - z[idx + 1]))[:, None]
            rc = rj[k][idx] + f * (rj[k][idx + 1] - rj[k][idx])
            rc_norm = np.linalg.norm(rc, axis=1)
            u = rc / rc_norm[:, None]
            ev = e_vec[idx] + f * (e_vec[idx + 1] - e_vec[idx])
            pp = p_semi[idx] + f[:, 0] * (p_semi[idx + 1] - p_semi[idx])
            r_orbit = pp / (1.0 + np.einsum("ij,ij->i", ev, u))
            if np.min(np.abs(rc_norm - r_orbit)) <= d:
                kept += 1
    print(json.dumps({"objects": len(sats), "span_s": a.span_s, "threshold_m": d,
                      "step_s": a.step_s, "perigee_apogee_survivors": survivors,
                      "plane_crossings": int(crossings),
                      "kept_by_any_path_filter": kept,
                      "path_filter_upper_bound_removed": survivors - kept}))


if __name__ == "__main__":
    main()
