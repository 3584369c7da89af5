"""evade.sgp4: catalogs read as the CLI reads them, and propagate() against `evade propagate`
(the same theory, four lanes at a time here where the CLI takes one: within the four-lane
bound, 1e-12 |r| and 1e-6 m/s, sgp4.hpp) and against python sgp4's SatrecArray (an independent
implementation of the same theory: within 1 cm and 10 µm/s)."""
from __future__ import annotations

import numpy as np
import pytest

import evade
from conftest import cli_message

CATALOG = "scenarios/catalogs/synthetic-1200.tle"


@pytest.mark.parametrize("frame", ["teme", "eci"])
def test_propagate_equals_cli_json_within_the_lane_bound(repo, cli_json, frame):
    doc = cli_json(["propagate", "--tle", str(repo / CATALOG), "--span-s", "3600", "--step-s", "600",
                    "--frame", frame])
    t_s = np.arange(0.0, 3601.0, 600.0)
    p = evade.sgp4.propagate(repo / CATALOG, None, t_s, frame=frame, threads=2)
    assert p.start_utc == doc["start_utc"]
    assert p.r_m.shape == (len(doc["objects"]), len(t_s), 3)
    assert list(p.ids) == [o["id"] for o in doc["objects"]]
    assert p.names == [o["name"] for o in doc["objects"]]
    r_cli = np.array([[s["r_m"] for s in o["states"]] for o in doc["objects"]])
    v_cli = np.array([[s["v_mps"] for s in o["states"]] for o in doc["objects"]])
    # kSgp4X4DeepPositionErrorRel (the larger of the two lane bounds) and sgp4_x4_test's 1e-6 m/s
    dr = np.linalg.norm(p.r_m - r_cli, axis=-1)
    assert np.all(dr <= 1e-12 * np.linalg.norm(r_cli, axis=-1))
    assert np.max(np.linalg.norm(p.v_mps - v_cli, axis=-1)) <= 1e-6
    assert not p.error.any()
    only_r = evade.sgp4.propagate(repo / CATALOG, None, t_s, frame=frame, threads=2, velocities=False)
    assert only_r.v_mps is None and np.array_equal(only_r.r_m, p.r_m)


def test_propagate_matches_python_sgp4_satrec_array(repo):
    api = pytest.importorskip("sgp4.api")
    lines = (repo / CATALOG).read_text().splitlines()
    tle = [(lines[k + 1], lines[k + 2]) for k in range(0, len(lines) - 2, 3) if lines[k + 1].startswith("1 ")]
    sats = api.SatrecArray([api.Satrec.twoline2rv(a, b) for a, b in tle])
    t_s = np.arange(0.0, 86401.0, 3600.0)
    p = evade.sgp4.propagate(repo / CATALOG, "2026-11-17T00:00:00Z", t_s)
    # The start as a split Julian date: 2026-11-17 00:00 UTC is JD 2461361.5 exactly.
    jd = np.full_like(t_s, 2461361.5)
    fr = t_s / 86400.0
    err, r_km, v_kmps = sats.sgp4(jd, fr)
    assert p.r_m.shape == r_km.shape
    assert np.array_equal(p.error, err.astype(np.int32))
    # Tolerances: both evaluate tsince from their own epoch arithmetic (seconds since J2000
    # here, split Julian dates there): 1e-7 s of tsince is 0.8 mm at 7.5 km/s.
    assert np.max(np.abs(p.r_m - r_km * 1e3)) < 0.01
    assert np.max(np.abs(p.v_mps - v_kmps * 1e3)) < 1e-5


def test_catalog_text_names_each_bad_entry(repo):
    text = (repo / "test/sgp4/data/one_bad_checksum.tle").read_text()
    cat = evade.sgp4.read_catalog(text)
    assert cat.bad_entries == 1 and len(cat.issues) == 1
    assert "checksum" in cat.issues[0]
    assert len(cat) == len(cat.ids) == len(cat.names) > 0
    p = evade.sgp4.propagate(text, None, [0.0, 60.0])
    assert p.issues == cat.issues and p.r_m.shape == (len(cat), 2, 3)


