#!/usr/bin/env python3
"""A node on another architecture in the loop (issue 42 item 5; docs/INTEGRATION.md
"Cross-building for your flight computer"): the cross-built evade_guidance_node runs under
qemu-user against the host's `evade sim --lcm` over UDP multicast inside a private network
namespace (unshare -rn: loopback only, ttl=0), in lockstep, with authentication on (command,
sensor and telemetry keys, signed sensors required, a fresh state file). The same case is run
with the host's own node. In lockstep the commands depend only on the messages, so the target's
miss, Δv and closest approach must be the host node's as the guidance law computes them there
(same_guidance_test.cpp): bit for bit on aarch64 (Eigen in pairs, as on x86-64); with
--bounded (armhf and s390x, where Eigen computes lane after lane) within that test's bound,
the miss within P = 2 mm (two truths of one day at the tight tolerance), the closest approach
within P / v and the Δv within a P / v (v: seed0's closing speed, a = 1 m/s^2); cycles and
commands received exact. Both runs must account for every input and refuse none for
authentication.

  cross_hil_test.py --evade EVADE --native-node NODE --target T [--bounded] -- EMULATOR... NODE

Case: paper 000 Table 2, detection 10 s, 1 m/s^2 (paper 50.0021 m), 50 Hz. Exit 0 on a pass,
1 on a failure, 77 if user namespaces are not permitted here (nothing run).
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

URL = "udpm://239.255.76.67:7667?ttl=0"
SEED0 = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenarios", "seed0.yaml")
P_M = 2e-3  # same_guidance_test.cpp: 2 x the tight integrator's 1 mm per day
ACCEL_MPS2 = 1.0
PAPER_MISS_M = 50.0021  # Yao & Wang 2012, Table 2: 10 s, 1 m/s^2
SIM_ARGS = ["--scenario", "seed0", "--accel", "1", "--detect", "10",
            "--sensor-rate-hz", "50", "--guidance-rate-hz", "50"]


def keygen(evade, keys):
    for name, kid, role in (("ground", 1, None), ("sensor", 2, "sensor"),
                            ("telemetry", 3, "telemetry")):
        cmd = [evade, "keygen", "--out", os.path.join(keys, name + ".key"), "--key-id", str(kid)]
        if role:
            cmd += ["--role", role]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, timeout=60)


BANNER = "evade_guidance_node: lockstep"  # printed once every input is subscribed


def wait_until_subscribed(node, err_path, tag, limit_s=300.0):
    """Until the node's banner is on its stderr: LCM's udpm receiver drops a datagram whose
    channel has no subscription yet, so a simulator that starts while the node is still
    subscribing can lose the first cycle's nav or angles while its tick gets through, and the
    node answers that tick without them (docs/GUIDANCE_NODE.md "Known pitfalls"). Bounded:
    limit_s (qemu starts the node in seconds), or the node's exit."""
    t0 = time.monotonic()
    while time.monotonic() - t0 < limit_s:
        with open(err_path) as f:
            if BANNER in f.read():
                return
        if node.poll() is not None:
            raise RuntimeError(f"{tag}: the node exited {node.returncode} before subscribing: "
                               + open(err_path).read().strip())
        time.sleep(0.02)
    raise RuntimeError(f"{tag}: no '{BANNER}' banner from the node within {limit_s} s")


def run_pair(evade, node_cmd, keys, tag):
    """One lockstep run inside the namespace; returns (sim JSON, node stats JSON, node stderr)."""
    node = node_cmd + [
        "--lcm-url", URL, "--scenario", "seed0", "--max-accel-mps2", "1",
        "--guidance-rate-hz", "50", "--stats-json", "--lockstep", "--idle-exit-s", "60",
        "--keys", os.path.join(keys, "ground.key"),
        "--keys", os.path.join(keys, "sensor.key"), "--keys", os.path.join(keys, "telemetry.key"),
        "--auth-sensors", "required", "--auth-state", os.path.join(keys, tag + ".state"),
        "--auth-init", "1"]
    sim = [evade, "sim"] + SIM_ARGS + ["--key", os.path.join(keys, "sensor.key"),
                                       "--lcm", URL, "--lcm-timeout-s", "120", "--json"]
    err_path = os.path.join(keys, tag + ".err")
    with open(err_path, "w") as err:
        n = subprocess.Popen(node, stdout=subprocess.PIPE, stderr=err, text=True)
        try:
            wait_until_subscribed(n, err_path, tag)
            s = subprocess.run(sim, capture_output=True, text=True, timeout=600)
        finally:
            n.terminate()
            try:
                node_out, _ = n.communicate(timeout=120)
            except subprocess.TimeoutExpired:
                n.kill()
                node_out, _ = n.communicate()
    node_err = open(err_path).read()
    if s.returncode != 0:
        raise RuntimeError(f"{tag}: evade sim exited {s.returncode}: {s.stderr.strip()}\n"
                           f"node stderr: {node_err.strip()}")
    if n.returncode != 0:
        raise RuntimeError(f"{tag}: node exited {n.returncode}: {node_err.strip()}")
    return json.loads(s.stdout), json.loads(node_out), node_err


def seed0_closing_mps():
    """|v_debris - v_satellite| of scenarios/seed0.yaml (its two v_eci_mps lines, in order)."""
    rows = re.findall(r"^\s*v_eci_mps:\s*\[([^\]]*)\]", open(SEED0).read(), re.M)
    va, vb = ([float(x) for x in r.split(",")] for r in rows[:2])
    return math.dist(va, vb)


