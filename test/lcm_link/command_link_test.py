#!/usr/bin/env python3
"""The command link as the ground sees it (docs/SECURITY.md UPLINK-*, TM-*, ARSN-*; issue 40
rows 1-5, 9 and 13): the real `evade` ground commands against a real `evade_guidance_node` over
UDP multicast inside a private network namespace (unshare -rn: loopback only, ttl=0; nothing
leaves this machine), with keys generated into a private directory.

  command_link_test.py EVADE NODE ATTACKER CASE

CASE (one ctest each):
  auto_plan_id       a fresh node: `evade plan --publish --key` with no --seq takes plan id 1
                     from the node's signed status and exits 0; again: plan 2, exit 0
  refused_plans      row 1: a disarmed node answers `disarmed` (exit 3); a node that does not
                     hold the ground's key answers nothing (exit 4); row 2: another plan with
                     the id in force is refused `not_newer` (exit 3)
  standby_arm        row 3: `evade arm --arm` signed with a standby key: exit 3 `standby_key`
  forged_telemetry   row 4: with no node, a forger answering every command (acks naming it,
                     unsigned and under its own key) and claiming every plan accepted in its
                     status: the ground exits 4 and counts what it ignored; with the node
                     running under the same forger: exit 0, the node's own answer
  skewed_clock       rows 9 and 13: a ground whose clock is 1 h ahead (faketime): its plan is
                     refused `from_future` (exit 3, the skew named), its disarm is accepted; the
                     ground with the right clock is not locked out; a clock 0.7 s behind arms
  lost_counter       row 9: the ground's ARSN counter file deleted: the next command recovers
                     from the node's answer (exit 0, one recovery) without a node restart
  conjunction        issue 43 AUT-1: `evade conjunction --publish` of a CDM whose TCA is a day
                     ahead: tracked (exit 0), the same again `already in force` (exit 0), a
                     higher --event-version replaces it, the lower one is refused `not_newer`
                     (exit 3); a TCA in the past or --pc-target above --pc-red: exit 2 before
                     anything is sent
  cam_decide         AUT-7: `evade cam decide` on an event without a proposal (the node has no
                     navigation): `no_proposal` from the node's signed proposal (exit 3, nothing
                     sent), a named proposal refused `not_pending` (exit 3); --autonomy off
                     accepted; the node's stats count each; `evade cam review --event` reads
                     the node's signed proposal from the bus (no burn in it: exit 2) and
                     ignores it under another telemetry key (exit 4)
  node_start         row 5: the node refuses to start (exit 2, one line naming the file) from a
                     deleted, cut or edited state file or one with mode 0666; --auth-init
                     refuses to overwrite one
Exit 0 pass, 1 fail (every failed check printed), 77 skipped (no user namespaces; skewed_clock
without faketime).
"""
import datetime
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

URL = "udpm://239.255.76.67:7667?ttl=0"
CATALOG = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenarios",
                       "catalogs", "synthetic-1200.tle")
NETNS = "ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo"


class Checks:
    def __init__(self):
        self.failed = []

    def check(self, name, ok, value=None):
        print(("ok   " if ok else "FAIL ") + name + ("" if ok else f": {value!r}"))
        if not ok:
            self.failed.append(name)


