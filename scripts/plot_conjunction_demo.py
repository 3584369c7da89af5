#!/usr/bin/env python3
"""The plot of scripts/conjunction_demo (docs/AUTONOMY.md AUT-11): one row per run, from
OUT/<run>.json (`evade cam hil`). Left: the Pc the node knew over time to TCA (each CDM's, the
onboard post-burn Pc once proposed) on a log scale with the red threshold and the target, the
CDMs sent, the veto deadline and the burn marked. Right: the truth's range between the two
objects around TCA is not recorded whole, so the bar shows the truth's miss against the miss
without the burn, with the hard-body radius.

  plot_conjunction_demo.py OUT RUNS PNG"""
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def draw(ax_pc, ax_miss, h):
    tca = h["tca_s"]
    red, target = h["thresholds"]["pc_red"], h["thresholds"]["pc_target"]
    ax_pc.axhline(red, color="red", lw=1, label="red threshold")
    ax_pc.axhline(target, color="green", lw=1, ls="--", label="post-burn target")
    for c in h["cdms"]:
        x = (c["t_send_s"] - tca) / 3600.0
        ax_pc.semilogy([x], [max(c["pc"], 1e-12)], "ko")
        ax_pc.axvline(x, color="gray", lw=0.5)
        ax_pc.axvline(-c["veto_deadline_before_tca_s"] / 3600.0, color="orange", lw=0.8, ls=":")
    for p in h["proposals"]:
        q = p["proposal"]
        if q["proposal_id"] and q["state"] == "proposed":
            ax_pc.semilogy([(p["t_s"] - tca) / 3600.0], [q["post_pc"]], "bs")
    for b in h["burns"]:
        ax_pc.axvline(-b["before_tca_s"] / 3600.0, color="blue", lw=1.5, label="burn")
    ax_pc.set_ylim(1e-13, 1.0)
    ax_pc.set_xlim(-tca / 3600.0, 0.0)
    ax_pc.set_xlabel("time to TCA [h]")
    ax_pc.set_ylabel("Pc")
    ax_pc.set_title("%s: CDMs (black), post-burn Pc (blue), veto deadline (orange)" % h["run"],
                    fontsize=9)
    ax_pc.legend(fontsize=7, loc="lower left")
    t = h["truth"]
    ax_miss.bar(["no burn", "flown"], [t["miss_without_burn_m"], t["miss_m"]],
                color=["gray", "blue"])
    ax_miss.set_ylabel("truth's miss [m]")
    ax_miss.set_title("truth Pc at the new TCA %.2e" % t.get("pc_2d", float("nan")), fontsize=9)


def main():
    out, runs, png = sys.argv[1], [r for r in sys.argv[2].split(",") if r], sys.argv[3]
    fig, axes = plt.subplots(len(runs), 2, figsize=(11, 3.2 * len(runs)), squeeze=False,
                             gridspec_kw={"width_ratios": [3, 1]})
    for k, r in enumerate(runs):
        draw(axes[k][0], axes[k][1], json.load(open(os.path.join(out, r + ".json"))))
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
