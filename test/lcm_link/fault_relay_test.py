#!/usr/bin/python3
"""ctest FaultRelay.*: scripts/fault_relay, the user-space netem of the HIL fault bench.

  fault_relay_test.py SOURCE_DIR models    FaultRelay.ModelsMatchNetemStatistics
      The per-datagram decisions (no sockets): over 40,000 seeded datagrams the loss,
      duplication and reorder fractions are within 5 binomial standard deviations of the
      configured probability (sd = sqrt(p (1 - p) / n): 0.0015 for p = 0.1), uniform delays stay
      in [D - J, D + J) with mean D within 5 sd of the mean (J / sqrt(3 n)), normal delays have
      mean D and sd J within 5 % (n = 40,000: the sample sd's own relative sd is 0.35 %);
      the same seed gives the same decisions and another seed different ones; bad arguments exit
      2 naming the flag.
  fault_relay_test.py SOURCE_DIR network   FaultRelay.ForwardsOnlyAcrossAndBlacksOut
      In a private network namespace (exit 77 if unshare -rn is not permitted): the relay
      forwards EVADE_NAV from group A to group B and EVADE_THRUST_CMD from B to A, never a
      command from A to B nor navigation from B to A (nothing loops), and drops everything in a
      0.5 s blackout starting 0.5 s after the first datagram from A (30 ms margins at the edges
      for scheduling on a loaded machine).
"""
import importlib.machinery
import importlib.util
import math
import os
import socket
import struct
import subprocess
import sys
import tempfile
import time
import types

N = 40000


def load_relay(src):
    path = os.path.join(src, "scripts", "fault_relay")
    loader = importlib.machinery.SourceFileLoader("fault_relay", path)
    spec = importlib.util.spec_from_loader("fault_relay", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def args(**kw):
    a = dict(seed=7, loss=0.0, delay_ms=0.0, jitter_ms=0.0, distribution="uniform", reorder=0.0,
             duplicate=0.0, blackout_at_s=0.0, blackout_s=0.0)
    a.update(kw)
    return types.SimpleNamespace(**a)


def within(name, x, expect, tol, fails):
    ok = abs(x - expect) <= tol
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {x:.5f} (expected {expect:.5f} +- {tol:.5f})")
    if not ok:
        fails.append(name)


def binomial_tol(p, n):
    return 5.0 * math.sqrt(p * (1.0 - p) / n)


def test_models(src):
    r = load_relay(src)
    fails = []
    m = r.FaultModel(args(loss=0.10), "A>B:EVADE_NAV")
    lost = sum(1 for _ in range(N) if not m.decide()[0])
    within("loss fraction", lost / N, 0.10, binomial_tol(0.10, N), fails)

    m = r.FaultModel(args(duplicate=0.05), "A>B:EVADE_NAV")
    dup = sum(1 for _ in range(N) if len(m.decide()[0]) == 2)
    within("duplicate fraction", dup / N, 0.05, binomial_tol(0.05, N), fails)

    m = r.FaultModel(args(delay_ms=20.0, jitter_ms=10.0), "A>B:EVADE_NAV")
    d = [m.decide()[0][0] * 1e3 for _ in range(N)]
    if not all(10.0 <= x < 30.0 for x in d):
        fails.append("uniform delay outside [10, 30) ms")
    within("uniform delay mean ms", sum(d) / N, 20.0, 5.0 * 10.0 / math.sqrt(3.0 * N), fails)

    m = r.FaultModel(args(delay_ms=20.0, jitter_ms=5.0, distribution="normal"), "A>B:EVADE_NAV")
    d = [m.decide()[0][0] * 1e3 for _ in range(N)]
    mean = sum(d) / N
    sd = math.sqrt(sum((x - mean) ** 2 for x in d) / (N - 1))
    within("normal delay mean ms", mean, 20.0, 5.0 * 5.0 / math.sqrt(N), fails)
    within("normal delay sd ms", sd, 5.0, 0.05 * 5.0, fails)

    m = r.FaultModel(args(delay_ms=20.0, reorder=0.05), "A>B:EVADE_NAV")
    early = sum(1 for _ in range(N) if m.decide()[0][0] == 0.0)
    within("reorder (sent at once) fraction", early / N, 0.05, binomial_tol(0.05, N), fails)

    cfg = args(loss=0.1, delay_ms=20.0, jitter_ms=10.0, duplicate=0.05, reorder=0.05)
    a1, a2 = r.FaultModel(cfg, "A>B:EVADE_NAV"), r.FaultModel(cfg, "A>B:EVADE_NAV")
    same = all(a1.decide() == a2.decide() for _ in range(2000))
    b = r.FaultModel(args(seed=8, loss=0.1, delay_ms=20.0, jitter_ms=10.0, duplicate=0.05,
                          reorder=0.05), "A>B:EVADE_NAV")
    a3 = r.FaultModel(cfg, "A>B:EVADE_NAV")
    differ = any(a3.decide() != b.decide() for _ in range(2000))
    print(f"{'ok  ' if same else 'FAIL'} same seed, same decisions")
    print(f"{'ok  ' if differ else 'FAIL'} other seed, other decisions")
    if not (same and differ):
        fails.append("determinism")

    relay = os.path.join(src, "scripts", "fault_relay")
    ok_a, ok_b = "udpm://239.255.76.67:7667?ttl=0", "udpm://239.255.76.68:7668?ttl=0"
    for bad, word in ((["--loss", "1.5"], "--loss"), (["--delay-ms", "nan"], "--delay-ms"),
                      (["--reorder", "0.05"], "--reorder"),
                      (["--delay-ms", "5", "--jitter-ms", "10"], "--jitter-ms"),
                      (["--b", ok_a], "must differ"),
                      (["--b", "udpm://239.255.76.68:7668?ttl=1"], "ttl must be 0"),
                      (["--b", "udpm://10.0.0.1:7668?ttl=0"], "not a multicast group")):
        argv = ["--a", ok_a, "--b", ok_b] + bad
        p = subprocess.run([sys.executable, relay] + argv, capture_output=True, text=True,
                           timeout=20)
        good = p.returncode == 2 and word in p.stderr
        print(f"{'ok  ' if good else 'FAIL'} {' '.join(bad)}: exit {p.returncode}, "
              f"{p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ''}")
        if not good:
            fails.append(f"bad argument {bad}")
    return 1 if fails else 0


def lcm_datagram(channel, payload):
    return struct.pack(">II", 0x4C433032, 0) + channel.encode() + b"\0" + payload


def rx(group, port):
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
    s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    s.bind(("", port))
    s.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP,
                 struct.pack("4s4s", socket.inet_aton(group), socket.inet_aton("0.0.0.0")))
    s.setblocking(False)
    return s