class Bench:
    """Keys, the node and the ground commands in a scratch directory."""

    def __init__(self, evade, node, attacker, d):
        self.evade, self.node_bin, self.attacker, self.d = evade, node, attacker, d
        self.node = None
        for name, kid, role in (("ground", 1, "command"), ("telemetry", 3, "telemetry"),
                                ("telemetry2", 6, "telemetry"),
                                ("standby", 4, "command"), ("other", 5, "command")):
            subprocess.run([evade, "keygen", "--out", self.path(name + ".key"), "--key-id",
                            str(kid), "--role", role], check=True, stdout=subprocess.DEVNULL)

    def path(self, name):
        return os.path.join(self.d, name)

    def start_node(self, keys=("ground", "standby"), state="node.state", extra=()):
        args = [self.node_bin, "--lcm-url", URL, "--auth-state", self.path(state),
                "--stats-json", "--max-cycles", "3000"]
        for k in keys + ("telemetry",):
            args += ["--keys", self.path(k + ".key")]
        if not os.path.exists(self.path(state)):
            args += ["--auth-init", "1" if "ground" in keys else "5"]
        self.node_err = self.path(state + ".err")
        self.node = subprocess.Popen(list(args) + list(extra), stdout=subprocess.PIPE,
                                     stderr=open(self.node_err, "w"), text=True)
        for _ in range(100):  # its banner: it has subscribed
            time.sleep(0.05)
            if "fixed rate" in open(self.node_err).read():
                break
        time.sleep(0.2)

    def stop_node(self):
        self.node.send_signal(signal.SIGTERM)
        out, _ = self.node.communicate(timeout=20)
        self.node = None
        return json.loads(out) if out.strip() else {}

    def ground(self, *args, key="ground", prefix=(), timeout_s="2"):
        cmd = list(prefix) + [self.evade] + list(args) + [
            "--key", self.path(key + ".key"), "--telemetry-key", self.path("telemetry.key"),
            "--lcm-url", URL, "--ack-timeout-s", timeout_s, "--json"]
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
        try:
            j = json.loads(p.stdout)
        except ValueError:
            j = {}
        return p.returncode, j.get("uplink", j), p.stderr

    def plan(self, *extra, key="ground", prefix=()):
        return self.ground("plan", "formation", "--scenario", "seed3", "--publish", *extra,
                           key=key, prefix=prefix)


def case_auto_plan_id(b, c):
    b.start_node()
    rc, u, _ = b.plan()
    c.check("first plan, no --seq: exit 0", rc == 0, (rc, u))
    rc2, u2, _ = b.plan()
    c.check("second plan, no --seq: exit 0", rc2 == 0, (rc2, u2))
    s = b.stop_node()
    c.check("the node accepted plans 1 and 2", s.get("plan", {}).get("accepted") == 2
            and s.get("plan", {}).get("ack_id") == 2, s.get("plan"))
    c.check("identity", s.get("inputs", {}).get("identity") is True, s.get("inputs"))


def case_refused_plans(b, c):
    b.start_node(extra=["--start-disarmed"])
    rc, u, _ = b.plan("--seq", "7")
    c.check("disarmed node: exit 3 disarmed", rc == 3 and u.get("reason") == "disarmed", (rc, u))
    b.stop_node()
    b.start_node(keys=("other",), state="other.state")
    rc, u, _ = b.plan("--seq", "7")
    c.check("node without the ground's key: exit 4, nothing verified answers",
            rc == 4 and u.get("telemetry", {}).get("acks_verified") == 0, (rc, u))
    b.stop_node()
    b.start_node()
    rc, u, _ = b.plan("--seq", "5")
    c.check("plan 5 accepted", rc == 0, (rc, u))
    rc, u, _ = b.plan("--seq", "5", "--epoch-utime", str(int(time.time() * 1e6) + 60_000_000))
    c.check("another plan 5: exit 3 not_newer", rc == 3 and u.get("reason") == "not_newer", (rc, u))
    b.stop_node()


def case_standby_arm(b, c):
    b.start_node()
    rc, u, _ = b.ground("arm", "--arm", key="standby")
    c.check("arm under a standby key: exit 3 standby_key",
            rc == 3 and u.get("reason") == "standby_key", (rc, u))
    rc, u, _ = b.ground("arm", "--arm")
    c.check("arm under the active key: exit 0", rc == 0, (rc, u))
    b.stop_node()


