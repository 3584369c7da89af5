"""One case of the HIL fault bench for the ctest scripts hil_*_test.py.

run(src, build, case) runs scripts/hil_faults --no-build --relay --case CASE with the
binaries of BUILD and returns (status, result, returncode): status 77 when unshare -rn is not
permitted (the caller skips), 1 when the script gave no result, else None with the case's
JSON object and the script's exit code (nonzero when one of its own checks failed).
"""
import json
import os
import subprocess
import tempfile


def run(src, build, case):
    with tempfile.TemporaryDirectory(prefix=f"evade_{case}_") as out:
        env = dict(os.environ, EVADE_BUILD_DIR=build)
        p = subprocess.run([os.path.join(src, "scripts", "hil_faults"), "--no-build", "--relay",
                            "--case", case, "--out", out], env=env,
                           stdout=subprocess.PIPE, timeout=100)
        if p.returncode == 77:
            print("SKIP: unshare -rn is not permitted here (no user namespaces)")
            return 77, None, p.returncode
        if not p.stdout:
            print(f"FAIL: scripts/hil_faults exited {p.returncode} without a result")
            return 1, None, p.returncode
        return None, json.loads(p.stdout)["cases"][case], p.returncode
