#!/usr/bin/python3
"""Plot an `evade sim --csv` time history like paper 000 (Yao & Wang 2012) Figs. 3-4.

usage: plot_sim.py RUN.csv OUT.png

Panels: (a) relative position of the debris seen from the satellite, projected on the plane
perpendicular to the initial relative velocity (the encounter plane: the evasion shows as the
track moving away from the origin), (b) range, (c) LOS rate, true and estimated (Fig. 4),
(d) zero-effort miss r^2 w_s / |r_dot| from the truth (eq. 7) and the commanded acceleration.
"""
import csv
import math
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
except ImportError as e:  # one line, never a traceback
    sys.stderr.write(f"plot_sim.py: matplotlib is not available ({e}); scripts/setup installs python3-matplotlib\n")
    sys.exit(1)


def main():
    if len(sys.argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    rows = list(csv.DictReader(open(sys.argv[1])))
    if not rows:
        sys.stderr.write("plot_sim.py: empty CSV\n")
        return 1
    f = lambda k: [float(r[k]) for r in rows]  # noqa: E731
    t = f("t_s")
    t0 = t[0]
    t = [x - t0 for x in t]
    rel = list(zip(f("rel_x_m"), f("rel_y_m"), f("rel_z_m")))
    v0 = [float(rows[1]["rel_%s_m" % a]) - float(rows[0]["rel_%s_m" % a]) for a in "xyz"]
    n = math.sqrt(sum(c * c for c in v0))
    w = [c / n for c in v0]
    ref = [1.0, 0.0, 0.0] if abs(w[0]) < 0.9 else [0.0, 1.0, 0.0]
    p1 = [w[1] * ref[2] - w[2] * ref[1], w[2] * ref[0] - w[0] * ref[2], w[0] * ref[1] - w[1] * ref[0]]
    n1 = math.sqrt(sum(c * c for c in p1))
    p1 = [c / n1 for c in p1]
    p2 = [w[1] * p1[2] - w[2] * p1[1], w[2] * p1[0] - w[0] * p1[2], w[0] * p1[1] - w[1] * p1[0]]
    x1 = [sum(a * b for a, b in zip(r, p1)) for r in rel]
    x2 = [sum(a * b for a, b in zip(r, p2)) for r in rel]

    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    ax[0][0].plot(x1, x2, "b-")
    ax[0][0].plot([x1[-1]], [x2[-1]], "ro", label="end (closest approach)")
    ax[0][0].set_xlabel("encounter-plane axis 1 [m]")
    ax[0][0].set_ylabel("encounter-plane axis 2 [m]")
    ax[0][0].set_title("debris relative to satellite, encounter plane (cf. Fig. 3)")
    ax[0][0].axis("equal")
    ax[0][0].legend()
    ax[0][1].semilogy(t, f("range_m"))
    ax[0][1].set_xlabel("time from detection [s]")
    ax[0][1].set_ylabel("range [m]")
    ax[0][1].set_title("range")
    ax[1][0].semilogy(t, [max(x, 1e-12) for x in f("los_rate_true_radps")], label="true")
    ax[1][0].semilogy(t, [max(x, 1e-12) for x in f("los_rate_est_radps")], "--", label="estimated")
    ax[1][0].set_xlabel("time from detection [s]")
    ax[1][0].set_ylabel("LOS rate [rad/s]")
    ax[1][0].set_title("LOS rate (cf. Fig. 4)")
    ax[1][0].legend()
    zem = [float(r["zem_true_m"]) for r in rows]
    ax[1][1].plot(t, zem, label="ZEM (truth, eq. 7) [m]")
    ax2 = ax[1][1].twinx()
    ax2.plot(t, f("cmd_accel_mps2"), "r:", label="commanded accel [m/s^2]")
    ax2.set_ylabel("accel [m/s^2]")
    ax[1][1].set_xlabel("time from detection [s]")
    ax[1][1].set_ylabel("ZEM [m]")
    ax[1][1].set_title("predicted miss and command")
    ax[1][1].legend(loc="upper left")
    ax2.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=100)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception as e:  # noqa: BLE001 - one line for the CLI to report, never a traceback
        sys.stderr.write(f"plot_sim.py: {type(e).__name__}: {e}\n")
        sys.exit(1)
