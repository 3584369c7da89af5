"""The evasion planners of the papers (``evade plan threat-area|formation|observability``).

* :func:`plan_threat_area`: paper 001 (Yu, Wang, Sun 2017): the chaser's potential threat
  area, the target's optimal evasive burn at fixed V_E, the smallest eliminating burn, the
  transfer-time study.
* :func:`plan_formation`: paper 003 (Duan et al.): formation collision avoidance by a small
  semi-major-axis change (two tangential burns).
* :func:`plan_observability`: paper 004 (Yu, Wang, Zhou): the observability-minimizing
  evasive burn (NLopt ISRES + polish).

Each returns the command's JSON document (a :class:`evade.Record`) with ``burn_plan``: the
plan the command publishes with --publish / --plan-out, as numpy columns (burn times t_s [s
after the plan's epoch], Δv in RSW ``dv_rsw_mps`` and, when the planner knows the inertial
state, in ECI ``dv_eci_mps`` [m/s]), or None when there is nothing to fly. The GIL is
released while planning; bad input raises evade.InputError with the CLI's message.
"""
from __future__ import annotations

import os
from typing import Mapping, Optional, Sequence, Union

from . import _evade
from ._inputs import overrides, param_values, scenario_path
from .assessment import PlanResult

__all__ = ["plan_threat_area", "plan_formation", "plan_observability"]

Sets = Union[None, Mapping[str, object], Sequence[str]]
Scenario = Union[str, "os.PathLike[str]"]


def _check_plan_id(plan_id: int) -> int:
    if int(plan_id) < 0:
        raise _evade.InputError(f"plan_id = {plan_id}: expected an integer >= 0")
    return int(plan_id)


def plan_threat_area(scenario: Scenario, *, set: Sets = None, dv_mps: Optional[float] = None,
                     dt_transfer_s: Optional[float] = None, impulses: Optional[int] = None,
                     seed: Optional[int] = None, eliminate: bool = False,
                     sweep_dv_mps: Optional[Sequence[float]] = None,
                     sweep_transfer_s: Optional[Sequence[float]] = None,
                     plan_id: int = 0) -> PlanResult:
    """Paper 001's study, as ``evade plan threat-area --scenario SCENARIO`` runs it.

    scenario: a shipped name ("seed1") or a YAML path (required, as by the CLI); ``set``:
    key=value overrides. ``dv_mps``: the evasive burn V_E [m/s] (evasion.dv_mps);
    ``dt_transfer_s``: the chaser's transfer time [s] (transfer.dt_s); ``impulses``: its
    impulses (transfer.impulses); ``seed``: the ISRES seed / the sweep's sample position.
    ``eliminate``: also the smallest V_E with no threat area; ``sweep_dv_mps``: the arc at
    each V_E [m/s] (Fig. 8); ``sweep_transfer_s``: the costs at each transfer time [s] (Fig. 4).
    ``burn_plan``: the one RSW impulse at t0 (no ECI Δv), numbered ``plan_id``; None when
    V_E = 0."""
    if seed is not None and not 0 <= int(seed) <= 2**32 - 1:
        raise _evade.InputError(f"seed = {seed}: expected an integer in [0, 4294967295]")
    params = param_values(**{"evasion.dv_mps": dv_mps, "transfer.dt_s": dt_transfer_s,
                             "transfer.impulses": impulses})
    doc, plan = _evade.plan_threat_area(
        scenario_path(scenario), overrides(set), params, -1 if seed is None else int(seed),
        bool(eliminate), [float(v) for v in sweep_dv_mps or []],
        [float(v) for v in sweep_transfer_s or []], _check_plan_id(plan_id))
    return PlanResult(doc, plan)


def plan_formation(scenario: Scenario = "seed3", *, set: Sets = None,
                   numerical_limits: bool = False, plan_id: int = 0) -> PlanResult:
    """Paper 003's avoidance decision, as ``evade plan formation`` makes it.

    scenario: a shipped name (default "seed3", the CLI's) or a YAML path; ``set``: overrides.
    ``numerical_limits``: also Table 1 by bisection on propagated margins (slower).
    ``burn_plan``: the Δa burn and the restore burn (t_s after the scenario's epoch; Δv in RSW
    and ECI), numbered ``plan_id``; None when no maneuver is needed or the decision is not
    feasible."""
    doc, plan = _evade.plan_formation(scenario_path(scenario), overrides(set),
                                      bool(numerical_limits), _check_plan_id(plan_id))
    return PlanResult(doc, plan)


def plan_observability(scenario: Scenario = "seed4", *, set: Sets = None,
                       objective: Optional[str] = None, seed: Optional[int] = None,
                       plan_id: int = 0) -> PlanResult:
    """Paper 004's observability-minimizing burn, as ``evade plan observability`` plans it.

    scenario: a shipped name (default "seed4", the CLI's) or a YAML path; ``set``: overrides.
    ``objective``: 'paper' | 'los-change' | 'estimation' (default: the scenario's
    objective.name); ``seed``: the ISRES seed in [0, 2147483647] (default: isres.seed).
    ``burn_plan``: one RSW impulse at t0 (no ECI Δv) with ``observability`` (ε, θ [rad], the
    objective, its value, evaluations), numbered ``plan_id``."""
    if objective is not None and objective not in ("paper", "los-change", "estimation"):
        raise _evade.InputError(
            f"objective '{objective}' is unknown; allowed: paper, los-change, estimation")
    if seed is not None and int(seed) < 0:  # above 2147483647: the library's message
        raise _evade.InputError(f"seed = {seed}: expected an integer in [0, 2147483647]")
    doc, plan = _evade.plan_observability(scenario_path(scenario), overrides(set), objective or "",
                                          -1 if seed is None else int(seed),
                                          _check_plan_id(plan_id))
    return PlanResult(doc, plan)
