"""evade.plan_threat_area, plan_formation and plan_observability against `evade plan
threat-area|formation|observability`: the same input gives the CLI's --json document, the
burn plan is the one the CLI writes with --plan-out, and bad input gives the CLI's message."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

import evade
from conftest import cli_message, without_wall_times

# A faster threat-area search than seed1's (the CLI suite's publish tests use the same).
FAST_THREAT = ["sweep.step_s=20", "evasion.max_evaluations=200"]




def set_args(sets):
    return [a for s in sets for a in ("--set", s)]


def assert_burn_plan_is_the_plan_file(plan, path):
    f = json.loads(path.read_text())
    imp = f["impulses"]
    eci = np.array([[math.nan] * 3 if i.get("dv_eci_mps") is None else i["dv_eci_mps"] for i in imp])
    assert plan["plan_id"] == f["plan_id"] and plan["source"] == f["source"]
    np.testing.assert_array_equal(plan["t_s"], [i["t_s"] for i in imp])
    np.testing.assert_array_equal(plan["dv_rsw_mps"], [i["dv_rsw_mps"] for i in imp])
    np.testing.assert_array_equal(plan["dv_eci_mps"], eci)
    np.testing.assert_array_equal(plan["dv_eci_valid"], ~np.isnan(eci[:, 0]))


def cli_with_plan_file(cli_json, args, tmp_path, plan_id):
    """The CLI's document with --plan-out (its "plan_file" entry removed) and the file."""
    out = tmp_path / "plan.json"
    doc = cli_json([*args, "--plan-out", str(out), "--seq", str(plan_id)])
    assert doc.pop("plan_file") == str(out)
    return doc, out


def assert_bad_input(cli_error, args, call):
    rc, err = cli_error(args)
    assert rc == 2
    with pytest.raises(evade.InputError) as e:
        call()
    assert str(e.value) == cli_message(err)


# --- threat-area (paper 001) -------------------------------------------------------------

def test_plan_threat_area_equals_cli(cli_json, tmp_path):
    doc, out = cli_with_plan_file(cli_json, ["plan", "threat-area", "--scenario", "seed1"], tmp_path, 4)
    r = evade.plan_threat_area("seed1", plan_id=4)
    assert without_wall_times(r.to_dict()) == without_wall_times(doc)
    assert r.threat_arc_s == 2543.14453125
    assert_burn_plan_is_the_plan_file(r.burn_plan, out)
    assert r.burn_plan["source"] == "threat-area" and not r.burn_plan["dv_eci_valid"].any()


def test_plan_threat_area_flags_equal_cli(cli_json):
    args = ["plan", "threat-area", "--scenario", "seed1", *set_args(FAST_THREAT), "--dv-mps", "25",
            "--dt-transfer-s", "2000", "--impulses", "3", "--seed", "5"]
    r = evade.plan_threat_area("seed1", set=FAST_THREAT, dv_mps=25.0, dt_transfer_s=2000,
                               impulses=3, seed=5)
    assert without_wall_times(r.to_dict()) == without_wall_times(cli_json(args))
    assert np.linalg.norm(r.burn_plan["dv_rsw_mps"][0]) == pytest.approx(25.0, rel=1e-9)


def test_plan_threat_area_sweeps_equal_cli(cli_json):
    args = ["plan", "threat-area", "--scenario", "seed1", *set_args(FAST_THREAT),
            "--sweep-dv", "10,30", "--sweep-transfer", "1400,2200"]
    r = evade.plan_threat_area("seed1", set=FAST_THREAT, sweep_dv_mps=[10, 30],
                               sweep_transfer_s=(1400.0, 2200.0))
    assert without_wall_times(r.to_dict()) == without_wall_times(cli_json(args))


def test_plan_threat_area_eliminate_equals_cli(cli_json):
    sets = FAST_THREAT + ["sweep.edge_tol_s=0.5", "evasion.seed=3", "elimination.tol_mps=1"]
    doc = cli_json(["plan", "threat-area", "--scenario", "seed1", "--eliminate", *set_args(sets)])
    r = evade.plan_threat_area("seed1", set=sets, eliminate=True)
    assert without_wall_times(r.to_dict()) == without_wall_times(doc)


def test_plan_threat_area_without_a_burn_has_no_plan(cli_json):
    doc = cli_json(["plan", "threat-area", "--scenario", "seed1", *set_args(FAST_THREAT), "--dv-mps", "0"])
    r = evade.plan_threat_area("seed1", set=FAST_THREAT, dv_mps=0)
    assert without_wall_times(r.to_dict()) == without_wall_times(doc)
    assert r.burn_plan is None


THREAT_BAD = {
    "impulses_out_of_range": (dict(set={"transfer.impulses": 5}), ["--set", "transfer.impulses=5"]),
    "negative_dv_keyword": (dict(dv_mps=-1), ["--set", "evasion.dv_mps=-1"]),
    "nan_transfer_time": (dict(dt_transfer_s=math.nan), ["--set", "transfer.dt_s=nan"]),
    "negative_sweep_dv": (dict(sweep_dv_mps=[-1]), ["--sweep-dv", "-1"]),
    "unknown_key": (dict(set=["evasion.bogus=1"]), ["--set", "evasion.bogus=1"]),
}