def case_forged_telemetry(b, c):
    forger = subprocess.Popen([b.attacker, "forge-telemetry", URL, "30"], stdout=subprocess.PIPE,
                              text=True)
    time.sleep(0.3)
    rc, u, _ = b.plan("--seq", "3")
    c.check("no node, forged answers: exit 4", rc == 4, (rc, u))
    c.check("forgeries ignored and counted", u.get("telemetry", {}).get("ignored", 0) > 0, u)
    rc, u, _ = b.ground("arm", "--arm")
    c.check("no node, forged answers to an arm: exit 4", rc == 4, (rc, u))
    b.start_node()
    rc, u, _ = b.plan("--seq", "3")
    c.check("node running, forged refusals: exit 0 on the node's answer", rc == 0, (rc, u))
    c.check("its counter not pushed by the forged status", u.get("arsn", 0) < 1000, u)
    b.stop_node()
    forger.send_signal(signal.SIGTERM)
    forger.wait(timeout=10)


def case_skewed_clock(b, c):
    if os.environ.get("EVADE_NO_FAKETIME"):  # set by ctest for the sanitizer build
        print("skewed_clock: skipped: " + os.environ["EVADE_NO_FAKETIME"])
        sys.exit(77)
    ft = shutil.which("faketime")
    if ft is None:
        print("skewed_clock: faketime not installed (scripts/setup installs it): skipped")
        sys.exit(77)
    os.environ["FAKETIME_DONT_FAKE_MONOTONIC"] = "1"
    b.start_node()
    ahead = (ft, "-f", "+1h")
    rc, u, _ = b.plan("--seq", "1", prefix=ahead)
    c.check("clock 1 h ahead: plan exit 3 from_future",
            rc == 3 and u.get("reason") == "from_future", (rc, u))
    c.check("the skew is named", "ahead" in u.get("note", ""), u)
    rc, u, _ = b.ground("arm", "--disarm", prefix=ahead)
    c.check("clock 1 h ahead: disarm exit 0", rc == 0, (rc, u))
    rc, u, _ = b.ground("arm", "--arm", prefix=(ft, "-f", "-0.7"))
    c.check("clock 0.7 s behind: arm exit 0", rc == 0, (rc, u))
    rc, u, _ = b.plan("--seq", "1")
    c.check("right clock: plan exit 0, no lock-out", rc == 0, (rc, u))
    s = b.stop_node()
    c.check("identity", s.get("inputs", {}).get("identity") is True, s.get("inputs"))


def case_lost_counter(b, c):
    b.start_node()
    for _ in range(3):
        rc, u, _ = b.ground("arm", "--arm")
    c.check("three arms accepted", rc == 0, (rc, u))
    os.remove(b.path("ground.key.arsn"))
    rc, u, err = b.plan("--seq", "1")
    c.check("counter lost: plan exit 0", rc == 0, (rc, u))
    c.check("recovered once from the node's answer", u.get("arsn_recoveries") == 1, u)
    c.check("the ground said the counter was missing", "ARSN counter" in err, err)
    b.stop_node()


def write_cdm(b, name, tca_from_now_s):
    """The shipped CAM example CDM with its TCA tca_from_now_s from now and created now."""
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenarios",
                       "cdm", "cam-example.cdm")
    now = datetime.datetime.now(datetime.timezone.utc)
    fmt = "%Y-%m-%dT%H:%M:%S.000"
    text = open(src).read()
    text = re.sub(r"^TCA\s*=.*$", "TCA = " + (now + datetime.timedelta(seconds=tca_from_now_s))
                  .strftime(fmt), text, flags=re.M)
    text = re.sub(r"^CREATION_DATE\s*=.*$", "CREATION_DATE = " + now.strftime(fmt), text,
                  flags=re.M)
    with open(b.path(name), "w") as f:
        f.write(text)
    return b.path(name)


def conjunction(b, cdm, *extra):
    rc, j, err = b.ground("conjunction", "--cdm", cdm, "--hbr-m", "20", "--publish", *extra)
    return rc, j, err


