#!/usr/bin/python3
"""ctest LcmLink.HilDuplicatesNeverThrust: 5 % duplication on the HIL fault bench.

scripts/hil_faults --case duplicate --relay: paper 000's seed0 case (1 m/s^2, 10 s, 50 Hz),
the node at its own fixed rate against `evade sim --realtime`, scripts/fault_relay duplicating
5 % of the datagrams both ways (seeded: the same datagrams in every run). Asserts:
  - the node counted every duplicated input the relay delivered as stale `duplicate_seq`
    (no loss or delay here, so both copies of each arrive: exactly one of them is stale) and
    consumed each measurement once (consumed + superseded = the relay's originals);
  - no thrust from an older or stale measurement (thrust commands' input utime never goes
    back, and is within the 0.5 s stale limit);
  - the simulator discarded duplicated commands (commands_discarded_old > 0; at most the
    relay's count of command copies that were not newer: copies delivered after the simulator
    stopped listening are not seen) and received no malformed one;
  - the input accounting identity.
No timing is asserted. Exit 77 without user namespaces.
usage: hil_duplicate_test.py SOURCE_DIR BUILD_DIR
"""
import sys

import hil_fault_case


def main():
    status, j, returncode = hil_fault_case.run(sys.argv[1], sys.argv[2], "duplicate")
    if status is not None:
        return status
    i, rel = j["inputs"], j["relay"]
    ins = ("A>B EVADE_NAV", "A>B EVADE_ANGLES")
    dup = sum(rel[k]["duplicated"] for k in ins)
    originals = sum(rel[k]["seen"] for k in ins)
    print(f"miss {j['miss_m']:.4f} m; relay duplicated {dup} of {originals} inputs; node "
          f"inputs {i}; simulator discarded {j['commands_discarded_old']} commands as not "
          f"newer (relay delivered {j['relay_cmds_delivered_not_newer']} such copies)")
    checks = [
        ("some inputs duplicated", dup > 0),
        ("every duplicate counted stale duplicate_seq",
         i["by_reason"].get("duplicate_seq", 0) == dup and i["stale"] == dup),
        ("each original used once", i["consumed"] + i["superseded"] == originals),
        ("no thrust from an older or stale measurement",
         j["thrust_from_older_input"] == 0 and j["thrust_without_input"] == 0
         and j["thrust_max_input_age_ms"] <= 500.0),
        ("simulator discarded duplicated commands",
         0 < j["commands_discarded_old"] <= j["relay_cmds_delivered_not_newer"]),
        ("simulator received no malformed command", j["commands_discarded_malformed"] == 0),
        ("input accounting identity", j["identity_holds"]),
        ("node received what the relay delivered", j["node_received_equals_relay_delivered"]),
    ]
    for what, ok in checks:
        print(f"{'ok  ' if ok else 'FAIL'} {what}")
    return 0 if all(ok for _, ok in checks) and returncode == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
