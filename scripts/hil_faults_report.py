#!/usr/bin/python3
"""Report of scripts/hil_faults: reads each case's outputs (OUT/CASE/: sim.json, sim.csv,
node.json, and with the relay relay.json + relay_log.jsonl) and prints one JSON object, or the
Markdown table of docs/VALIDATION.md with --table. Exit 1 if a check fails:
  - the node's input accounting identity received = consumed + rejected + stale + superseded
    + dropped;
  - no thrust from stale data: every thrust command of the node used a measurement no older
    than the stale limit (0.5 s), and none used an older measurement than an earlier thrust
    command did (a duplicated or reordered datagram never drove the law backwards);
  - relay only: the node received exactly what the relay delivered to it;
  - the simulator received no malformed command (duplicated and overtaken commands are
    discarded by its filter and counted: commands_discarded_old, beside the relay's count of
    command copies it delivered that were not newer than an earlier one);
  - blackout: every command of the node from (blackout start + stale limit + 2 cycles) to the
    blackout's end is SAFE with zero thrust, and the node is evading again before the end.
"""
import argparse
import csv
import json
import os
import sys

MODES = ["STANDBY", "TRACKING", "EVADE", "COAST", "SAFE"]
REASONS = ["none", "no_track", "disarmed", "zem_above_trigger", "passed_closest_approach",
           "dv_budget_exhausted", "burn_time_exhausted", "nav_invalid", "nav_stale",
           "measurement_invalid", "measurement_stale", "low_los_rate"]
STALE_LIMIT_S = 0.5   # guidance.stale_limit_s default (the node is run without --stale-limit-s)
CYCLE_S = 0.02        # 50 Hz
BLACKOUT_S = 2.0


def name(table, k):
    return table[k] if 0 <= k < len(table) else str(k)


def transitions(points):
    """[(t, mode, reason)] -> the points where (mode, reason) changes."""
    out, last = [], None
    for t, m, r in points:
        if (m, r) != last:
            out.append({"t_s": round(t, 3), "mode": m, "reason": r})
            last = (m, r)
    return out


