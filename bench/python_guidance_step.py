"""What Python adds to the paper-000 guidance law, and the Monte Carlo of paper 000 from Python
against the CLI.

1. GuidanceLaw.step from Python (timeit, best of --repeat, ns per call, the loop's own cost
   measured and subtracted) against the same steps run inside C++ (the extension's hidden
   _step_n: one C++ loop over the same inputs, timed around the loop) and, when it is built,
   the Google Benchmark BM_GuidanceStep of bench/guidance_bench.cpp. The difference is the
   Python overhead per call (the issue's target: under 1 µs).
   Inputs as bench/guidance_bench.cpp feeds them: a LOS turning at 1e-3 rad/s, 50e-6 rad
   angle noise, rates given, armed, 50 Hz, the law evading.
2. The 1000-run Monte Carlo of paper 000 with noisy angles: the Python loop of
   examples/python/monte_carlo_paper000.py (one evade.simulate per run, --threads Python
   threads), the library's own Monte Carlo in process (evade.simulate(runs=...)), and
   `evade sim --runs ... --threads ... --json` (wall time of the process).

    python bench/python_guidance_step.py [--steps 100000] [--repeat 7] [--runs 1000]
        [--evade build/apps/evade] [--guidance-bench build/bench/guidance_bench]
"""
from __future__ import annotations

import argparse
import importlib.util
import json
import os
import subprocess
import time
import timeit
from pathlib import Path
from typing import Any, Dict, Optional

import numpy as np

import evade

REPO = Path(__file__).resolve().parents[1]
R_SAT = (6.8e6, 0.0, 0.0)
V_SAT = (0.0, 7500.0, 0.0)
SIGMA_ANGLE_RAD, SIGMA_RATE_RADPS = 50e-6, 1e-5
AZ_RATE_RADPS = 1e-3
CONFIG = {"dv_budget_mps": 1e4, "max_burn_s": 1e5}  # evade for the whole run, as the C++ bench


def step_inputs(n: int) -> Dict[str, np.ndarray]:
    """bench/guidance_bench.cpp's feed: a LOS turning at 1e-3 rad/s, noisy angles, 50 Hz."""
    t = 1.0 + 0.02 * np.arange(n)
    u = np.stack([np.cos(1e-3 * t), np.sin(1e-3 * t), np.full(n, 0.1)], axis=1)
    u /= np.linalg.norm(u, axis=1)[:, None]
    rng = np.random.default_rng(1)
    return {"t_s": t,
            "el": np.arcsin(u[:, 2]) + SIGMA_ANGLE_RAD * rng.standard_normal(n),
            "az": np.arctan2(u[:, 1], u[:, 0]) + SIGMA_ANGLE_RAD * rng.standard_normal(n),
            "el_rate": np.zeros(n), "az_rate": np.full(n, AZ_RATE_RADPS)}


def python_step_ns(x: Dict[str, np.ndarray], repeat: int) -> Dict[str, float]:
    """ns per GuidanceLaw.step from a Python loop (positional arguments, tuples for vectors),
    the loop's own cost (the same loop calling nothing) subtracted."""
    n = len(x["t_s"])
    feed = list(zip(x["t_s"].tolist(), x["el"].tolist(), x["az"].tolist()))
    env = {"feed": feed, "GuidanceLaw": evade.GuidanceLaw, "CONFIG": CONFIG, "r_m": R_SAT,
           "v_mps": V_SAT, "sigma_rad": SIGMA_ANGLE_RAD, "sigma_radps": SIGMA_RATE_RADPS,
           "az_rate_radps": AZ_RATE_RADPS}
    setup = "step = GuidanceLaw(CONFIG).step"
    calls = ("for t_s, el_rad, az_rad in feed:\n"
             "    step(t_s, r_m, v_mps, True, el_rad, az_rad, sigma_rad, True, True, 0.0,\n"
             "         az_rate_radps, sigma_radps)")
    empty = "for t_s, el_rad, az_rad in feed:\n    pass"
    kw = ("for t_s, el_rad, az_rad in feed:\n"
          "    step(t_s, r_m, v_mps, has_measurement=True, elevation_rad=el_rad,\n"
          "         azimuth_rad=az_rad, sigma_angle_rad=sigma_rad, has_rates=True,\n"
          "         azimuth_rate_radps=az_rate_radps, sigma_rate_radps=sigma_radps)")
    best = {name: min(timeit.Timer(stmt, setup, globals=env).repeat(repeat, 1)) * 1e9 / n
            for name, stmt in (("calls", calls), ("loop", empty), ("keywords", kw))}
    return {"positional_ns": best["calls"] - best["loop"],
            "keywords_ns": best["keywords"] - best["loop"], "loop_ns": best["loop"]}


