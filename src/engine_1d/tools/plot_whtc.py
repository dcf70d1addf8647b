#!/usr/bin/python3
"""Plots of engine_1d_whtc results: speed, reference vs actual torque, cumulative fuel (1D vs map),
boost/turbo speed, and the torque regression scatter.
Usage: plot_whtc.py whtc_1hz.csv OUTDIR"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    path, out = sys.argv[1], sys.argv[2]
    with open(path) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    if not rows:
        print("plot_whtc.py: no data")
        return
    c = {k: [r[k] for r in rows] for k in rows[0]}
    t = c["t_s"]
    fig, axs = plt.subplots(4, 1, figsize=(14, 13), sharex=True)
    axs[0].plot(t, c["speed_rpm"], "k", lw=0.8)
    axs[0].set_ylabel("speed [rpm]")
    axs[1].plot(t, c["torque_ref_Nm"], "k", lw=0.8, label="reference (GTR No. 4)")
    axs[1].plot(t, c["torque_Nm"], "r", lw=0.8, label="1D engine (cycle mean)")
    axs[1].set_ylabel("torque [Nm]")
    axs[1].legend(loc="upper right")
    axs[2].plot(t, c["fuel_cum_g"], "r", label="1D engine")
    axs[2].plot(t, c["fuel_map_cum_g"], "k--", label="reference map along the actual trace")
    axs[2].set_ylabel("cumulative fuel [g]")
    axs[2].legend(loc="upper left")
    axs[3].plot(t, c["boost_bar"], "b", lw=0.8, label="boost [bar]")
    axs[3].plot(t, c["boost_target_bar"], "c", lw=0.6, label="boost target [bar]")
    ax2 = axs[3].twinx()
    ax2.plot(t, c["turbo_krpm"], "g", lw=0.6)
    ax2.set_ylabel("turbo speed [krpm]", color="g")
    axs[3].set_ylabel("boost [bar]")
    axs[3].legend(loc="upper left")
    axs[3].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(f"{out}/whtc_traces.png", dpi=100)

    fig, ax = plt.subplots(figsize=(6, 6))
    ax.plot(c["torque_ref_Nm"], c["torque_Nm"], ".", ms=2)
    lo = min(c["torque_ref_Nm"] + c["torque_Nm"])
    hi = max(c["torque_ref_Nm"] + c["torque_Nm"])
    ax.plot([lo, hi], [lo, hi], "k-", lw=0.8)
    ax.set_xlabel("reference torque [Nm]")
    ax.set_ylabel("actual torque [Nm]")
    ax.set_title("WHTC torque regression (1 Hz)")
    fig.tight_layout()
    fig.savefig(f"{out}/whtc_regression.png", dpi=100)
    print(f"plot_whtc.py: wrote {out}/whtc_traces.png and {out}/whtc_regression.png")


if __name__ == "__main__":
    main()