def drain(s):
    got = []
    while True:
        try:
            got.append(s.recv(65536))
        except BlockingIOError:
            return got


def network_inner(src):
    subprocess.run(["ip", "link", "set", "lo", "up"], check=True)
    subprocess.run(["ip", "link", "set", "lo", "multicast", "on"], check=True)
    subprocess.run(["ip", "route", "add", "224.0.0.0/4", "dev", "lo"], check=True)
    ga, pa, gb, pb = "239.255.76.67", 7667, "239.255.76.68", 7668
    with tempfile.TemporaryDirectory() as tmp:
        relay = subprocess.Popen(
            [sys.executable, os.path.join(src, "scripts", "fault_relay"),
             "--a", f"udpm://{ga}:{pa}?ttl=0", "--b", f"udpm://{gb}:{pb}?ttl=0",
             "--blackout-at-s", "0.5", "--blackout-s", "0.5", "--stats",
             os.path.join(tmp, "stats.json")], stderr=subprocess.PIPE, text=True)
        relay.stderr.readline()  # "ready": its sockets are joined
        ra, rb = rx(ga, pa), rx(gb, pb)
        tx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
        tx.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 0)
        sent_t, t0, in_a, in_b = {}, None, [], []
        for k in range(150):
            now = time.monotonic()
            t0 = now if t0 is None else t0
            sent_t[k] = now - t0
            tx.sendto(lcm_datagram("EVADE_NAV", b"A-nav-%d" % k), (ga, pa))
            tx.sendto(lcm_datagram("EVADE_THRUST_CMD", b"A-cmd-%d" % k), (ga, pa))
            tx.sendto(lcm_datagram("EVADE_THRUST_CMD", b"B-cmd-%d" % k), (gb, pb))
            tx.sendto(lcm_datagram("EVADE_NAV", b"B-nav-%d" % k), (gb, pb))
            time.sleep(0.01)
            in_a += drain(ra)  # read as we go: the socket buffers hold ~200 datagrams
            in_b += drain(rb)
        time.sleep(0.2)
        got_a, got_b = b"\n".join(in_a + drain(ra)), b"\n".join(in_b + drain(rb))
        relay.terminate()
        relay.wait(timeout=10)
    fails = []
    # On B: our own B-* sends and the relayed A-nav-*; never A-cmd (commands do not cross A->B).
    # On A: our own A-* sends and the relayed B-cmd-*; never B-nav.
    if b"A-cmd-" in got_b:
        fails.append("a command crossed from A to B")
    if b"B-nav-" in got_a:
        fails.append("navigation crossed from B to A")
    for k in range(150):
        t = sent_t[k]
        inside = 0.53 <= t < 0.97
        outside = t < 0.47 or t >= 1.03
        for tag, where in ((b"A-nav-%d" % k, got_b), (b"B-cmd-%d" % k, got_a)):
            present = (tag + b"\n") in (where + b"\n") or where.endswith(tag)
            if inside and present:
                fails.append(f"{tag.decode()} (sent {t:.3f} s) delivered in the blackout")
            if outside and not present:
                fails.append(f"{tag.decode()} (sent {t:.3f} s) not delivered")
    for f in fails[:20]:
        print("FAIL: " + f)
    print(f"{len(fails)} failures over 150 datagrams each way")
    return 1 if fails else 0


def test_network(src):
    if subprocess.run(["unshare", "-rn", "true"], capture_output=True).returncode != 0:
        print("SKIP: unshare -rn is not permitted here (no user namespaces)")
        return 77
    p = subprocess.run(["unshare", "-rn", sys.executable, os.path.abspath(__file__), src,
                        "network-inner"], timeout=60)
    return p.returncode


def main():
    src, what = sys.argv[1], sys.argv[2]
    return {"models": test_models, "network": test_network,
            "network-inner": network_inner}[what](src)


if __name__ == "__main__":
    sys.exit(main())
