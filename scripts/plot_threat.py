#!/usr/bin/python3
"""Plots of `evade plan threat-area` (paper 001): threat arc vs evasion burn (Fig. 8) and the
eliminating burn vs transfer time (Fig. 4).

Usage: plot_threat.py RESULT.json OUT.png   (RESULT.json: the command's --json output)
"""
import json
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
except ImportError as e:  # one line, never a traceback
    sys.stderr.write(f"plot_threat.py: matplotlib is not available ({e}); scripts/setup installs python3-matplotlib\n")
    sys.exit(1)

PAPER_ELIMINATING_MPS = 161.698


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_threat.py RESULT.json OUT.png")
    with open(sys.argv[1]) as f:
        r = json.load(f)
    panels = [k for k in ("sweep_dv", "sweep_transfer") if r.get(k)]
    if not panels:
        sys.exit("plot_threat.py: the result has neither sweep_dv nor sweep_transfer")
    fig, axes = plt.subplots(1, len(panels), figsize=(6.5 * len(panels), 4.5), squeeze=False)
    for ax, key in zip(axes[0], panels):
        rows = r[key]
        if key == "sweep_dv":
            x = [row["dv_mps"] for row in rows]
            y = [row["threat_arc_deg"] for row in rows]
            ax.plot(x, y, "o-", label="ours (HCW, ISRES)")
            ax.axvline(PAPER_ELIMINATING_MPS, color="r", ls="--",
                       label="paper: eliminated at 161.698 m/s")
            if "t0_bound_mps" in r:
                ax.axvline(r["t0_bound_mps"], color="g", ls=":",
                           label="bound dv_max - J(t0) = %.1f m/s" % r["t0_bound_mps"])
            if "eliminating_dv_mps" in r:
                ax.axvline(r["eliminating_dv_mps"], color="k", ls="-.",
                           label="ours: eliminated at %.2f m/s" % r["eliminating_dv_mps"])
            ax.set_xlabel("evasion burn V_E [m/s]")
            ax.set_ylabel("potential threat arc [deg]")
            ax.set_title("Threat arc vs evasion burn (paper 001 Fig. 8)")
        else:
            x = [row["dt_transfer_s"] for row in rows]
            ax.plot(x, [row["t0_bound_mps"] for row in rows], "g:",
                    label="bound dv_max - J(t0)")
            if all("eliminating_dv_mps" in row for row in rows):
                ax.plot(x, [row["eliminating_dv_mps"] for row in rows], "o-",
                        label="ours: eliminating V_E")
            ax.axvline(2200.0, color="r", ls="--", label="paper: worst case 2200 s")
            ax.set_xlabel("chaser transfer time dT [s]")
            ax.set_ylabel("burn [m/s]")
            ax.set_title("Eliminating burn vs transfer time (paper 001 Fig. 4)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception as e:  # noqa: BLE001 - one line for the CLI to report, never a traceback
        sys.stderr.write(f"plot_threat.py: {type(e).__name__}: {e}\n")
        sys.exit(1)
