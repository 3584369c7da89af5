"""evade.simulate against `evade sim` (same JSON, same time history as --csv, same Monte Carlo)
and evade.GuidanceLaw stepped by hand (paper 000: STANDBY before a track, then thrust at
max_accel_mps2 along −e_θ; SAFE on bad nav; no thrust disarmed)."""
from __future__ import annotations

import csv
import math

import numpy as np
import pytest

import evade
from conftest import cli_message

NOISY = {"sensor.noise_rad": 50e-6, "sensor.has_rates": False}
NOISY_FLAGS = ["--set", "sensor.noise_rad=5e-05", "--set", "sensor.has_rates=false"]
# Fields a --realtime run adds from the wall clock; a lockstep run (the only kind simulate
# runs) has none, so its document compares whole with the CLI's.
WALL_CLOCK_KEYS = ("command_age_ms_p50", "command_age_ms_p99", "command_age_ms_max",
                   "sim_late_steps", "sim_late_max_ms", "start_utime_us")


def test_simulate_json_equals_cli(cli_json):
    doc = evade.simulate("seed0").to_dict()
    assert not any(k in doc for k in WALL_CLOCK_KEYS)
    assert doc == cli_json(["sim", "--scenario", "seed0"])


def test_simulate_json_with_overrides_equals_cli(cli_json):
    doc = evade.simulate("seed0", set={"guidance.max_accel_mps2": 0.5, **NOISY}).to_dict()
    flags = ["--set", "guidance.max_accel_mps2=0.5", *NOISY_FLAGS]
    assert doc == cli_json(["sim", "--scenario", "seed0", *flags])


def test_series_equals_cli_csv(cli_json, tmp_path):
    path = tmp_path / "run.csv"
    cli_json(["sim", "--scenario", "seed0", "--csv", str(path)])
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    series = evade.simulate("seed0").series
    assert list(series) == list(rows[0])  # the CSV's columns, in its order
    for name, values in series.items():
        assert len(values) == len(rows)
        cli = [r[name] for r in rows]
        if name in ("mode", "reason"):
            assert values.tolist() == cli
        elif name in ("has_meas", "fallback"):
            assert values.dtype == bool and values.tolist() == [c == "1" for c in cli]
        else:  # the CSV prints 15 significant digits
            np.testing.assert_allclose(values, np.array(cli, dtype=float), rtol=1e-13,
                                       atol=1e-9, err_msg=name)


def test_series_closest_approach_agrees_with_miss_and_tca():
    r = evade.simulate("seed0")
    s = r.series
    t, rel = s["t_s"], np.stack([s["rel_x_m"], s["rel_y_m"], s["rel_z_m"]], axis=1)
    assert t[0] == pytest.approx(r.start_s, abs=1e-6)
    assert t[-1] <= r.tca_s < t[-1] + 1.0 / r.parameters.guidance.rate_hz
    assert np.all(np.diff(s["range_m"]) < 0.0)  # closing up to the last sample before TCA
    # Straight-line closest approach from the last two samples (1 m/s^2 bends the path by
    # 0.2 mm over a 20 ms cycle).
    v = (rel[-1] - rel[-2]) / (t[-1] - t[-2])
    dt = -rel[-1].dot(v) / v.dot(v)
    assert t[-1] + dt == pytest.approx(r.tca_s, abs=1e-5)
    assert np.linalg.norm(rel[-1] + v * dt) == pytest.approx(r.miss_m, abs=0.02)
    assert s["mode"][-1] == r.final_mode and s["mode"][0] == "EVADE"


def test_monte_carlo_equals_cli(cli_json):
    r = evade.simulate("seed0", set=NOISY, runs=20, seed=7, threads=2, series=False)
    cli = cli_json(["sim", "--scenario", "seed0", *NOISY_FLAGS, "--runs", "20", "--seed", "7",
                    "--threads", "2"])
    assert r.to_dict() == cli
    assert r.series == {}
    miss = r.monte_carlo_miss_m
    assert miss.shape == (20,) and r.monte_carlo_dv_mps.shape == (20,)
    assert np.percentile(miss, 50) == pytest.approx(r.miss_m_p50, rel=1e-12)
    assert miss.min() == r.miss_m_min and miss.max() == r.miss_m_max


def test_monte_carlo_run_flown_alone_by_its_seeds():
    mc = evade.simulate("seed0", set=NOISY, runs=3, seed=7, series=False)
    for i in range(3):
        one = evade.simulate("seed0", set={**NOISY, **evade.monte_carlo_seeds(7, i)}, series=False)
        assert one.miss_m == mc.monte_carlo_miss_m[i]