def cpp_step_ns(x: Dict[str, np.ndarray], repeat: int) -> float:
    """ns per GuidanceLaw::step in a C++ loop over the same inputs (best of repeat)."""
    n = len(x["t_s"])
    best = float("inf")
    for _ in range(repeat):
        law = evade.GuidanceLaw(CONFIG)
        elapsed_s, evading = law._step_n(x["t_s"], x["el"], x["az"], x["el_rate"], x["az_rate"],
                                         R_SAT, V_SAT, SIGMA_ANGLE_RAD, SIGMA_RATE_RADPS)
        assert evading > n // 2, "the bench law should be evading"
        best = min(best, elapsed_s * 1e9 / n)
    return best


def google_benchmark_ns(exe: Path) -> Optional[float]:
    """BM_GuidanceStep's mean ns per step (bench/guidance_bench.cpp), None if not built."""
    if not exe.is_file():
        return None
    p = subprocess.run([str(exe), "--benchmark_filter=BM_GuidanceStep$",
                        "--benchmark_format=json", "--benchmark_repetitions=3",
                        "--benchmark_report_aggregates_only=true"],
                       capture_output=True, text=True, check=True)
    rows = json.loads(p.stdout)["benchmarks"]
    return min(r["real_time"] for r in rows if r.get("aggregate_name") in ("mean", "median"))


def load_example():
    path = REPO / "examples" / "python" / "monte_carlo_paper000.py"
    spec = importlib.util.spec_from_file_location("monte_carlo_paper000", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def monte_carlo_walls(runs: int, threads: int, evade_cli: Path) -> Dict[str, Any]:
    example = load_example()
    base = example.noise_overrides(50e-6, 1.0)
    t0 = time.perf_counter()
    miss_py = example.monte_carlo(base, runs, 1, threads)
    out: Dict[str, Any] = {"python_loop_s": time.perf_counter() - t0}
    t0 = time.perf_counter()
    lib = evade.simulate("seed0", set=base, runs=runs, seed=1, threads=threads, series=False)
    out["in_process_s"] = time.perf_counter() - t0
    out["same_runs"] = bool(np.array_equal(miss_py, lib.monte_carlo_miss_m))
    out["p50_m"] = float(np.percentile(miss_py, 50))
    if evade_cli.is_file():
        args = [str(evade_cli), "sim", "--scenario", "seed0", "--set", "sensor.noise_rad=5e-05",
                "--set", "sensor.has_rates=false", "--runs", str(runs), "--seed", "1",
                "--threads", str(threads), "--json"]
        t0 = time.perf_counter()
        p = subprocess.run(args, capture_output=True, text=True, check=True)
        out["cli_s"] = time.perf_counter() - t0
        out["cli_p50_m"] = json.loads(p.stdout)["miss_m_p50"]
        out["cli_command"] = " ".join(["evade", *args[1:]])
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--steps", type=int, default=100000, help="steps per timing [-]")
    ap.add_argument("--repeat", type=int, default=7, help="timings, the best kept [-]")
    ap.add_argument("--runs", type=int, default=1000, help="Monte Carlo runs (0: skip) [-]")
    ap.add_argument("--threads", type=int, default=2, help="Monte Carlo threads [-]")
    ap.add_argument("--evade", default=os.environ.get("EVADE_CLI", str(REPO / "build/apps/evade")),
                    help="the evade CLI (default $EVADE_CLI or build/apps/evade)")
    ap.add_argument("--guidance-bench", default=str(REPO / "build/bench/guidance_bench"),
                    help="the Google Benchmark program of the guidance step")
    a = ap.parse_args()
    print(f"cores {os.cpu_count()}, load average before {os.getloadavg()[0]:.2f}")
    x = step_inputs(a.steps)
    py = python_step_ns(x, a.repeat)
    cpp = cpp_step_ns(x, a.repeat)
    print(f"GuidanceLaw.step from Python, positional: {py['positional_ns']:.0f} ns/call "
          f"(keywords {py['keywords_ns']:.0f}; the bare loop, {py['loop_ns']:.0f} ns, subtracted)")
    print(f"GuidanceLaw::step in a C++ loop over the same inputs: {cpp:.0f} ns/step")
    gb = google_benchmark_ns(Path(a.guidance_bench))
    if gb is not None:
        print(f"Google Benchmark BM_GuidanceStep: {gb:.0f} ns/step")
    print(f"Python overhead per call: {py['positional_ns'] - cpp:.0f} ns positional, "
          f"{py['keywords_ns'] - cpp:.0f} ns with keywords")
    if a.runs > 0:
        mc = monte_carlo_walls(a.runs, a.threads, Path(a.evade))
        print(f"Monte Carlo of paper 000, {a.runs} runs, {a.threads} threads, "
              "50e-6 rad angles only:")
        print(f"  Python loop of evade.simulate:     {mc['python_loop_s']:.2f} s "
              f"(p50 {mc['p50_m']:.4f} m; runs identical to the library's: "
              f"{mc['same_runs']})")
        print(f"  evade.simulate(runs=...):          {mc['in_process_s']:.2f} s")
        if "cli_s" in mc:
            print(f"  {mc['cli_command']}: {mc['cli_s']:.2f} s (p50 {mc['cli_p50_m']:.4f} m)")
    print(f"load average after {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