def case_conjunction(b, c):
    cdm = write_cdm(b, "day.cdm", 86400)
    b.start_node()
    p = subprocess.run([b.evade, "conjunction", "--cdm", cdm, "--hbr-m", "20", "--json"],
                       capture_output=True, text=True, timeout=60)
    event = json.loads(p.stdout)["event"]
    c.check("without --publish: the event printed, exit 0", p.returncode == 0 and
            event["event_id"] > 0 and event["version"] > 0, (p.returncode, p.stderr))
    rc, u, _ = conjunction(b, cdm)
    c.check("tracked: exit 0 accepted", rc == 0 and u.get("reason") == "accepted"
            and u.get("detail") == 0, (rc, u))
    rc, u, _ = conjunction(b, cdm)
    c.check("the same event again: exit 0 already in force (CONJ_ALREADY_TRACKED)",
            rc == 0 and u.get("reason") == "already in force" and u.get("detail") == 10, (rc, u))
    v = event["version"]
    rc, u, _ = conjunction(b, cdm, "--event-version", str(v + 1))
    c.check("a higher version: exit 0, replaced", rc == 0 and u.get("detail") == 1, (rc, u))
    rc, u, _ = conjunction(b, cdm)
    c.check("the lower version: exit 3 not_newer", rc == 3 and u.get("reason") == "not_newer",
            (rc, u))
    rc, u, err = conjunction(b, write_cdm(b, "past.cdm", -60))
    c.check("TCA in the past: exit 2 naming it, nothing sent",
            rc == 2 and "tca_not_ahead" in err and u == {}, (rc, err))
    rc, u, err = conjunction(b, cdm, "--pc-target", "1e-3")
    c.check("--pc-target above --pc-red: exit 2 naming both",
            rc == 2 and "--pc-target" in err and "--pc-red" in err, (rc, err))
    s = b.stop_node()
    a = s.get("autonomy", {})
    c.check("the node tracked 1, replaced 1, again 1, refused 1",
            (a.get("events_tracked"), a.get("events_replaced"), a.get("events_again"),
             a.get("events_refused")) == (1, 1, 1, 1), a)
    c.check("identity", s.get("inputs", {}).get("identity") is True, s.get("inputs"))


def case_cam_decide(b, c):
    cdm = write_cdm(b, "day.cdm", 86400)
    b.start_node()
    rc, u, _ = conjunction(b, cdm)
    p = subprocess.run([b.evade, "conjunction", "--cdm", cdm, "--hbr-m", "20", "--json"],
                       capture_output=True, text=True, timeout=60)
    event = str(json.loads(p.stdout)["event"]["event_id"])
    c.check("tracked", rc == 0, (rc, u))
    rc, u, _ = b.ground("cam", "decide", "--event", event, "--veto", timeout_s="4")
    c.check("no navigation, no proposal: exit 3 no_proposal, nothing sent",
            rc == 3 and u.get("reason") == "no_proposal" and u.get("transmissions") == 0
            and "no_nav" in u.get("note", ""), (rc, u))
    rc, u, _ = b.ground("cam", "decide", "--event", event, "--veto", "--proposal", "5")
    c.check("a named proposal: exit 3 not_pending", rc == 3 and u.get("reason") == "not_pending",
            (rc, u))
    rc, u, _ = b.ground("cam", "decide", "--event", "999", "--veto", "--proposal", "5")
    c.check("an unknown event: exit 3 unknown_event",
            rc == 3 and u.get("reason") == "unknown_event", (rc, u))
    rc, u, _ = b.ground("cam", "decide", "--autonomy", "off")
    c.check("--autonomy off: exit 0", rc == 0 and u.get("reason") == "accepted", (rc, u))
    rc, u, err = b.ground("cam", "decide", "--veto")
    c.check("--veto without --event: exit 2", rc == 2 and "--event" in err, (rc, err))
    review = [b.evade, "cam", "review", "--cdm", cdm, "--hbr-m", "20", "--tle", CATALOG,
              "--event", event, "--lcm-url", URL, "--wait-s", "3", "--telemetry-key"]
    p = subprocess.run(review + [b.path("telemetry.key")], capture_output=True, text=True, timeout=60)
    c.check("cam review from the bus: the node's signed proposal read, no burn in it: exit 2",
            p.returncode == 2 and "no burn" in p.stderr, (p.returncode, p.stderr))
    p = subprocess.run(review + [b.path("telemetry2.key")], capture_output=True, text=True, timeout=60)
    c.check("cam review under another telemetry key: nothing verified, exit 4",
            p.returncode == 4 and "ignored" in p.stderr, (p.returncode, p.stderr))
    s = b.stop_node()
    a = s.get("autonomy", {})
    c.check("the node's policy is off, 1 decision applied and 2 refused",
            (a.get("policy"), a.get("decisions_applied"), a.get("decisions_refused")) ==
            ("off", 1, 2), a)
    c.check("identity", s.get("inputs", {}).get("identity") is True, s.get("inputs"))


