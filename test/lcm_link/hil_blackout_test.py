#!/usr/bin/python3
"""ctest LcmLink.HilBlackoutGoesSafeAndRecovers: the 2 s blackout of the HIL fault bench.

scripts/hil_faults --case blackout --relay: paper 000's seed0 case (1 m/s^2, 10 s, 50 Hz),
the node at its own fixed rate against `evade sim --realtime`, every datagram between them
dropped from 3 s to 5 s after the simulator's start (scripts/fault_relay; the kernel's netem
is not needed). Asserts, from the node's own commands as it sent them (the relay's log):
  - every command from blackout start + stale limit (0.5 s) + 2 cycles (40 ms: the watchdog
    trips at the first cycle whose newest measurement is older than the limit, and a cycle may
    start up to one period late) to the blackout's end is SAFE with zero thrust;
  - the node is in EVADE again after the blackout, before the run ends;
  - no thrust from stale data: every thrust command used a measurement no older than the
    stale limit, none used an older one than an earlier thrust command;
  - the input accounting identity, and the node received exactly what the relay delivered.
No timing figure is asserted (the machine is shared). Exit 77 without user namespaces.
usage: hil_blackout_test.py SOURCE_DIR BUILD_DIR
"""
import sys

import hil_fault_case


def main():
    status, j, returncode = hil_fault_case.run(sys.argv[1], sys.argv[2], "blackout")
    if status is not None:
        return status
    hist = " -> ".join(f"{e['mode']} {e['t_s']:.2f}" for e in j["mode_history"])
    print(f"miss {j['miss_m']:.4f} m; node modes: {hist}")
    print(f"SAFE {j['blackout_safe_after_s']} s after the blackout began; EVADE again "
          f"{j['blackout_evade_again_after_end_s']} s after it ended; {j['blackout_cmds_checked']} "
          f"commands checked in the window; max measurement age of a thrust command "
          f"{j['thrust_max_input_age_ms']:.1f} ms; inputs {j['inputs']}")
    checks = [
        ("SAFE with zero thrust throughout the blackout", j["blackout_all_safe_zero_thrust"]),
        ("commands in the blackout window", j["blackout_cmds_checked"] >= 60),
        ("EVADE again after the blackout", j["blackout_evade_again_after_end_s"] is not None),
        ("thrust only from measurements within the stale limit",
         j["thrust_max_input_age_ms"] is not None and j["thrust_max_input_age_ms"] <= 500.0),
        ("no thrust without or from an older measurement",
         j["thrust_without_input"] == 0 and j["thrust_from_older_input"] == 0),
        ("input accounting identity", j["identity_holds"]),
        ("node received what the relay delivered", j["node_received_equals_relay_delivered"]),
        ("simulator received no malformed command", j["commands_discarded_malformed"] == 0),
    ]
    for what, ok in checks:
        print(f"{'ok  ' if ok else 'FAIL'} {what}")
    return 0 if all(ok for _, ok in checks) and returncode == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
