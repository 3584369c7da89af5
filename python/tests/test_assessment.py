"""evade.assess, evade.plan_cam and the CDM reader/writer against `evade assess|plan cam`: the
same input gives the CLI's --json document, and bad input the CLI's error message."""
from __future__ import annotations

import json
import math
import subprocess
import warnings

import numpy as np
import pytest

import evade
from conftest import _cli_path, cli_message, without_wall_times

CASE01 = "scenarios/cdm/alfano-2009-case01.cdm"
CAM_CDM = "scenarios/cdm/cam-example.cdm"
NPD_CDM = "test/assess_cli/data/alfano-2009-case01-velocity-npd-orekit-units.cdm"
ZERO_SPEED_CDM = "test/assess_cli/data/alfano-2009-case11-zero-relative-velocity.cdm"




def quiet_assess(*args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return evade.assess(*args, **kwargs)


# --- evade.assess ------------------------------------------------------------------------

@pytest.mark.parametrize("plane", [[0, 10, 25, 50, 5], "0,10,25,50,5", (0.0, 10.0, 25.0, 50.0)])
def test_assess_encounter_plane_equals_cli(cli_json, plane):
    hbr = 5.0 if len(plane) == 4 else None
    doc = cli_json(["assess", "--encounter-plane", "0,10,25,50,5"])
    assert evade.assess(encounter_plane=plane, hbr_m=hbr).to_dict() == doc


@pytest.mark.parametrize("threads", [1, 2])
def test_assess_scenario_monte_carlo_equals_cli(cli_json, repo, threads):
    # The CLI on 2 threads; the Monte Carlo depends on the seed only, not on the threads.
    scenario = str(repo / "scenarios/assess-example.yaml")
    doc = cli_json(["assess", "--scenario", scenario, "--mc", "20000", "--seed", "7", "--threads", "2"])
    r = evade.assess(scenario, mc=20000, seed=7, threads=threads)
    assert r.to_dict() == doc
    assert r.pc_mc_low <= r.pc_mc <= r.pc_mc_high


def test_assess_monte_carlo_with_j2_equals_cli(cli_json, repo):
    scenario = str(repo / "scenarios/formation-conjunction.yaml")
    doc = cli_json(["assess", "--scenario", scenario, "--mc", "10000",
                    "--set", "assessment.mc_j2=true", "--threads", "2"])
    r = evade.assess(scenario, mc=10000, threads=2, set={"assessment.mc_j2": True})
    assert r.to_dict() == doc


@pytest.mark.parametrize("cdm,hbr,window,sets", [
    (CASE01, 15.0, None, ["assessment.tca_search_s=0"]),
    ("test/data/alfano2009/AlfanoTestCase01.cdm", 15.0, 21600.0, ["assessment.tca_search_s=0"]),
    (CAM_CDM, 15.0, None, []),
    ("test/assess_cli/data/alfano-2009-case01-drag-row-npd.cdm", 15.0, None, []),
])
def test_assess_cdm_equals_cli(cli_json, repo, cdm, hbr, window, sets):
    path = str(repo / cdm)
    args = ["assess", "--cdm", path, "--hbr-m", repr(hbr)]
    if window is not None:
        args += ["--window-s", repr(window)]
    for s in sets:
        args += ["--set", s]
    r = quiet_assess(cdm=path, hbr_m=hbr, window_s=window, set=sets)
    assert r.to_dict() == cli_json(args)
    if window is not None:  # Alfano case 1 (GEO, 14 mm/s) fails the 2D usage checks
        assert r.method == "3d_nc"


def test_assess_warnings_are_the_clis_stderr(repo):
    path = str(repo / NPD_CDM)
    p = subprocess.run([_cli_path(), "assess", "--cdm", path, "--hbr-m", "15", "--json"],
                       capture_output=True, text=True, check=True)
    stderr_lines = [ln for ln in p.stderr.splitlines() if ln.startswith("evade assess: ")]
    with pytest.warns(RuntimeWarning) as caught:
        r = evade.assess(cdm=path, hbr_m=15)
    assert r.to_dict() == json.loads(p.stdout)
    assert [str(w.message) for w in caught] == stderr_lines
    assert ["evade assess: " + w for w in r.warnings] == stderr_lines
    assert r.covariance_repaired[0] is True


def test_assess_cdm_given_as_text_or_object(repo):
    path = repo / CASE01
    by_path = quiet_assess(cdm=path, hbr_m=15).to_dict()
    by_text = quiet_assess(cdm=path.read_text(), hbr_m=15).to_dict()
    by_object = quiet_assess(cdm=evade.read_cdm(path), hbr_m=15).to_dict()
    assert by_text.pop("source") == "cdm <text>"
    assert by_object.pop("source") == f"cdm {path}"
    by_path.pop("source")
    assert by_path == by_text == by_object


# --- CDM ---------------------------------------------------------------------------------

def test_read_cdm_fields(cli_json, repo):
    path = str(repo / CASE01)
    c = evade.read_cdm(path)
    doc = cli_json(["assess", "--cdm", path, "--hbr-m", "15"])["cdm"]
    assert c.message_id == doc["message_id"] == "A09_case_01"
    assert c.tca_utc == doc["tca"]
    assert c.miss_distance_m == doc["miss_distance_m"] == 5.049717
    assert c.relative_speed_mps == doc["relative_speed_mps"]
    assert c.collision_probability == doc["collision_probability"]
    assert c.collision_probability_method == doc["collision_probability_method"]
    assert c.tca_j2000_s == -43200.0  # 2000-01-01T00:00:00 UTC is J2000 minus 12 h
    np.testing.assert_array_equal(c.relative_position_rtn_m, [-0.502165, -0.497806, 4.999966])
    assert c.object1.ref_frame == "EME2000" and c.object1.designator == "1001"
    np.testing.assert_allclose(c.object1.r_ref_frame_m, [153446.765, 41874155.870, 0.0], rtol=1e-15)
    np.testing.assert_allclose(c.object1.v_ref_frame_mps, [3066.874761, -11.373615, 0.0], rtol=1e-15)
    cov = c.object1.cov_rtn_m2
    assert cov.shape == (6, 6) and np.allclose(cov, cov.T)
    assert cov[0, 0] == float(c.object1.covariance["CR_R"])
    assert c.object1.cov_rows[:6] == ["R", "T", "N", "RDOT", "TDOT", "NDOT"]
    full = c.object1.cov_rtn_full_si
    assert full.shape == (len(c.object1.cov_rows),) * 2
    np.testing.assert_array_equal(full[:6, :6], cov)


def test_cdm_round_trips_through_kvn_and_xml(repo, tmp_path):
    c = evade.read_cdm(repo / CASE01)
    assert evade.read_cdm(c.to_kvn()) == c
    assert evade.read_cdm(c.to_xml()) == c
    for fmt in ("kvn", "xml"):
        out = tmp_path / f"case01.{fmt}"
        evade.write_cdm(c, out, format=fmt)
        back = evade.read_cdm(out)
        assert back == c and back.source == str(out)
    assert c.to_xml().lstrip().startswith("<")
    with pytest.raises(evade.InputError, match="format 'json' is unknown"):
        evade.write_cdm(c, tmp_path / "x", format="json")


def test_read_cdm_notes_equivalent_units(repo):
    c = evade.read_cdm(repo / NPD_CDM)
    assert any("m**2/s**2" in n for n in c.notes)


def _bad_cdms(repo, tmp_path):
    good = (repo / CASE01).read_text()
    lines = good.splitlines(keepends=True)
    edits = {
        "bad_epoch": [ln if not ln.startswith("TCA ") else "TCA = 2024-13-01T00:00:00\n" for ln in lines],
        "missing_miss": [ln for ln in lines if not ln.startswith("MISS_DISTANCE")],
        "bad_number": [ln if not ln.startswith("X    ") else "X = abc [km]\n" for ln in lines],
        "bad_unit": [ln.replace("[km/s]", "[m/s]", 1) if ln.startswith("X_DOT") else ln for ln in lines],
    }
    out = {}
    for name, new in edits.items():
        p = tmp_path / f"{name}.cdm"
        p.write_text("".join(new))
        out[name] = p
    return out


@pytest.mark.parametrize("case", ["bad_epoch", "missing_miss", "bad_number", "bad_unit"])
def test_bad_cdm_message_is_the_clis(cli_error, repo, tmp_path, case):
    path = _bad_cdms(repo, tmp_path)[case]
    rc, err = cli_error(["assess", "--cdm", str(path), "--hbr-m", "15"])
    assert rc == 2
    message = cli_message(err)
    assert message.startswith("CDM line")
    for call in (lambda: evade.assess(cdm=path, hbr_m=15), lambda: evade.assess(cdm=path.read_text(), hbr_m=15),
                 lambda: evade.read_cdm(path), lambda: evade.read_cdm(path.read_text()),
                 lambda: evade.plan_cam(cdm=path, hbr_m=15, lead_s=100)):
        with pytest.raises(evade.InputError) as e:
            call()
        assert str(e.value) == message


def test_missing_cdm_file(cli_error, tmp_path):
    path = str(tmp_path / "none.cdm")
    rc, err = cli_error(["assess", "--cdm", path, "--hbr-m", "15"])
    with pytest.raises(evade.InputError) as e:
        evade.assess(cdm=path, hbr_m=15)
    assert rc == 2 and str(e.value) == cli_message(err)
    with pytest.raises(evade.InputError, match="cannot open"):
        evade.read_cdm(path)


# Bad input of the CLI suite (test/assessment, test/assess_cli): (Python call, CLI args).
ASSESS_BAD = {
    "plane_of_three_numbers": (dict(encounter_plane="1,2,3"), ["--encounter-plane", "1,2,3"]),
    "no_encounter": (dict(), []),
    "two_encounters": (dict(scenario="{assess}", encounter_plane=[0, 10, 25, 50, 5]),
                       ["--scenario", "{assess}", "--encounter-plane", "0,10,25,50,5"]),
    "cdm_without_hbr": (dict(cdm="{case01}"), ["--cdm", "{case01}"]),
    "nan_hbr": (dict(cdm="{case01}", hbr_m=math.nan), ["--cdm", "{case01}", "--hbr-m", "nan"]),
    "window_with_plane": (dict(encounter_plane="0,10,25,50,5", window_s=100),
                          ["--encounter-plane", "0,10,25,50,5", "--window-s", "100"]),
    "mc_with_plane": (dict(encounter_plane="0,10,25,50,5", mc=10),
                      ["--encounter-plane", "0,10,25,50,5", "--mc", "10"]),
    "negative_window": (dict(scenario="{assess}", window_s=-5),
                        ["--scenario", "{assess}", "--set", "assessment.window_s=-5"]),
    "nan_window": (dict(cdm="{case01}", hbr_m=15, set={"assessment.window_s": math.nan}),
                   ["--cdm", "{case01}", "--hbr-m", "15", "--set", "assessment.window_s=nan"]),
    "unknown_key": (dict(cdm="{case01}", hbr_m=15, set=["assessment.bogus=1"]),
                    ["--cdm", "{case01}", "--hbr-m", "15", "--set", "assessment.bogus=1"]),
    "unknown_scenario_key": (dict(scenario="{assess}", set={"conjunction.bogus": 1}),
                             ["--scenario", "{assess}", "--set", "conjunction.bogus=1"]),
    "unknown_scenario": (dict(scenario="nope"), ["--scenario", "nope"]),
}


def _fill(value, names):
    if isinstance(value, str):
        return value.format(**names)
    if isinstance(value, list):
        return [_fill(v, names) for v in value]
    if isinstance(value, dict):
        return {k: _fill(v, names) for k, v in value.items()}
    return value


@pytest.mark.parametrize("case", sorted(ASSESS_BAD))
def test_assess_bad_input_message_is_the_clis(cli_error, repo, case):
    names = {"assess": str(repo / "scenarios/assess-example.yaml"), "case01": str(repo / CASE01)}
    kwargs, args = (_fill(x, names) for x in ASSESS_BAD[case])
    rc, err = cli_error(["assess", *args])
    assert rc == 2
    with pytest.raises(evade.InputError) as e:
        evade.assess(**kwargs)
    assert str(e.value) == cli_message(err)


def test_assess_refuses_out_of_range_keywords():
    for kwargs in (dict(mc=-1), dict(threads=300), dict(seed=-1)):
        with pytest.raises(evade.InputError):
            evade.assess(encounter_plane="0,10,25,50,5", **kwargs)
    with pytest.raises(evade.InputError, match="hbr_m"):
        evade.assess(cdm=CASE01, hbr_m=-1)
    assert isinstance(evade.InputError("x"), ValueError)


# --- evade.plan_cam ----------------------------------------------------------------------

def _plan_file_columns(path):
    f = json.loads(path.read_text())
    imp = f["impulses"]
    eci = [[math.nan] * 3 if i.get("dv_eci_mps") is None else i["dv_eci_mps"] for i in imp]
    return f, np.array([i["t_s"] for i in imp]), np.array([i["dv_rsw_mps"] for i in imp]), np.array(eci)


def assert_burn_plan_is_the_plan_file(plan, path):
    f, t_s, dv_rsw, dv_eci = _plan_file_columns(path)
    assert plan["plan_id"] == f["plan_id"] and plan["source"] == f["source"]
    np.testing.assert_array_equal(plan["t_s"], t_s)
    np.testing.assert_array_equal(plan["dv_rsw_mps"], dv_rsw)
    np.testing.assert_array_equal(plan["dv_eci_mps"], dv_eci)
    np.testing.assert_array_equal(plan["dv_eci_valid"], ~np.isnan(dv_eci[:, 0]))


def test_plan_cam_scenario_equals_cli(cli_json, repo, tmp_path):
    scenario = str(repo / "scenarios/cam-example.yaml")
    out = tmp_path / "cam_plan.json"
    doc = cli_json(["plan", "cam", "--scenario", scenario, "--lead-s", "17000", "--pc-max", "1e-4",
                    "--plan-out", str(out), "--seq", "3"])
    r = evade.plan_cam(scenario, lead_s=17000, pc_max=1e-4, plan_id=3)
    assert doc.pop("plan_file") == str(out)
    cli_plan = doc.pop("plan")  # --plan-out adds the impulses and the file's name
    assert r.to_dict() == doc
    assert r.verified_ok is True
    assert_burn_plan_is_the_plan_file(r.burn_plan, out)
    assert cli_plan[0]["dv_rsw_mps"] == r.burn_plan["dv_rsw_mps"][0].tolist()


def test_plan_cam_cdm_equals_cli(cli_json, repo):
    path = str(repo / CAM_CDM)
    doc = cli_json(["plan", "cam", "--cdm", path, "--hbr-m", "15", "--lead-s", "17000",
                    "--pc-max", "1e-4", "--min-miss-m", "50"])
    r = evade.plan_cam(cdm=path, hbr_m=15, lead_s=17000, pc_max=1e-4, min_miss_m=50)
    assert r.to_dict() == doc
    assert r.burn_plan["source"] == "collision-avoidance" and r.burn_plan["plan_id"] == 0
    assert r.burn_plan["dv_eci_valid"].tolist() == [True]


def test_plan_cam_along_track_only_equals_cli(cli_json, repo):
    scenario = str(repo / "scenarios/cam-example.yaml")
    doc = cli_json(["plan", "cam", "--scenario", scenario, "--lead-s", "17000", "--pc-max", "1e-4",
                    "--along-track-only"])
    r = evade.plan_cam(scenario, lead_s=17000, pc_max=1e-4, along_track_only=True)
    assert r.to_dict() == doc


@pytest.mark.parametrize("sweep", [(3000, 9000, 2), "3000:9000:2"])
def test_plan_cam_sweep_equals_cli_and_has_no_plan(cli_json, repo, sweep):
    scenario = str(repo / "scenarios/cam-example.yaml")
    doc = cli_json(["plan", "cam", "--scenario", scenario, "--pc-max", "1e-4", "--sweep-lead", "3000:9000:2"])
    r = evade.plan_cam(scenario, pc_max=1e-4, sweep_lead_s=sweep)
    assert r.to_dict() == doc
    assert r.burn_plan is None


CAM_BAD = {
    "negative_lead": (dict(lead_s=-5, pc_max=1e-4), ["--lead-s", "-5", "--pc-max", "1e-4"]),
    "lead_past_span": (dict(lead_s=1e6, pc_max=1e-4), ["--lead-s", "1e6", "--pc-max", "1e-4"]),
    "pc_max_zero": (dict(lead_s=17000, pc_max=0), ["--lead-s", "17000", "--pc-max", "0"]),
    "nan_pc_max": (dict(lead_s=17000, pc_max=math.nan), ["--lead-s", "17000", "--pc-max", "nan"]),
    "unreachable": (dict(lead_s=17000, pc_max=1e-4, set={"cam.max_dv_mps": 0.01}),
                    ["--lead-s", "17000", "--pc-max", "1e-4", "--set", "cam.max_dv_mps=0.01"]),
    "bad_sweep": (dict(pc_max=1e-4, sweep_lead_s="100:50"), ["--pc-max", "1e-4", "--sweep-lead", "100:50"]),
    "unknown_key": (dict(lead_s=17000, set=["cam.bogus=1"]), ["--lead-s", "17000", "--set", "cam.bogus=1"]),
}


@pytest.mark.parametrize("case", sorted(CAM_BAD))
def test_plan_cam_bad_input_message_is_the_clis(cli_error, repo, case):
    scenario = str(repo / "scenarios/cam-example.yaml")
    kwargs, args = CAM_BAD[case]
    rc, err = cli_error(["plan", "cam", "--scenario", scenario, *args])
    assert rc == 2
    with pytest.raises(evade.InputError) as e:
        evade.plan_cam(scenario, **kwargs)
    assert str(e.value) == cli_message(err)


def test_plan_cam_refuses_zero_relative_speed_and_two_sources(cli_error, repo):
    path = str(repo / ZERO_SPEED_CDM)
    rc, err = cli_error(["plan", "cam", "--cdm", path, "--hbr-m", "4", "--pc-max", "1e-4", "--lead-s", "1000"])
    with pytest.raises(evade.InputError) as e:
        evade.plan_cam(cdm=path, hbr_m=4, pc_max=1e-4, lead_s=1000)
    assert rc == 2 and str(e.value) == cli_message(err)
    assert "relative speed is zero" in str(e.value)
    rc, err = cli_error(["plan", "cam", "--lead-s", "1000"])
    with pytest.raises(evade.InputError) as e:
        evade.plan_cam(lead_s=1000)
    assert str(e.value) == cli_message(err)
