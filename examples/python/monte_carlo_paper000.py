"""Monte Carlo of paper 000's close-range evasion (Yao & Wang 2012, sec. 4–5) with noisy angles,
written in Python: one evade.simulate() per run, each with its own sensor/actuator noise seeds,
and a histogram of the miss distance.

The scenario is seed0 (paper 000 Table 1: the debris 10 s from a collision; the law thrusts at
max_accel_mps2 along −e_θ from detection), with an angles-only sensor of 1σ ``--noise-rad``
(the guidance filter estimates the LOS rates, paper 000 eq. 15–18). Run i uses the seeds
``evade sim --runs N --seed S`` gives its run i (evade.monte_carlo_seeds), so ``--check``
compares the percentiles with the library's own Monte Carlo of the same runs.

    python examples/python/monte_carlo_paper000.py                 # 1000 runs, 2 threads
    python examples/python/monte_carlo_paper000.py --runs 200 --out miss.png --check

Headless (matplotlib's Agg backend). 1000 runs take a few seconds on 2 cores: the runs are
spread over --threads Python threads, which run in parallel because evade.simulate releases
the GIL while it simulates.
"""
from __future__ import annotations

import argparse
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Dict

import numpy as np

import evade


def noise_overrides(noise_rad: float, accel_mps2: float) -> Dict[str, object]:
    """seed0 with an angles-only sensor of 1σ noise_rad and the law's acceleration."""
    return {"sensor.noise_rad": noise_rad, "sensor.has_rates": False,
            "guidance.max_accel_mps2": accel_mps2}


def run_miss_m(base: Dict[str, object], seed: int, run: int) -> float:
    """Miss distance [m] of Monte Carlo run ``run`` (its own noise seeds)."""
    overrides = {**base, **evade.monte_carlo_seeds(seed, run)}
    return evade.simulate("seed0", set=overrides, series=False).miss_m


def monte_carlo(base: Dict[str, object], runs: int, seed: int, threads: int) -> np.ndarray:
    with ThreadPoolExecutor(max_workers=threads) as pool:
        return np.array(list(pool.map(lambda i: run_miss_m(base, seed, i), range(runs))))


def save_histogram(miss_m: np.ndarray, title: str, path: str) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    # The bins span p1..max so that a few far-low runs do not squeeze the bulk into one bar;
    # the runs below are counted in the legend.
    lo = float(np.percentile(miss_m, 1))
    below = int(np.count_nonzero(miss_m < lo))
    ax.hist(miss_m, bins=40, range=(lo, float(miss_m.max())), color="tab:blue",
            edgecolor="white", label=f"runs ({below} below {lo:.4f} m, min {miss_m.min():.4f} m)")
    for p, style in ((5, ":"), (50, "--"), (95, ":")):
        ax.axvline(np.percentile(miss_m, p), color="k", linestyle=style, label=f"p{p}")
    ax.set_xlabel("miss distance [m]")
    ax.set_ylabel("runs")
    ax.set_title(title)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=1000, help="Monte Carlo runs [-]")
    ap.add_argument("--seed", type=int, default=1, help="Monte Carlo seed [-]")
    ap.add_argument("--threads", type=int, default=2, help="Python threads running simulations")
    ap.add_argument("--noise-rad", type=float, default=50e-6, help="1-sigma angle noise [rad]")
    ap.add_argument("--accel-mps2", type=float, default=1.0, help="guidance acceleration [m/s^2]")
    ap.add_argument("--out", default="miss_histogram.png", help="histogram PNG")
    ap.add_argument("--check", action="store_true",
                    help="also run the library's Monte Carlo of the same runs and compare")
    a = ap.parse_args()
    if a.runs < 1:
        ap.error("--runs must be at least 1")

    base = noise_overrides(a.noise_rad, a.accel_mps2)
    nominal = evade.simulate("seed0", set=base, series=False)
    t0 = time.perf_counter()
    miss_m = monte_carlo(base, a.runs, a.seed, a.threads)
    wall_s = time.perf_counter() - t0
    p5, p50, p95 = np.percentile(miss_m, [5, 50, 95])
    print(f"paper 000 seed0, {a.runs} runs, angles-only noise {a.noise_rad:g} rad, "
          f"accel {a.accel_mps2:g} m/s^2 (unforced miss {nominal.nominal_miss_m:.4f} m)")
    print(f"miss [m]: p5 {p5:.4f}  p50 {p50:.4f}  p95 {p95:.4f}  "
          f"min {miss_m.min():.4f}  max {miss_m.max():.4f}  mean {miss_m.mean():.4f}")
    print(f"{wall_s:.2f} s for {a.runs} runs on {a.threads} threads "
          f"({1e3 * wall_s / a.runs:.2f} ms per run)")
    save_histogram(miss_m, f"paper 000 seed0: miss over {a.runs} runs "
                           f"(angle noise {a.noise_rad:g} rad)", a.out)
    print(f"histogram: {a.out}")
    if a.check:
        lib = evade.simulate("seed0", set=base, runs=a.runs, seed=a.seed, threads=a.threads,
                             series=False)
        same = np.array_equal(lib.monte_carlo_miss_m, miss_m)
        print(f"library Monte Carlo: p50 {lib.miss_m_p50:.4f} m; every run identical: {same}")
        return 0 if same else 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
