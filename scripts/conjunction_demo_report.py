#!/usr/bin/env python3
"""The summary of scripts/conjunction_demo (docs/AUTONOMY.md AUT-11): one JSON object on stdout
from OUT/<run>.json (`evade cam hil`) and OUT/node_<run>.json (the node's --stats-json).

  conjunction_demo_report.py OUT RUNS        (RUNS: comma-separated burn,veto,update)

Per run: outcome (burned / vetoed / no burn), the truth's miss and 2D Pc at the new TCA beside
the red threshold and the target, the onboard Pc before and after the burn and its predicted
miss, the delivered delta-v and when, the decision latency on the simulator's clock and the
node's planning worker on the wall clock, the node's cycle compute p50/p99/max, overruns (a
lockstep cycle has none: no deadline) and the cycles whose compute exceeded the period, and
whether its input accounting holds (received = consumed + rejected + stale + superseded +
dropped + auth_failed + replayed)."""
import json
import os
import sys


def summary(out, run):
    h = json.load(open(os.path.join(out, run + ".json")))
    node = json.load(open(os.path.join(out, "node_" + run + ".json")))
    i = node["inputs"]
    identity = i["received"] == (i["consumed"] + i["rejected"] + i["stale"] + i["superseded"]
                                 + i["dropped"] + i["auth_failed"] + i["replayed"])
    ob = h["onboard"] or {}
    outcome = "burned" if h["burns"] else ("vetoed" if ob.get("state") == "vetoed" else "no burn")
    lat = h["decision_latency"]
    return {
        "outcome": outcome,
        "truth_miss_m": h["truth"]["miss_m"],
        "truth_miss_without_burn_m": h["truth"]["miss_without_burn_m"],
        "truth_pc_2d": h["truth"].get("pc_2d"),
        "pc_red": h["thresholds"]["pc_red"],
        "pc_target": h["thresholds"]["pc_target"],
        "onboard_pc": ob.get("pc"),
        "onboard_post_pc": ob.get("post_pc"),
        "onboard_post_miss_m": ob.get("post_miss_m"),
        "dv_mps": h["dv_total_mps"],
        "burn_before_tca_s": [b["before_tca_s"] for b in h["burns"]],
        "cdms": [{"t_send_s": c["t_send_s"], "version": c["version"], "miss_m": c["miss_m"],
                  "pc": c["pc"]} for c in h["cdms"]],
        "uplinks": [{"what": u["what"], "outcome": u["outcome"], "reason": u["reason"]}
                    for u in h["uplinks"]],
        "decisions": [{"state": d["state"], "receipt_to_decision_sim_s": d["receipt_to_decision_s"]}
                      for d in lat],
        "planning_worker_ms_max": node["autonomy"]["planning_us_max"] * 1e-3,
        "faster_than_real_time": h["faster_than_real_time"],
        "cycles": node["cycles"],
        "cycle_compute_us": node["compute_us"],
        "overruns": node["overruns"],
        "cycles_over_period": node["cycles_over_period"],
        "inputs_identity_holds": identity,
        "autonomy": node["autonomy"],
        "wall_s": h["wall_s"],
    }


def main():
    out, runs = sys.argv[1], [r for r in sys.argv[2].split(",") if r]
    print(json.dumps({r: summary(out, r) for r in runs}, indent=2))


if __name__ == "__main__":
    main()
