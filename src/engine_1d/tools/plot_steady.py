#!/usr/bin/python3
"""Contour plots of the engine_1d_steady results: reference BSFC, 1D BSFC and their error over
speed x torque, plus lambda, turbine-inlet T, peak pressure and NOx. Points outside the BSFC
validation region (column in_region = 0, reason in region_note) are drawn as crosses, those
inside as dots; the error panel's title gives the statistics of both.
Usage: plot_steady.py steady_points.csv OUTDIR"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402


def main():
    path, out = sys.argv[1], sys.argv[2]
    with open(path) as f:
        rows = [{k: (v if k == "region_note" else float(v)) for k, v in r.items()}
                for r in csv.DictReader(f)]
    if len(rows) < 3:
        print("plot_steady.py: fewer than 3 points, no contour plot")
        return
    n = [r["speed_rpm"] for r in rows]
    t = [r["torque_Nm"] for r in rows]
    tri = mtri.Triangulation(n, t)
    panels = [("bsfc_ref_g_kWh", "reference BSFC [g/kWh]", "viridis_r"),
              ("bsfc_g_kWh", "1D engine BSFC [g/kWh]", "viridis_r"),
              ("bsfc_err_pct", "BSFC error 1D vs reference [%]", "RdBu_r")]
    fig, axs = plt.subplots(1, 3, figsize=(17, 5), sharey=True)
    lo = min(min(r["bsfc_ref_g_kWh"] for r in rows), min(r["bsfc_g_kWh"] for r in rows))
    hi = min(max(max(r["bsfc_ref_g_kWh"] for r in rows), max(r["bsfc_g_kWh"] for r in rows)), 320)
    for ax, (key, title, cmap) in zip(axs, panels):
        z = [r[key] for r in rows]
        if key == "bsfc_err_pct":
            m = max(abs(v) for v in z)
            levels = [-m + 2 * m * i / 20 for i in range(21)]
        else:
            levels = [lo + (hi - lo) * i / 20 for i in range(21)]
        cs = ax.tricontourf(tri, z, levels=levels, cmap=cmap, extend="both")
        inside = [r.get("in_region", 1.0) > 0.5 for r in rows]
        ax.plot([x for x, i in zip(n, inside) if i], [y for y, i in zip(t, inside) if i], "k.", ms=3)
        ax.plot([x for x, i in zip(n, inside) if not i], [y for y, i in zip(t, inside) if not i],
                "kx", ms=3, mew=0.6)
        fig.colorbar(cs, ax=ax)
        if key == "bsfc_err_pct":
            e_all = [abs(v) for v in z]
            e_in = [abs(v) for v, i in zip(z, inside) if i]
            title += (f"\nall {len(e_all)}: mean |e| {sum(e_all) / len(e_all):.2f} %, max {max(e_all):.1f} %")
            if e_in:
                title += (f"; region (dots) {len(e_in)}: mean {sum(e_in) / len(e_in):.2f} %, "
                          f"max {max(e_in):.1f} %")
        ax.set_title(title, fontsize=9 if key == "bsfc_err_pct" else None)
        ax.set_xlabel("speed [rpm]")
    axs[0].set_ylabel("brake torque [Nm]")
    fig.tight_layout()
    fig.savefig(f"{out}/steady_bsfc.png", dpi=110)

    others = [("lambda", "lambda [-]"), ("T3_K", "turbine-inlet T [K]"),
              ("p3_Pa", "turbine-inlet p [Pa]"), ("pmax_bar", "peak cylinder pressure [bar]"),
              ("turbo_krpm", "turbo speed [krpm]"), ("nox_g_kWh", "engine-out NOx [g/kWh]"),
              ("air_kg_s", "air mass flow [kg/s]"), ("boost_Pa", "boost pressure [Pa]")]
    fig, axs = plt.subplots(2, 4, figsize=(20, 8), sharex=True, sharey=True)
    for ax, (key, title) in zip(axs.flat, others):
        cs = ax.tricontourf(tri, [r[key] for r in rows], levels=20, cmap="viridis")
        ax.plot(n, t, "k.", ms=2)
        fig.colorbar(cs, ax=ax)
        ax.set_title(title)
    for ax in axs[1]:
        ax.set_xlabel("speed [rpm]")
    for ax in axs[:, 0]:
        ax.set_ylabel("brake torque [Nm]")
    fig.tight_layout()
    fig.savefig(f"{out}/steady_quantities.png", dpi=110)
    print(f"plot_steady.py: wrote {out}/steady_bsfc.png and {out}/steady_quantities.png")


if __name__ == "__main__":
    main()