@pytest.mark.parametrize("case", sorted(THREAT_BAD))
def test_plan_threat_area_bad_input_message_is_the_clis(cli_error, case):
    kwargs, args = THREAT_BAD[case]
    assert_bad_input(cli_error, ["plan", "threat-area", "--scenario", "seed1", *args],
                     lambda: evade.plan_threat_area("seed1", **kwargs))


def test_plan_threat_area_unknown_scenario(cli_error):
    assert_bad_input(cli_error, ["plan", "threat-area", "--scenario", "nope"],
                     lambda: evade.plan_threat_area("nope"))


# --- formation (paper 003) ---------------------------------------------------------------

def test_plan_formation_equals_cli(cli_json, tmp_path):
    doc, out = cli_with_plan_file(cli_json, ["plan", "formation"], tmp_path, 2)
    r = evade.plan_formation(plan_id=2)
    assert without_wall_times(r.to_dict()) == without_wall_times(doc)
    assert_burn_plan_is_the_plan_file(r.burn_plan, out)
    assert r.burn_plan["t_s"].shape == (2,) and r.burn_plan["dv_eci_valid"].all()


def test_plan_formation_numerical_limits_equal_cli(cli_json):
    doc = cli_json(["plan", "formation", "--scenario", "seed3", "--numerical-limits"])
    r = evade.plan_formation("seed3", numerical_limits=True)
    assert without_wall_times(r.to_dict()) == without_wall_times(doc)


def test_plan_formation_infeasible_has_no_plan(cli_json):
    doc = cli_json(["plan", "formation", "--scenario", "seed3-infeasible"])
    r = evade.plan_formation("seed3-infeasible")
    assert without_wall_times(r.to_dict()) == without_wall_times(doc)
    assert r.burn_plan is None


FORMATION_BAD = {
    "bad_earth": ["earth.re_m=2e7"],
    "burn_before_epoch": ["maneuver.burn_before_tca_s=200000"],
    "nan_value": ["maneuver.burn_before_tca_s=nan"],
    "unknown_key": ["bogus.key=1"],
}


@pytest.mark.parametrize("case", sorted(FORMATION_BAD))
def test_plan_formation_bad_input_message_is_the_clis(cli_error, case):
    sets = FORMATION_BAD[case]
    assert_bad_input(cli_error, ["plan", "formation", *set_args(sets)],
                     lambda: evade.plan_formation(set=sets))


# --- observability (paper 004) -----------------------------------------------------------

def test_plan_observability_equals_cli(cli_json, tmp_path):
    doc, out = cli_with_plan_file(cli_json, ["plan", "observability"], tmp_path, 7)
    r = evade.plan_observability(plan_id=7)
    assert without_wall_times(r.to_dict()) == without_wall_times(doc)
    assert_burn_plan_is_the_plan_file(r.burn_plan, out)
    extras = r.burn_plan["observability"]
    assert (extras["eps_rad"], extras["theta_rad"]) == (r.eps_rad, r.theta_rad)
    assert (extras["objective"], extras["objective_value"]) == (r.objective, r.value)
    assert extras["evaluations"] == r.evaluations


def test_plan_observability_objective_and_seed_equal_cli(cli_json):
    doc = cli_json(["plan", "observability", "--scenario", "seed4", "--objective", "los-change", "--seed", "3"])
    r = evade.plan_observability("seed4", objective="los-change", seed=3)
    assert without_wall_times(r.to_dict()) == without_wall_times(doc)
    assert r.objective == "los-change"


OBSERVABILITY_BAD = {
    "zero_dv": ["burn.dv_mps=0"],
    "nan_state": ["chaser.r_paper_m=[nan,0,0]"],
    "inverted_bounds": ["burn.theta_min_rad=-1.0"],
    "unknown_key": ["burn.dv=3"],
}


@pytest.mark.parametrize("case", sorted(OBSERVABILITY_BAD))
def test_plan_observability_bad_input_message_is_the_clis(cli_error, case):
    sets = OBSERVABILITY_BAD[case]
    assert_bad_input(cli_error, ["plan", "observability", *set_args(sets)],
                     lambda: evade.plan_observability(set=sets))


def test_plan_observability_refuses_bad_keywords():
    with pytest.raises(evade.InputError, match="objective 'bogus' is unknown"):
        evade.plan_observability(objective="bogus")
    with pytest.raises(evade.InputError, match="seed"):
        evade.plan_observability(seed=-4)
    with pytest.raises(evade.InputError, match="2147483647"):
        evade.plan_observability(seed=3_000_000_000)
    with pytest.raises(evade.InputError, match="plan_id"):
        evade.plan_formation(plan_id=-1)
