#!/usr/bin/env python3
"""scripts/check_costs fails where it must: growth above the limit fails naming the case, a
growth within it passes, a case without a record fails; and measured on this build, a record
20 % below the guidance step's real count fails naming guidance_step (a deliberately
"slowed" step, seen from the record's side).
  check_costs_test.py SOURCE_DIR BUILD_DIR"""
import json
import os
import subprocess
import sys
import tempfile

src, build = sys.argv[1], sys.argv[2]
script = os.path.join(src, "scripts", "check_costs")
failures = []


def run(args):
    r = subprocess.run([sys.executable, script] + args, capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def expect(cond, what, out):
    if not cond:
        failures.append("%s\n%s" % (what, out))


with tempfile.TemporaryDirectory() as tmp:
    def write(name, doc):
        path = os.path.join(tmp, name)
        with open(path, "w") as f:
            json.dump(doc, f)
        return path

    record = write("record.json", {"a": 1000, "b": 1000})
    code, out = run(["--compare", record, write("grown.json", {"a": 1111, "b": 1000})])
    expect(code == 1 and "a: 1111 instructions, recorded 1000 (+11.1 %): FAILED" in out,
           "11 % growth of case a must fail naming it", out)
    expect("b: 1000 instructions, recorded 1000 (+0.0 %): ok" in out, "case b is within", out)
    code, out = run(["--compare", record, write("within.json", {"a": 1099, "b": 950})])
    expect(code == 0, "9.9 % growth is within the 10 % limit", out)
    code, out = run(["--compare", record, write("new.json", {"c": 5})])
    expect(code == 1 and "c: no recorded count" in out, "a case with no record fails", out)

    real = os.path.join(tmp, "real.json")
    code, out = run([build, "--cases", "guidance_step", "--save", "--record", real])
    expect(code == 0, "recording the guidance step on this build", out)
    with open(real) as f:
        doc = json.load(f)
    doc["counts"]["guidance_step"] = int(doc["counts"]["guidance_step"] * 0.8)
    with open(real, "w") as f:
        json.dump(doc, f)
    code, out = run([build, "--cases", "guidance_step", "--record", real])
    expect(code == 1 and "guidance_step:" in out and "FAILED" in out,
           "a step 25 % above its record must fail naming guidance_step", out)
    doc["toolchain"]["compiler"] = "gcc 0.0"
    with open(real, "w") as f:
        json.dump(doc, f)
    code, out = run([build, "--cases", "guidance_step", "--record", real])
    expect(code == 2 and "not comparable" in out, "another toolchain is refused (exit 2)", out)
    code, out = run([build, "--cases", "guidance_step", "--record", real, "--other-toolchain-ok"])
    expect(code == 0 and "NOT COMPARED" in out, "--other-toolchain-ok says NOT COMPARED", out)
    code, out = run([build, "--cases", "nope"])
    expect(code == 2 and "--cases: unknown case nope" in out, "an unknown case is named", out)

if failures:
    print("\n\n".join(failures))
    sys.exit(1)
print("check_costs: every expected verdict")