def compare(native, target, tag, bounded):
    """The problems of the target's results against the host node's (module docstring)."""
    problems = []
    v = seed0_closing_mps()
    bound = {"miss_m": P_M, "tca_s": P_M / v, "dv_mps": ACCEL_MPS2 * P_M / v}
    for k in ("miss_m", "dv_mps", "tca_s", "cycles", "commands_received"):
        a, b = native.get(k), target.get(k)
        if a == b:
            continue
        if bounded and k in bound and abs(a - b) <= bound[k]:
            print(f"{k}: {tag} {b!r} host {a!r}, difference {b - a:.3g} within {bound[k]:.3g}")
            continue
        problems.append(f"{k}: {tag} node {b!r}, host node {a!r}: "
                        + (f"beyond the bound {bound.get(k, 0)}" if bounded else "not bit for bit"))
    return problems


def check_node(tag, stats):
    """Every input accounted for, none refused for authentication; returns the problems."""
    i = stats["inputs"]
    parts = ("consumed", "rejected", "stale", "superseded", "dropped", "auth_failed", "replayed")
    problems = []
    if i["received"] != sum(i[k] for k in parts):
        problems.append(f"{tag}: inputs received {i['received']} != the sum of {parts}: {i}")
    if i["auth_failed"] != 0:
        problems.append(f"{tag}: {i['auth_failed']} inputs failed authentication")
    if i["consumed"] == 0:
        problems.append(f"{tag}: the node consumed no input")
    for row in ("nav", "clock"):  # the simulator sends both every cycle
        if i["received_by_input"][row] < stats["cycles"]:
            problems.append(f"{tag}: {stats['cycles']} cycles on {i['received_by_input'][row]} "
                            f"{row} messages: one never reached the node")
    return problems


ELF_MACHINES = {62: "x86-64", 183: "aarch64", 40: "arm", 22: "s390x"}


def elf_machine(path):
    """The ELF header's e_machine of the binary, read in the file's own byte order."""
    with open(path, "rb") as f:
        head = f.read(20)
    if head[:4] != b"\x7fELF":
        raise RuntimeError(f"{path}: not an ELF file")
    return int.from_bytes(head[18:20], "little" if head[5] == 1 else "big")


def inside(args):
    with tempfile.TemporaryDirectory(prefix="evade-cross-hil-") as keys:
        os.chmod(keys, 0o700)
        keygen(args.evade, keys)
        native, native_node, _ = run_pair(args.evade, [args.native_node], keys, "native")
        target, target_node, _ = run_pair(args.evade, args.node_cmd, keys, args.target)
    problems = check_node("native", native_node) + check_node(args.target, target_node)
    machine = elf_machine(args.node_cmd[-1])
    print(f"{args.target} node: {' '.join(args.node_cmd)} "
          f"(ELF machine {machine}: {ELF_MACHINES.get(machine, 'unknown')})")
    if machine == 62:
        problems.append(f"{args.node_cmd[-1]} is an x86-64 binary, not the target's")
    if not native.get("sensors_signed") or not target.get("sensors_signed"):
        problems.append("the simulator did not sign its sensor messages")
    print(f"{'node':>10} {'miss_m':>20} {'dv_mps':>20} {'cycles':>7}  paper {PAPER_MISS_M} m")
    for tag, r in (("x86-64", native), (args.target, target)):
        print(f"{tag:>10} {r['miss_m']:20.15f} {r['dv_mps']:20.15f} {r['cycles']:7d}")
    problems += compare(native, target, args.target, args.bounded)
    if abs(target["miss_m"] - PAPER_MISS_M) > 0.02:  # paper000_table2_test's 50 Hz bound
        problems.append(f"miss {target['miss_m']} m is not within 2 cm of the paper's")
    for p in problems:
        print("FAIL:", p)
    for tag, stats in (("x86-64", native_node), (args.target, target_node)):
        i = stats["inputs"]
        print(f"{tag} node: {stats['cycles']} cycles, inputs {i['received']} = consumed "
              f"{i['consumed']} + stale {i['stale']} + dropped {i['dropped']} + replayed "
              f"{i['replayed']} + others; by input {i['received_by_input']}; auth_failed "
              f"{i['auth_failed']}")
    return 1 if problems else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--evade", required=True)
    ap.add_argument("--native-node", required=True)
    ap.add_argument("--target", required=True)
    ap.add_argument("--bounded", action="store_true",
                    help="within same_guidance_test.cpp's bound, not bit for bit")
    ap.add_argument("--inside", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("node_cmd", nargs="+", help="emulator and its arguments, then the node")
    args = ap.parse_args()
    if args.inside:
        return inside(args)
    if subprocess.run(["unshare", "-rn", "true"], capture_output=True).returncode != 0:
        print("cross_hil_test: unshare -rn is not permitted here (user namespaces disabled); "
              "nothing was run", file=sys.stderr)
        return 77
    net = ("ip link set lo up && ip link set lo multicast on && "
           "ip route add 224.0.0.0/4 dev lo && exec \"$@\"")
    cmd = ["unshare", "-rn", "sh", "-c", net, "sh", sys.executable, os.path.abspath(__file__),
           "--inside", "--evade", args.evade, "--native-node", args.native_node,
           "--target", args.target] + (["--bounded"] if args.bounded else []) + ["--"] + args.node_cmd
    return subprocess.run(cmd, timeout=1500).returncode


if __name__ == "__main__":
    sys.exit(main())
