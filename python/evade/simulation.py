"""Close-range evasion of paper 000 (Yao & Wang 2012, "Active collision avoidance maneuver
strategy for on-orbit spacecraft"): the closed-loop simulation of ``evade sim`` and the
guidance law itself.

The law thrusts at ``max_accel_mps2`` along −e_θ, e_θ being the direction in which the line of
sight (LOS) to the threat turns, estimated from filtered elevation/azimuth measurements
(paper 000 eq. 8–18). Vectors are ECI (J2000), SI units.
"""
from __future__ import annotations

import numbers
import os
import warnings
from typing import Any, Dict, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _evade
from ._inputs import overrides, scenario_path
from ._result import Record

__all__ = ["simulate", "SimResult", "GuidanceLaw", "ThrustCommand", "monte_carlo_seeds"]

ThrustCommand = _evade.ThrustCommand

_BOOL_COLUMNS = ("has_meas", "fallback")
_TEXT_COLUMNS = ("mode", "reason")


class SimResult(Record):
    """``evade sim --json``'s document (``miss_m``, ``tca_s``, ``dv_mps``, ... and with
    ``runs`` the Monte Carlo's ``miss_m_p5/p50/p95``), plus the single run's time history
    (:attr:`series`) and the Monte Carlo's per-run results."""

    __slots__ = ("_series", "_mc_miss_m", "_mc_dv_mps")

    def __init__(self, data: Dict[str, Any], series: Optional[Dict[str, np.ndarray]],
                 mc_miss_m: Optional[np.ndarray], mc_dv_mps: Optional[np.ndarray]):
        super().__init__(data)
        object.__setattr__(self, "_series", series)
        object.__setattr__(self, "_mc_miss_m", mc_miss_m)
        object.__setattr__(self, "_mc_dv_mps", mc_dv_mps)

    @property
    def series(self) -> Dict[str, np.ndarray]:
        """The single run's time history, one sample per guidance cycle: the columns of
        ``evade sim --csv`` (``t_s``, ``sat_x_m``, ``rel_x_m``, ``range_m``, ``mode``, ...),
        each a numpy array (float64; ``has_meas`` and ``fallback`` bool; ``mode`` and
        ``reason`` str). Empty when simulate() was called with ``series=False``."""
        return {} if self._series is None else self._series

    @property
    def monte_carlo_miss_m(self) -> Optional[np.ndarray]:
        """Miss distance [m] of each Monte Carlo run, in run order (None without ``runs``)."""
        return self._mc_miss_m

    @property
    def monte_carlo_dv_mps(self) -> Optional[np.ndarray]:
        """Δv [m/s] of each Monte Carlo run, in run order (None without ``runs``)."""
        return self._mc_dv_mps


def _series_arrays(columns: Optional[Dict[str, Any]]) -> Optional[Dict[str, np.ndarray]]:
    if columns is None:
        return None
    out: Dict[str, np.ndarray] = {}
    for name, values in columns.items():
        if name in _TEXT_COLUMNS:
            out[name] = np.array(values, dtype=str)
        elif name in _BOOL_COLUMNS:
            out[name] = values != 0.0
        else:
            out[name] = values
    return out


def simulate(scenario: Union[str, "os.PathLike[str]"] = "seed0", *,
             set: Union[None, Mapping[str, object], Sequence[str]] = None, runs: int = 0,
             seed: int = 1, threads: int = 2, series: bool = True) -> SimResult:
    """The closed-loop evasion simulation of paper 000 (sec. 4, Table 2), as ``evade sim``:
    truth (two bodies, two-body + J2), sensor, actuator and the guidance law in this process,
    exchanged with once per guidance cycle (lockstep).

    scenario: a shipped name ("seed0", the default) or a YAML path; ``set``: overrides of its
    keys, as ``--set key=value`` (``{"guidance.max_accel_mps2": 0.5, "sensor.noise_rad":
    50e-6, "sensor.has_rates": False, "sensor.seed": 7}``).
    runs: Monte Carlo runs after the single run (0: none), over sensor and actuator noise
    seeds drawn from ``seed`` as ``--runs/--seed`` do; threads: its worker threads.
    series: collect the single run's time history (:attr:`SimResult.series`).
    The GIL is released while the simulation runs.
    Raises evade.InputError with the CLI's message for a bad scenario, key or argument, and
    RuntimeError when the run finds no closest approach (the CLI exits 1)."""
    name = os.fspath(scenario)
    doc, found, warned, columns, mc_miss, mc_dv = _evade.simulate(
        name, scenario_path(name), overrides(set), int(runs), int(seed), int(threads),
        bool(series))
    if not found:
        raise RuntimeError("evade sim: " + "; ".join(warned))
    for w in warned:
        warnings.warn(f"evade sim: {w}", RuntimeWarning, stacklevel=2)
    return SimResult(doc, _series_arrays(columns), mc_miss, mc_dv)


