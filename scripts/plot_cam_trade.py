#!/usr/bin/python3
"""Plot the collision-avoidance trade space of `evade plan cam --sweep-lead A:B:N` (CSV).

usage: plot_cam_trade.py SWEEP.csv [SWEEP_ALONG_TRACK.csv] OUT.png

SWEEP.csv: `evade plan cam ... --sweep-lead A:B:N` (the unconstrained burn); the optional
second file the same with --along-track-only. Panels: (a) |dv| against the lead time (log),
with the 1/(3 lead) scaling of an along-track burn for reference; (b) Pc before the burn and
after it (verified by propagation), with the threshold. Rows with an error (no plan at that
lead) are left out and counted on stderr.
"""
import csv
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
except ImportError as e:  # one line, never a traceback
    sys.stderr.write(f"plot_cam_trade.py: matplotlib is not available ({e}); scripts/setup installs python3-matplotlib\n")
    sys.exit(1)


def load(path):
    rows = list(csv.DictReader(open(path)))
    ok = [r for r in rows if r["dv_mps"] != ""]
    if len(ok) < len(rows):
        sys.stderr.write("plot_cam_trade.py: %s: %d of %d leads without a plan\n"
                         % (path, len(rows) - len(ok), len(rows)))
    col = lambda k: [float(r[k]) for r in ok]  # noqa: E731
    return col("lead_s"), col("dv_mps"), col("pc_before"), col("pc_after")


def main():
    if len(sys.argv) not in (3, 4):
        sys.stderr.write(__doc__)
        return 2
    lead, dv, pc0, pc1 = load(sys.argv[1])
    if not lead:
        sys.stderr.write("plot_cam_trade.py: no plan in %s\n" % sys.argv[1])
        return 1
    fig, (a, b) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    h = [x / 3600.0 for x in lead]
    a.semilogy(h, [x * 100 for x in dv], "o-", ms=3, label="minimum |dv| (RTN)")
    if len(sys.argv) == 4:
        la, dva, _, _ = load(sys.argv[2])
        a.semilogy([x / 3600.0 for x in la], [x * 100 for x in dva], "s--", ms=3,
                   label="along track only")
    # An along-track burn displaces the primary by about 3 dv lead at TCA: for a fixed
    # displacement the burn scales as 1 / lead (anchored at the longest lead).
    k = dv[-1] * lead[-1]
    a.semilogy(h, [100 * k / x for x in lead], ":", color="gray", label="∝ 1 / lead")
    a.set_ylabel("|dv| [cm/s]")
    a.legend()
    a.grid(True, which="both", alpha=0.3)
    b.semilogy(h, pc0, "k-", label="Pc before")
    b.semilogy(h, pc1, "o-", ms=3, label="Pc after (verified by propagation)")
    b.set_xlabel("lead time before TCA [h]")
    b.set_ylabel("Pc (2D)")
    b.legend()
    b.grid(True, which="both", alpha=0.3)
    fig.suptitle("evade plan cam: trade space")
    fig.tight_layout()
    fig.savefig(sys.argv[-1], dpi=90)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception as e:  # noqa: BLE001 - one line for the CLI to report, never a traceback
        sys.stderr.write(f"plot_cam_trade.py: {type(e).__name__}: {e}\n")
        sys.exit(1)
