#!/usr/bin/env python3
"""Writes a synthetic 3LE catalog that looks like a real one (seeded, reproducible).

No real catalog is shipped with evade (provider terms), so scenarios/catalogs/ holds one
made by this script: the population mix of a public catalog (about 75 % LEO with the
sun-synchronous and 50-55 deg bands, debris clouds, 10 % MEO navigation shells near
2 rev/day, 8 % GEO, 4 % Molniya/GTO-type HEO, a few decaying objects), plausible B* and
n-dot/2 values, real column layout, valid checksums. Catalog numbers start at 90000 so
they never collide with a real object; epochs spread over 3 days before the reference day.

Usage: generate_tle_catalog.py [--count N] [--seed S] [--epoch YYDDD] OUT.tle
"""
import argparse
import math
import random


def checksum(line):
    return sum(int(c) if c.isdigit() else (1 if c == '-' else 0) for c in line[:68]) % 10


def implied(x):
    """' 12345-4' form: mantissa .12345, power of ten -4 (x = 0 gives ' 00000-0')."""
    if x == 0.0:
        return ' 00000-0'
    sign = '-' if x < 0 else ' '
    e = math.floor(math.log10(abs(x))) + 1
    mant = round(abs(x) / 10 ** e * 1e5)
    if mant >= 100000:
        mant //= 10
        e += 1
    esign = '-' if e < 0 else '+'
    return f"{sign}{mant:05d}{esign}{abs(e):1d}"


def ndot_field(x):
    s = f"{x:.8f}"
    s = s.replace('0.', '.', 1) if x >= 0 else s.replace('-0.', '-.', 1)
    return f"{s:>10}"


def orbit(rng, kind):
    """Mean motion (rev/day), e, i, B* for one object of a population class."""
    if kind == 'leo':
        alt = rng.choice([rng.uniform(350, 600), rng.uniform(500, 900), rng.uniform(700, 1500)])
        inc = rng.choice([rng.uniform(97.0, 99.5), rng.uniform(51.5, 53.2), rng.uniform(65, 87),
                          rng.uniform(28, 45), rng.uniform(0, 180)])
        e = abs(rng.gauss(0.0, 0.004))
        bstar = abs(rng.lognormvariate(math.log(5e-5), 1.2)) * (1.0 if alt > 450 else 5.0)
    elif kind == 'meo':
        alt, inc, e, bstar = rng.uniform(19100, 23300), rng.uniform(53, 65), abs(rng.gauss(0, 0.008)), 0.0
    elif kind == 'geo':
        alt, inc, e, bstar = rng.uniform(35700, 35880), abs(rng.gauss(0, 2.0)), abs(rng.gauss(0, 3e-4)), 0.0
    else:  # heo: Molniya and GTO-like
        rp = 6378.135 + rng.uniform(250, 1200)
        ra = 6378.135 + rng.uniform(35000, 40000)
        a = (rp + ra) / 2
        alt, e = a - 6378.135, (ra - rp) / (ra + rp)
        inc = rng.choice([rng.uniform(62, 65), rng.uniform(5, 28)])
        bstar = abs(rng.lognormvariate(math.log(1e-4), 1.0))
    a_km = 6378.135 + alt if kind != 'heo' else alt + 6378.135
    n = 86400.0 / (2 * math.pi * math.sqrt(a_km ** 3 / 398600.8))
    return n, min(e, 0.9), min(inc, 180.0), min(bstar, 0.9)


def catalog_field(catnum):
    """The 5-column catalog number: digits below 100000, else Alpha-5 (A0000 = 100000; the
    letters skip I and O), as Space-Track writes numbers up to 339999."""
    if catnum < 100000:
        return f"{catnum:05d}"
    letters = "ABCDEFGHJKLMNPQRSTUVWXYZ"
    head, tail = divmod(catnum, 10000)
    if head - 10 >= len(letters):
        raise SystemExit(f"catalog number {catnum} does not fit the Alpha-5 field")
    return f"{letters[head - 10]}{tail:04d}"


def tle(rng, catnum, kind, epoch_yy, epoch_day, launch):
    n, e, inc, bstar = orbit(rng, kind)
    ndot = bstar * 1e-3 * rng.uniform(0.5, 1.5) * (1 if rng.random() > 0.1 else -1)
    intl = f"{launch[0] % 100:02d}{launch[1]:03d}{launch[2]:<3}"
    day = epoch_day - rng.uniform(0.0, 3.0)
    l1 = (f"1 {catalog_field(catnum)}U {intl:<8} {epoch_yy:02d}{day:012.8f} {ndot_field(ndot)} "
          f"{implied(0.0)} {implied(bstar)} 0 {rng.randint(1, 999):4d}")
    raan, argp, m = (rng.uniform(0, 360) for _ in range(3))
    l2 = (f"2 {catalog_field(catnum)} {inc:8.4f} {raan:8.4f} {round(e * 1e7):07d} {argp:8.4f} {m:8.4f} "
          f"{n:11.8f}{rng.randint(1, 99999):5d}")
    return l1 + str(checksum(l1)), l2 + str(checksum(l2))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--count', type=int, default=1200)
    ap.add_argument('--seed', type=int, default=12)
    ap.add_argument('--epoch', default='26320', help='reference epoch YYDDD (default 26320)')
    ap.add_argument('out')
    a = ap.parse_args()
    rng = random.Random(a.seed)
    yy, ddd = int(a.epoch[:2]), float(a.epoch[2:]) + 1.0
    kinds = ['leo'] * 75 + ['meo'] * 10 + ['geo'] * 8 + ['heo'] * 4 + ['leo'] * 3
    lines = []
    for k in range(a.count):
        kind = rng.choice(kinds)
        launch = (rng.randint(1970, 2025), rng.randint(1, 120), rng.choice('ABCDEFGHJKLMNP'))
        name = {'leo': 'SYN LEO', 'meo': 'SYN NAV', 'geo': 'SYN GEO', 'heo': 'SYN HEO'}[kind]
        l1, l2 = tle(rng, 90000 + k, kind, yy, ddd, launch)
        lines += [f"0 {name} {k + 1:04d}", l1, l2]
    with open(a.out, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print(f"generate_tle_catalog.py: {a.count} element sets written to {a.out} (seed {a.seed})")


if __name__ == '__main__':
    main()