def monte_carlo_seeds(seed: int, run: int) -> Dict[str, int]:
    """The noise seeds of Monte Carlo run ``run`` (0-based) of ``simulate(runs=..., seed=seed)``
    and ``evade sim --runs --seed``, as ``set=`` overrides: ``{"sensor.seed": ...,
    "actuator.seed": ...}`` (splitmix64 of (seed, 2·run) and (seed, 2·run + 1)). A single run
    with these overrides flies exactly that Monte Carlo run."""
    sensor, actuator = _evade.monte_carlo_run_seeds(int(seed), int(run))
    return {"sensor.seed": sensor, "actuator.seed": actuator}


def _config_overrides(config: Mapping[str, object]) -> Tuple[list, Dict[str, float]]:
    """The config dict as (``--set`` texts, typed values): a real number (not a bool) reaches
    the C++ reader as the double given, as a CLI parameter flag does; anything else as text,
    refused there with the key's message when it is not what the key takes."""
    keys = {k if str(k).startswith("guidance.") else f"guidance.{k}": v for k, v in config.items()}
    typed = {k: float(v) for k, v in keys.items()
             if isinstance(v, numbers.Real) and not isinstance(v, bool)}
    return overrides({k: v for k, v in keys.items() if k not in typed}), typed


class GuidanceLaw(_evade._GuidanceLaw):
    """The paper-000 guidance law (the flight code): one :meth:`step` per guidance cycle.

    config: None (the declared defaults), a dict of its parameters (``{"max_accel_mps2":
    0.5, "filter.gate_chi2_2dof": 20}``, keys as under ``guidance.`` in a scenario; an
    unknown key is refused), or a scenario (a shipped name or a YAML path) whose
    ``guidance.*`` keys are read as ``evade sim`` reads them. ``set``: overrides of those
    scenario keys (``{"guidance.max_accel_mps2": 2}``).
    Raises evade.InputError naming the key and its allowed range for a bad value."""

    def __init__(self, config: Union[None, Mapping[str, object], str, "os.PathLike[str]"] = None,
                 *, set: Union[None, Mapping[str, object], Sequence[str]] = None):
        if config is None or isinstance(config, Mapping):
            if set is not None:
                raise _evade.InputError("set: applies only to a scenario (config='seed0', ...)")
            sets, params = _config_overrides(config or {})
            super().__init__("", "", sets, params, "GuidanceLaw config")
        else:
            name = os.fspath(config)
            super().__init__(name, scenario_path(name), overrides(set), {}, "")

    # step() and reset() are the extension's methods themselves (no Python layer in the
    # cycle): help(GuidanceLaw.step).

    @property
    def config(self) -> Dict[str, object]:
        """The parameters in force, keys as under ``guidance.`` in a scenario."""
        return self._config_dict()

    def status(self) -> Record:
        """The law's status after the last step (GuidanceStatus): ``mode``, ``reason``,
        ``track_valid``, ``los_rate_radps``, ``e_theta_eci`` (numpy (3,)), ``e_theta_cov_eci``
        (3, 3), ``los_unit_eci``, ``zem_m``, ``t_go_s``, ``dv_used_mps``, ``burn_s``,
        ``cycles``, ``meas_accepted``, ``meas_rejected``, ``filter_reinits``, ..."""
        return Record(self._status_dict())

    def __repr__(self) -> str:
        c = self.config
        return f"GuidanceLaw(max_accel_mps2={c['max_accel_mps2']!r}, rate_hz={c['rate_hz']!r})"
