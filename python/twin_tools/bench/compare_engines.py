"""Map engine vs 1D engine on the same stretch of a mission: torque traces (requested and actual
brake torque, from the bags by header.stamp), boost and fuel rate, plus a table of cumulative
fuel, NOx and wall/simulated time from the two runs' summary.json.

  python3 -m twin_tools.bench.compare_engines MAP_RUN_DIR ONED_RUN_DIR [--from S] [--to S]
      [-o torque_map_vs_1d.png]     (in a shell with the devel space: eval "$(scripts/twin env)";
                                    `scripts/twin bench 1d` draws it for its two runs)

The 1D engine's torque gradients are smoothed by turbo lag and manifold filling; the map engine
follows its request with the VECTO PT1 full-load build-up only.
"""
import argparse
import json
import os
import sys

import numpy as np
import rosbag
from twin_tools import wiring

# topics (twin_tools.wiring: the participants' topics.yaml)
ENGINE_STATE = wiring.topic("engine", "state")
VEHICLE_ENGINE_COMMAND = wiring.topic("vehicle", "engine_command")


def series(bag, topic, fields, t0, t1):
    out = {f: [] for f in ["t"] + fields}
    with rosbag.Bag(bag) as b:
        for _, m, _ in b.read_messages(topics=[topic]):
            t = m.header.stamp.to_sec()
            if t < t0 or t > t1:
                continue
            out["t"].append(t)
            for f in fields:
                out[f].append(getattr(m, f))
    return {k: np.asarray(v) for k, v in out.items()}


def main():
    ap = argparse.ArgumentParser(prog="compare_engines", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("map_dir")
    ap.add_argument("oned_dir")
    ap.add_argument("--from", dest="t0", type=float, default=0.0)
    ap.add_argument("--to", dest="t1", type=float, default=1e9)
    ap.add_argument("-o", "--out", default=None)
    a = ap.parse_args()
    runs = {"map": a.map_dir, "1d": a.oned_dir}
    data = {}
    for k, d in runs.items():
        bag = os.path.join(d, "run.bag")
        data[k] = (series(bag, ENGINE_STATE, ["brake_torque_nm", "boost_pressure_pa", "fuel_mass_flow_kg_s", "engine_speed_rad_s"], a.t0, a.t1),
                   series(bag, VEHICLE_ENGINE_COMMAND, ["torque_request_nm"], a.t0, a.t1))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(12, 9), sharex=True)
    for k, style in (("map", "-"), ("1d", "-")):
        e, c = data[k]
        ax[0].plot(c["t"], c["torque_request_nm"], "--", lw=0.7, label="request (%s run)" % k)
        ax[0].plot(e["t"], e["brake_torque_nm"], style, lw=1.0, label="brake torque, %s engine" % k)
        ax[1].plot(e["t"], e["boost_pressure_pa"] / 1e5, lw=1.0, label=k)
        ax[2].plot(e["t"], e["fuel_mass_flow_kg_s"] * 3.6e6, lw=0.8, label=k)
    ax[0].set(ylabel="torque [Nm]", title="Map vs 1D engine on the same mission stretch")
    ax[1].set(ylabel="boost pressure [bar]")
    ax[2].set(ylabel="fuel rate [g/h]", xlabel="time (header.stamp) [s]")
    for x in ax:
        x.legend(fontsize=8)
        x.grid(alpha=0.3)
    fig.tight_layout()
    out = a.out or os.path.join(a.oned_dir, "torque_map_vs_1d.png")
    fig.savefig(out, dpi=110)
    print(out)
    rows = []
    for k, d in runs.items():
        with open(os.path.join(d, "summary.json")) as f:
            s = json.load(f)
        if not s.get("sim_time_s"):
            sys.exit("compare_engines: the %s run in %s did not simulate anything (see its status.json)" % (k, d))
        rows.append((k, s))
    print("| engine | sim time [s] | wall/sim | fuel [kg] | fuel [L/100km] | NOx engine-out [g] |")
    print("|---|---|---|---|---|---|")
    for k, s in rows:
        print("| %s | %.1f | %.3f | %.4f | %.2f | %s |" % (k, s["sim_time_s"], s["wall_time_s"] / s["sim_time_s"],
              s.get("fuel_kg", float("nan")), s.get("fuel_l_per_100km", float("nan")),
              "%.2f" % s["nox_engine_out_g"] if "nox_engine_out_g" in s else "-"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
