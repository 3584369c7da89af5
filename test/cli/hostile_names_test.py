#!/usr/bin/env python3
"""Issue 46: catalog names that are not plain ASCII never make a command write invalid JSON.

Names in Latin-1 (0xC9), with quotes, backslashes and non-ASCII UTF-8, as 3LE title lines, and a
CDM whose MESSAGE_ID is Latin-1: every --json output of `evade propagate --tle`, `evade screen
--tle` and `evade assess --cdm` must decode as strict UTF-8 and parse with a strict JSON parser,
and the names must come back as the readers decoded them (Latin-1 read as Latin-1), the issue a
stray Latin-1 line raises included. A title
with a control character is refused with its line and column, the element set read without it.

  hostile_names_test.py EVADE SOURCE_DIR
"""
import json
import pathlib
import subprocess
import sys
import tempfile

ISS1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927"
ISS2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537"
# A second object (catalog number 25545, its checksum recomputed) for the screen.
ISS1B = "1 25545U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  292"
ISS2B = "2 25545  51.6416 247.4627 0006703 130.5360 325.0288 15.7212539156353"

NAMES = [(b"ISS \xc9TOILE \"q\" \\ b", "ISS \u00c9TOILE \"q\" \\ b"),   # Latin-1
         ("DEBRIS \u6e2c\u8a66 \u2014 </x>".encode("utf-8"), "DEBRIS \u6e2c\u8a66 \u2014 </x>")]


def checksum(line):
    return str(sum(int(c) if c.isdigit() else (1 if c == "-" else 0) for c in line[:68]) % 10)


def run(evade, args):
    p = subprocess.run([evade, *args], capture_output=True, timeout=120, check=False)
    return p.returncode, p.stdout, p.stderr.decode("utf-8", "replace")


def strict_json(raw, what):
    text = raw.decode("utf-8")  # strict: raises on any invalid byte
    return json.loads(text, strict=True, parse_constant=lambda c: (_ for _ in ()).throw(
        ValueError(f"{what}: non-JSON constant {c}")))


def names_in(doc):
    out = []
    def walk(x):
        if isinstance(x, dict):
            for k, v in x.items():
                if k in ("name", "name_1", "name_2", "object_name") and isinstance(v, str):
                    out.append(v)
                walk(v)
        elif isinstance(x, list):
            for v in x:
                walk(v)
    walk(doc)
    return out


def assess_latin1_cdm(evade, source_dir, d, failures):
    cdm = (pathlib.Path(source_dir) / "scenarios/cdm/cam-example.cdm").read_bytes()
    lines = [b"MESSAGE_ID = CAM \xc9" if l.startswith(b"MESSAGE_ID") else l
             for l in cdm.split(b"\n")]
    path = pathlib.Path(d) / "latin1.cdm"
    path.write_bytes(b"\n".join(lines))
    rc, out, err = run(evade, ["assess", "--cdm", str(path), "--hbr-m", "10", "--json"])
    if rc != 0:
        failures.append(f"assess --cdm --json: exit {rc}: {err.strip()}")
        return
    try:
        doc = strict_json(out, "assess")
    except (UnicodeDecodeError, ValueError) as e:
        failures.append(f"assess --cdm --json: invalid JSON: {e}")
        return
    got = doc.get("cdm", {}).get("message_id")
    if got != "CAM \u00c9":
        failures.append(f"assess --cdm --json: message_id {got!r}, expected 'CAM \u00c9'")
    print(f"assess --cdm --json: strict UTF-8 JSON, message_id {got!r}")


def main():
    evade, source_dir = sys.argv[1], sys.argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as d:
        tle = pathlib.Path(d) / "hostile.tle"
        b1 = ISS1B + checksum(ISS1B)
        b2 = ISS2B + checksum(ISS2B)
        tle.write_bytes(NAMES[0][0] + b"\n" + f"{ISS1}\n{ISS2}\n".encode() +
                        NAMES[1][0] + b"\n" + f"{b1}\n{b2}\n".encode() +
                        b"2 \xc9 a stray line 2 in Latin-1, reported as an issue\n")
        cases = {
            "propagate --json": ["propagate", "--tle", str(tle), "--span-s", "120", "--step-s", "60",
                                 "--json"],
            "screen --json": ["screen", "--tle", str(tle), "--span-s", "600", "--json", "--quiet"],
        }
        for what, args in cases.items():
            rc, out, err = run(evade, args)
            if rc != 0:
                failures.append(f"{what}: exit {rc}: {err.strip()}")
                continue
            try:
                doc = strict_json(out, what)
            except (UnicodeDecodeError, ValueError) as e:
                failures.append(f"{what}: invalid JSON: {e}")
                continue
            got = names_in(doc)
            for _, want in NAMES:
                if what.startswith("propagate") and want not in got:
                    failures.append(f"{what}: name {want!r} not in {got}")
            print(f"{what}: strict UTF-8 JSON, names {got}")
        ctl = pathlib.Path(d) / "control.tle"
        ctl.write_bytes(b"ISS\x07\n" + f"{ISS1}\n{ISS2}\n".encode())
        rc, out, err = run(evade, ["propagate", "--tle", str(ctl), "--span-s", "60", "--step-s", "60",
                                   "--json"])
        want = "control.tle:1:4: expected a title of printable characters (UTF-8 or Latin-1), found 'U+0007'"
        if want not in err:
            failures.append(f"control character: stderr lacks {want!r}: {err!r}")
        else:
            doc = strict_json(out, "control")
            if doc.get("bad_entries") != 1 or len(doc.get("objects", [])) != 1:
                failures.append(f"control character: expected 1 bad entry and the set read: {doc}")
            print("control character: refused at 1:4, the element set read without the title")
        assess_latin1_cdm(evade, source_dir, d, failures)
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