def load_case(d, blackout_at):
    sim = json.load(open(os.path.join(d, "sim.json")))
    node = json.load(open(os.path.join(d, "node.json")))
    start = sim["start_utime_us"]
    j = {"miss_m": sim["miss_m"], "dv_mps": sim["dv_mps"],
         "sim_commands_received": sim["commands_received"],
         "command_age_ms_p50": sim["command_age_ms_p50"],
         "command_age_ms_max": sim["command_age_ms_max"],
         "sim_late_steps": sim["sim_late_steps"], "sim_steps": sim["sim_steps"],
         "final_mode": sim.get("final_mode"), "node_overruns": node["overruns"],
         "node_watchdog_cycles": node["watchdog_cycles"], "inputs": node["inputs"]}
    i = node["inputs"]
    j["identity_holds"] = i["received"] == (i["consumed"] + i["rejected"] + i["stale"]
                                            + i["superseded"] + i["dropped"])
    rows = list(csv.DictReader(open(os.path.join(d, "sim.csv"))))
    t0 = float(rows[0]["t_s"]) if rows else 0.0
    end = start + round(1e6 * (float(rows[-1]["t_s"]) - t0)) if rows else start
    j["commands_discarded_old"] = sim["commands_discarded_old"]
    j["commands_discarded_malformed"] = sim["commands_discarded_malformed"]
    j["sim_command_timeouts"] = sim["command_timeouts"]
    log_path = os.path.join(d, "relay_log.jsonl")
    cmds = []  # the node's commands over the simulator's run (its last sample included)
    if os.path.exists(log_path):
        for line in open(log_path):
            e = json.loads(line)
            if e["ch"] == "cmd" and start <= e["utime"] <= end:
                cmds.append(e)
    if cmds:  # the node's own commands, as it sent them (before any fault)
        j["mode_history_source"] = "node commands (relay log)"
        pts = [((c["utime"] - start) * 1e-6, name(MODES, c["mode"]), name(REASONS, c["reason"]))
               for c in cmds]
        thrust = [c for c in cmds if c["accel_mps2"] > 0.0]
        ages = [(c["utime"] - c["input_utime"]) * 1e-3 for c in thrust]
        j["thrust_commands"] = len(thrust)
        j["thrust_max_input_age_ms"] = max(ages) if ages else None
        j["thrust_without_input"] = sum(1 for c in thrust if c["input_utime"] < 0)
        newest, backwards = -1, 0
        for c in thrust:
            backwards += 1 if c["input_utime"] < newest else 0
            newest = max(newest, c["input_utime"])
        j["thrust_from_older_input"] = backwards
    else:  # netem: what the simulator had in force at each sample (after the network)
        j["mode_history_source"] = "simulator (command in force at each sample)"
        pts = [(float(r["t_s"]) - t0, r["mode"], r["reason"]) for r in rows]
    j["mode_history"] = transitions(pts)
    if os.path.exists(os.path.join(d, "relay.json")):
        rel = json.load(open(os.path.join(d, "relay.json")))["channels"]
        g = lambda k, f: rel.get(k, {}).get(f, 0)
        ins = ("A>B EVADE_NAV", "A>B EVADE_ANGLES")
        j["relay"] = {k: {f: v for f, v in st.items() if f != "delay_ms"} | {
            "delay_ms": st.get("delay_ms")} for k, st in rel.items()}
        j["relay_inputs_delivered"] = sum(g(k, "delivered") for k in ins)
        j["node_received_equals_relay_delivered"] = (j["relay_inputs_delivered"]
                                                     == i["received"])
        j["relay_cmds_delivered"] = g("B>A EVADE_THRUST_CMD", "delivered")
        j["relay_cmds_delivered_not_newer"] = (j["relay_cmds_delivered"]
                                               - g("B>A EVADE_THRUST_CMD", "delivered_newer"))
    # Thrust the simulator's actuator (zero-order hold) applied in the blackout window.
    held = [r for r in rows if blackout_at <= float(r["t_s"]) - t0 < blackout_at + BLACKOUT_S
            and any(abs(float(r[f"accel_{a}_mps2"])) > 0.0 for a in "xyz")]
    j["sim_thrust_samples_in_blackout_window"] = len(held)
    return j, cmds, start


def check_blackout(j, cmds, start, blackout_at):
    b0, b1 = blackout_at, blackout_at + BLACKOUT_S
    safe_from = b0 + STALE_LIMIT_S + 2 * CYCLE_S
    during = [c for c in cmds if safe_from <= (c["utime"] - start) * 1e-6 < b1]
    j["blackout_cmds_checked"] = len(during)
    j["blackout_all_safe_zero_thrust"] = bool(during) and all(
        c["mode"] == 4 and c["accel_mps2"] == 0.0 for c in during)
    first_safe = next(((c["utime"] - start) * 1e-6 for c in cmds
                       if (c["utime"] - start) * 1e-6 >= b0 and c["mode"] == 4), None)
    j["blackout_safe_after_s"] = None if first_safe is None else round(first_safe - b0, 3)
    back = next(((c["utime"] - start) * 1e-6 for c in cmds
                 if (c["utime"] - start) * 1e-6 >= b1 and c["mode"] == 2), None)
    j["blackout_evade_again_after_end_s"] = None if back is None else round(back - b1, 3)


def failures(c, j):
    f = []
    if not j["identity_holds"]:
        f.append("input accounting identity broken")
    if j.get("thrust_max_input_age_ms") is not None and \
            j["thrust_max_input_age_ms"] > STALE_LIMIT_S * 1e3:
        f.append(f"thrust from a measurement {j['thrust_max_input_age_ms']:.1f} ms old")
    if j.get("thrust_without_input") or j.get("thrust_from_older_input"):
        f.append("thrust without a measurement or from an older one")
    if "relay" in j and not j["node_received_equals_relay_delivered"]:
        f.append(f"node received {j['inputs']['received']} != relay delivered "
                 f"{j['relay_inputs_delivered']}")
    if j["commands_discarded_malformed"]:
        f.append(f"the simulator received {j['commands_discarded_malformed']} malformed commands")
    if c.startswith("blackout") and "relay" in j:
        if not j["blackout_all_safe_zero_thrust"]:
            f.append("not SAFE with zero thrust throughout the blackout")
        if j["blackout_evade_again_after_end_s"] is None:
            f.append("no recovery (EVADE) after the blackout")
    return f