def test_latin1_and_control_character_titles(tmp_path):
    # Issue 46: a 3LE title in Latin-1 (0xC9) is read as Latin-1 ('É'), not left as bytes that
    # raised UnicodeDecodeError in .names; a control character refuses the title at its column.
    sets = ("1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927\n"
            "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537\n")
    path = tmp_path / "latin1.tle"
    path.write_bytes(b"ISS \xc9TOILE\n" + sets.encode())
    cat = evade.sgp4.read_catalog(path)
    assert cat.names == ["ISS \u00c9TOILE"] and cat.bad_entries == 0
    assert evade.sgp4.propagate(path, None, [0.0]).names == ["ISS \u00c9TOILE"]
    cat = evade.sgp4.read_catalog("ISS\x07\n" + sets)
    assert cat.names == [""] and cat.bad_entries == 1
    assert "1:4: expected a title of printable characters" in cat.issues[0]


def test_errors_per_instant_with_nan_states():
    # Two high-drag element sets of SGP4-VER (Vallado et al. 2006): 22312 leaves the theory's
    # domain (mean eccentricity, code 1) 29 400 s after its epoch, 28872 decays (code 6) by
    # 3 120 s. Each instant is computed on its own: the instant after the error is given too,
    # an error has NaN states, a decay keeps the state the theory computed (as python sgp4).
    ecc = ("1 22312U 93002D   06094.46235912  .99999999  81888-5  49949-3 0  3953\n"
           "2 22312  62.1486  77.4698 0308723 267.9229  88.7392 15.95744531 98783\n")
    p = evade.sgp4.propagate(ecc, None, [0.0, 29400.0, 60.0])
    assert list(p.error[0]) == [0, 1, 0]
    assert np.isnan(p.r_m[0, 1]).all() and np.isnan(p.v_mps[0, 1]).all()
    assert np.isfinite(p.r_m[0, [0, 2]]).all()
    assert evade.sgp4.error_text(1) != "none"
    decay = ("1 28872U 05037B   05333.02012661  .25992681  00000-0  24476-3 0  1534\n"
             "2 28872  96.4736 157.9986 0303955 244.0492 110.6523 16.46015938 10708\n")
    p = evade.sgp4.propagate(decay, None, [3120.0])
    assert p.error[0, 0] == 6 and np.isfinite(p.r_m[0, 0]).all()


def test_bad_inputs_raise_input_error_with_the_cli_message(repo, cli_error):
    _, err = cli_error(["propagate", "--tle", str(repo / CATALOG), "--frame", "gcrf"])
    with pytest.raises(evade.InputError) as e:
        evade.sgp4.propagate(repo / CATALOG, None, [0.0], frame="gcrf")
    assert str(e.value) == cli_message(err)
    bad = repo / "test/sgp4/data/all_bad.tle"
    _, err = cli_error(["propagate", "--tle", str(bad)])
    with pytest.raises(evade.InputError) as e:
        evade.sgp4.propagate(bad, None, [0.0])
    assert str(e.value) == cli_message(err)
    with pytest.raises(evade.InputError, match="t_s\\[1\\]"):
        evade.sgp4.propagate(repo / CATALOG, None, [0.0, float("nan")])
    with pytest.raises(evade.InputError, match="yesterday"):
        evade.sgp4.propagate(repo / CATALOG, "yesterday", [0.0])
    with pytest.raises(evade.InputError, match="1-D"):
        evade.sgp4.propagate(repo / CATALOG, None, [[0.0, 1.0]])
    with pytest.raises(evade.InputError, match="cannot open"):
        evade.sgp4.propagate(repo / "no-such.tle", None, [0.0])


def test_long_calls_release_the_gil(repo):
    # While propagate runs in a thread, this thread keeps running Python: the largest gap
    # between its loop iterations stays far below the call's duration (holding the GIL would
    # stall it for the whole call). Compared with the call's own duration, not a fixed time.
    import threading
    import time
    cat = evade.sgp4.read_catalog(repo / CATALOG)
    t_s = np.arange(0.0, 2 * 86400.0, 60.0)
    done = threading.Event()
    span = {}

    def work():
        t0 = time.perf_counter()
        evade.sgp4.propagate(cat, None, t_s, threads=1)
        span["s"] = time.perf_counter() - t0
        done.set()

    th = threading.Thread(target=work)
    last, gap = time.perf_counter(), 0.0
    th.start()
    while not done.is_set():
        now = time.perf_counter()
        gap, last = max(gap, now - last), now
    th.join()
    assert span["s"] > 0.2, "the call must be long enough to tell"
    assert gap < 0.5 * span["s"], f"largest gap {gap:.3f} s during a {span['s']:.3f} s call"