# ---- bad input: the CLI's message ---------------------------------------------------------

@pytest.mark.parametrize("sets", [
    ["guidance.max_accel_mps2=500"],
    ["guidance.max_accel_mps2=nan"],
    ["sensor.noise_rad=.nan"],
    ["satellite.r_eci_m=[1,.nan,3]"],
    ["sensor.noise=1e-6"],
    ["encounter.detect_before_tca_s=inf"],
])
def test_bad_scenario_value_gives_cli_message(cli_error, sets):
    rc, err = cli_error(["sim", *[a for kv in sets for a in ("--set", kv)]])
    assert rc == 2
    with pytest.raises(evade.InputError) as e:
        evade.simulate(set=sets)
    assert str(e.value) == cli_message(err)


@pytest.mark.parametrize("flag,kwargs", [
    (["--runs", "-3"], {"runs": -3}),
    (["--threads", "0"], {"threads": 0}),
    (["--threads", "65"], {"threads": 65}),
    (["--seed", "-1"], {"seed": -1}),
])
def test_bad_run_option_gives_cli_message(cli_error, flag, kwargs):
    rc, err = cli_error(["sim", *flag])
    assert rc == 2
    with pytest.raises(evade.InputError) as e:
        evade.simulate(**kwargs)
    # The keyword's name stands for the flag: "runs = -3 outside ..." for "--runs = -3 ...".
    assert str(e.value) == cli_message(err).replace(flag[0], flag[0][2:])


def test_unknown_scenario_gives_cli_message(cli_error):
    _, err = cli_error(["sim", "--scenario", "nope"])
    with pytest.raises(evade.InputError) as e:
        evade.simulate("nope")
    # The directories searched are the process's own (beside the executable): not compared.
    assert str(e.value).split(" (searched")[0] == cli_message(err).split(" (searched")[0]


# ---- GuidanceLaw ----------------------------------------------------------------------------

R_SAT = (6.8e6, 0.0, 0.0)
V_SAT = (0.0, 7500.0, 0.0)
EL0, AZ0, EL_RATE, AZ_RATE = 0.1, 0.5, 2e-3, 1e-2


def _angles(t_s):
    """A threat whose LOS turns at constant elevation/azimuth rates."""
    return EL0 + EL_RATE * t_s, AZ0 + AZ_RATE * t_s


def _minus_e_theta(t_s):
    """−e_θ from the true LOS and its rate, with the zenith convention (los_geometry.hpp)."""
    el, az = _angles(t_s)
    ys = np.array([-math.cos(az) * math.sin(el), -math.sin(az) * math.sin(el), math.cos(el)])
    zs = np.array([math.sin(az), -math.cos(az), 0.0])
    u = np.array([math.cos(az) * math.cos(el), math.sin(az) * math.cos(el), math.sin(el)])
    e_theta = EL_RATE * ys - AZ_RATE * math.cos(el) * zs
    e_theta /= np.linalg.norm(e_theta)
    if np.cross(u, e_theta).dot(np.array(R_SAT)) < 0.0:
        e_theta = -e_theta
    return -e_theta


def _step(law, t_s, r=R_SAT, armed=True):
    el, az = _angles(t_s)
    return law.step(t_s, r, V_SAT, True, el, az, 1e-6, armed, True, EL_RATE, AZ_RATE, 1e-7)


def test_law_standby_then_evade_along_minus_e_theta():
    law = evade.GuidanceLaw({"max_accel_mps2": 0.5})
    c = law.step(0.0, R_SAT, V_SAT)  # no measurement yet
    assert (c.mode, c.reason) == ("STANDBY", "no_track")
    assert c.accel_mps2 == 0.0 and c.u_eci == (0.0, 0.0, 0.0)
    assert _step(law, 0.02).mode == "STANDBY"  # one update of the two a track needs
    for k in range(2, 10):
        t = 0.02 * k
        c = _step(law, t)
        assert (c.mode, c.reason) == ("EVADE", "none")
        assert c.accel_mps2 == 0.5 and c.t_s == pytest.approx(t)
        u = np.array(c.u_eci)
        assert np.linalg.norm(u) == pytest.approx(1.0, abs=1e-12)
        np.testing.assert_allclose(u, _minus_e_theta(t), atol=1e-4)
        np.testing.assert_allclose(u, -law.status().e_theta_eci, atol=1e-12)
        np.testing.assert_allclose(c.accel_eci_mps2, 0.5 * u, atol=1e-15)
    st = law.status()
    # 9 measurements: the first initialises the filter, the other 8 are accepted updates.
    assert st.mode == "EVADE" and st.track_valid
    assert (st.meas_accepted, st.meas_rejected, st.filter_reinits) == (8, 0, 0)
    assert st.dv_used_mps == pytest.approx(0.5 * 0.02 * 7, rel=1e-9)