def case_node_start(b, c):
    state = b.path("start.state")
    base = [b.node_bin, "--lcm-url", "memq://", "--max-cycles", "1", "--auth-state", state,
            "--keys", b.path("ground.key"), "--keys", b.path("telemetry.key")]

    def start(*extra):
        p = subprocess.run(base + list(extra), capture_output=True, text=True, timeout=30)
        lines = [l for l in p.stderr.splitlines() if "invalid input" in l]
        return p.returncode, lines

    rc, lines = start()
    c.check("missing state: exit 2, one line naming it",
            rc == 2 and len(lines) == 1 and state in lines[0], (rc, lines))
    rc, _ = start("--auth-init", "1")
    c.check("--auth-init: starts and writes the state", rc == 0 and os.path.exists(state), rc)
    rc, lines = start("--auth-init", "1")
    c.check("--auth-init again: exit 2", rc == 2 and len(lines) == 1, (rc, lines))
    good = open(state).read()
    for name, text in (("cut to its header", good.splitlines()[0] + "\n"),
                       ("a key's line removed",
                        "".join(l + "\n" for l in good.splitlines() if not l.startswith("key 1 "))),
                       ("an ARSN edited", good.replace(" 0 ", " 1 ", 1))):
        with open(state, "w") as f:
            f.write(text)
        rc, lines = start()
        c.check(f"{name}: exit 2, one line", rc == 2 and len(lines) == 1, (rc, lines))
    with open(state, "w") as f:
        f.write(good)
    os.chmod(state, 0o666)
    rc, lines = start()
    c.check("mode 0666: exit 2, one line", rc == 2 and len(lines) == 1 and "chmod" in lines[0],
            (rc, lines))
    os.chmod(state, 0o600)
    rc, _ = start()
    c.check("the good file again: starts", rc == 0, rc)


CASES = {"auto_plan_id": case_auto_plan_id, "refused_plans": case_refused_plans,
         "standby_arm": case_standby_arm, "forged_telemetry": case_forged_telemetry,
         "skewed_clock": case_skewed_clock, "lost_counter": case_lost_counter,
         "conjunction": case_conjunction, "cam_decide": case_cam_decide,
         "node_start": case_node_start}


def main():
    evade, node, attacker, case = sys.argv[1:5]
    if case not in CASES:
        print(f"unknown case {case!r}: {sorted(CASES)}")
        return 2
    if os.environ.get("EVADE_IN_NETNS") != "1" and case != "node_start":
        if subprocess.run(["unshare", "-rn", "sh", "-c", NETNS], capture_output=True).returncode:
            print("unshare -rn is not permitted here: skipped")
            return 77
        env = dict(os.environ, EVADE_IN_NETNS="1")
        inner = f"{NETNS} && exec {sys.executable} " + " ".join(
            f"'{a}'" for a in [os.path.abspath(__file__)] + sys.argv[1:])
        return subprocess.run(["unshare", "-rn", "sh", "-c", inner], env=env).returncode
    c = Checks()
    d = tempfile.mkdtemp(prefix="evade-link-")
    os.chmod(d, 0o700)
    b = Bench(evade, node, attacker, d)
    try:
        CASES[case](b, c)
    finally:
        if b.node is not None:
            b.node.kill()
        shutil.rmtree(d, ignore_errors=True)
    print(f"{case}: {'FAILED ' + ', '.join(c.failed) if c.failed else 'passed'}")
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main())