def hist_str(h):
    return " → ".join(f"{e['mode']} {e['t_s']:.2f}" + (f" ({e['reason']})" if e["reason"] not in
                      ("none", "no_track") else "") for e in h)


def table(res, meta):
    print(f"Injector: {meta['injector']}; {meta['sched']}; seed {meta['seed']}; load "
          f"{meta['load']}.")
    print()
    print("| case | miss m | Δ clean % | Δv m/s | node mode history (s from start) | inputs recv = "
          "cons + rej + stale + sup + drop | stale: dup / out-of-order / old utime | seq gaps | "
          "relay → node inputs (lost, dup) | max meas. age in a thrust cmd ms | cmds to sim: "
          "delivered (not newer) / accepted / discarded old | simulator thrust in the blackout s | "
          "overruns |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    clean = res.get("clean", {}).get("miss_m")
    for c, j in res.items():
        i, br = j["inputs"], j["inputs"]["by_reason"]
        d = "" if clean is None else f"{100.0 * (j['miss_m'] - clean) / clean:+.3f}"
        rl = j.get("relay", {})
        lost = sum(rl.get(k, {}).get("lost", 0) + rl.get(k, {}).get("blackout_dropped", 0)
                   for k in ("A>B EVADE_NAV", "A>B EVADE_ANGLES"))
        dup = sum(rl.get(k, {}).get("duplicated", 0) for k in ("A>B EVADE_NAV", "A>B EVADE_ANGLES"))
        age = j.get("thrust_max_input_age_ms")
        held = (f"{CYCLE_S * j['sim_thrust_samples_in_blackout_window']:.2f}"
                if c.startswith("blackout") else "–")
        print(f"| {c} | {j['miss_m']:.4f} | {d} | {j['dv_mps']:.3f} | {hist_str(j['mode_history'])} "
              f"| {i['received']} = {i['consumed']} + {i['rejected']} + {i['stale']} + "
              f"{i['superseded']} + {i['dropped']} | {br.get('duplicate_seq', 0)} / "
              f"{br.get('out_of_order_seq', 0)} / {br.get('stale_utime', 0)} | {i['seq_gaps']} | "
              f"{j.get('relay_inputs_delivered', '–')} ({lost}, {dup}) | "
              f"{'–' if age is None else f'{age:.1f}'} | {j.get('relay_cmds_delivered', '–')} "
              f"({j.get('relay_cmds_delivered_not_newer', '–')}) / {j['sim_commands_received']} / "
              f"{j['commands_discarded_old']} | {held} | {j['node_overruns']} |")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--out", required=True)
    p.add_argument("--injector", required=True)
    p.add_argument("--sched", required=True)
    p.add_argument("--seed", required=True)
    p.add_argument("--blackout-at-s", type=float, required=True)
    p.add_argument("--load", required=True)
    p.add_argument("--table", action="store_true")
    p.add_argument("cases", nargs="+")
    a = p.parse_args()
    res, bad = {}, {}
    for c in a.cases:
        j, cmds, start = load_case(os.path.join(a.out, c), a.blackout_at_s)
        if c.startswith("blackout") and cmds:
            check_blackout(j, cmds, start, a.blackout_at_s)
        res[c] = j
        f = failures(c, j)
        if f:
            bad[c] = f
    clean = res.get("clean", {}).get("miss_m")
    for j in res.values():
        if clean:
            j["miss_vs_clean_pct"] = 100.0 * (j["miss_m"] - clean) / clean
    meta = {"injector": a.injector, "sched": a.sched, "seed": a.seed, "load": a.load}
    if a.table:
        table(res, meta)
    else:
        print(json.dumps(dict(meta, cases=res, failures=bad), indent=2))
    for c, f in bad.items():
        print(f"hil_faults: {c}: " + "; ".join(f), file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