def test_law_safe_on_nan_nav_and_back():
    law = evade.GuidanceLaw("seed0")  # one update makes a track there
    assert _step(law, 0.0).mode == "EVADE"
    c = _step(law, 0.02, r=(math.nan, 0.0, 0.0))
    assert (c.mode, c.reason, c.accel_mps2) == ("SAFE", "nav_invalid", 0.0)
    c = law.step(0.04, R_SAT, V_SAT, nav_valid=False)
    assert (c.mode, c.reason) == ("SAFE", "nav_invalid")
    assert _step(law, 0.06).mode == "EVADE"  # not latched


def test_law_disarmed_gives_no_thrust_and_reset_forgets_the_track():
    law = evade.GuidanceLaw("seed0", set={"guidance.armed": False})
    assert law.config["armed"] is False and law.config["min_track_updates"] == 1
    for k in range(5):
        c = _step(law, 0.02 * k, armed=False)
        assert c.accel_mps2 == 0.0 and c.u_eci == (0.0, 0.0, 0.0)
    assert (c.mode, c.reason) == ("TRACKING", "disarmed")
    law.reset()
    assert law.status().mode == "STANDBY" and law.status().dv_used_mps == 0.0


def test_law_takes_numpy_and_lists_like_tuples():
    a, b = evade.GuidanceLaw(), evade.GuidanceLaw()
    for k in range(4):
        t = 0.02 * k
        el, az = _angles(t)
        ca = a.step(t, R_SAT, V_SAT, True, el, az, 1e-6, True, True, EL_RATE, AZ_RATE, 1e-7)
        cb = b.step(t, np.array(R_SAT), list(V_SAT), has_measurement=True, elevation_rad=el,
                    azimuth_rad=az, sigma_angle_rad=1e-6, has_rates=True,
                    elevation_rate_radps=EL_RATE, azimuth_rate_radps=AZ_RATE,
                    sigma_rate_radps=1e-7)
        assert repr(ca) == repr(cb)


def test_law_bad_config_gives_library_message():
    with pytest.raises(evade.InputError, match=r"key 'guidance.max_accel_mps2' = '500' is invalid: "
                                               r"expected a number in \(0, 100\] m/s\^2"):
        evade.GuidanceLaw({"max_accel_mps2": 500})
    with pytest.raises(evade.InputError, match="unknown key 'guidance.max_accel'"):
        evade.GuidanceLaw({"max_accel": 1.0})
    with pytest.raises(evade.InputError, match="scenario 'nope' not found"):
        evade.GuidanceLaw("nope")


def test_law_bad_step_arguments():
    law = evade.GuidanceLaw()
    with pytest.raises(evade.InputError, match="r_eci_m: expected 3 numbers"):
        law.step(0.0, (1.0, 2.0), V_SAT)
    with pytest.raises(evade.InputError, match="v_eci_mps: expected 3 numbers"):
        law.step(0.0, R_SAT, ("a", 0.0, 0.0))
    with pytest.raises(evade.InputError, match="t_s = nan"):
        law.step(math.nan, R_SAT, V_SAT)


def test_guidance_law_config_keyword_is_the_double_given():
    # docs/ARCHITECTURE.md "A parameter's way": 0.1 + 0.2 has no short decimal form; the
    # keyword's value reaches the law's config as that double (typed, no text on the way).
    v = 0.1 + 0.2
    assert evade.GuidanceLaw({"max_accel_mps2": v}).config["max_accel_mps2"] == v
    assert evade.GuidanceLaw({"guidance.max_accel_mps2": v}).config["max_accel_mps2"] == v
    assert evade.GuidanceLaw("seed0", set={"guidance.max_accel_mps2": v}).config["max_accel_mps2"] == v
    with pytest.raises(evade.InputError, match=r"key 'guidance.max_accel_mps2' = 'true' is invalid"):
        evade.GuidanceLaw({"max_accel_mps2": True})  # a bool is not a number


def test_law_config_matches_a_simulated_scenario(cli_json):
    cfg = evade.GuidanceLaw("seed0", set={"guidance.max_accel_mps2": 2.0}).config
    used = cli_json(["sim", "--set", "guidance.max_accel_mps2=2"])["scenario_used"]["guidance"]
    assert cfg["max_accel_mps2"] == 2.0
    assert cfg["filter.gate_chi2_2dof"] == float(used["filter"]["gate_chi2_2dof"])
