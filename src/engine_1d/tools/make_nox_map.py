#!/usr/bin/python3
"""Engine-out NOx map of the map engine from the 1D engine's steady points.

usage: make_nox_map.py STEADY_CSV OUT_CSV "COMMAND THAT PRODUCED STEADY_CSV" [COMMIT]
  STEADY_CSV: DIR/steady_points.csv of engine_1d_steady (default grid 9 speeds x 21 loads,
  650-2450 rpm, 10-100 % load, ambient 25 C). Every point must have converged.
Writes OUT_CSV (config/data/engine/nox_map_1d.csv) with '#' header lines saying how it was made,
and columns speed_rpm, load, torque_Nm, ei_nox_g_per_kg, nox_g_kWh, fuel_g_s:
  ei_nox_g_per_kg = NOx mass flow / fuel mass flow of the 1D engine at that point, where
  NOx [g/s] = nox_g_kWh * T_b * omega / 3.6e6 (as NO2). The map engine (src/engine_map/nox_map.hpp)
  interpolates EI bilinearly over speed x load (load = T_b / T_full-load) and multiplies by its own
  fuel flow (0 in a fuel cut); outside the grid it clamps to the edge values.
Run with /usr/bin/python3 (standard library only)."""
import csv
import math
import sys


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    src, out, cmd = sys.argv[1], sys.argv[2], sys.argv[3]
    commit = sys.argv[4] if len(sys.argv) > 4 else "(not given)"
    rows = list(csv.DictReader(open(src)))
    bad = [r for r in rows if r["converged"] != "1"]
    if bad:
        sys.exit(f"make_nox_map.py: {len(bad)} points of {src} did not converge, e.g. "
                 f"{bad[0]['speed_rpm']} rpm load {bad[0]['load']}")
    lines = []
    for r in rows:
        n, T, fuel = float(r["speed_rpm"]), float(r["torque_Nm"]), float(r["fuel_kg_s"])
        nox_g_kwh = float(r["nox_g_kWh"])
        nox_g_s = nox_g_kwh * T * n * math.pi / 30.0 / 3.6e6
        ei = nox_g_s / fuel  # g NO2 per kg fuel
        lines.append((n, float(r["load"]), T, ei, nox_g_kwh, fuel * 1e3))
    lines.sort()
    amb = sorted(set(r.get("ambient_T_K", "298.15") for r in rows))
    with open(out, "w") as f:
        f.write("# Engine-out NOx map of the map engine (src/engine_map/nox_map.hpp), derived from the\n"
                "# calibrated 1D engine (src/engine_1d README, 'Engine-out NOx'): emission index\n"
                "# ei_nox_g_per_kg [g NO2 / kg fuel] over engine speed [rpm] x load [T_b / T_full-load].\n"
                "# The map engine multiplies it by its own fuel flow (0 in a fuel cut) and clamps\n"
                "# outside the grid. Warm engine, ambient %s K, standard pressure, no EGR.\n"
                "# Generated, do not edit by hand:\n"
                "#   %s\n"
                "#   /usr/bin/python3 src/engine_1d/tools/make_nox_map.py %s %s '<command>' %s\n"
                "# (1D engine at commit %s). torque_Nm, nox_g_kWh, fuel_g_s: for information.\n"
                % ("/".join(amb), cmd, "DIR/steady_points.csv", "config/data/engine/nox_map_1d.csv",
                   commit, commit))
        f.write("speed_rpm,load,torque_Nm,ei_nox_g_per_kg,nox_g_kWh,fuel_g_s\n")
        for n, l, T, ei, g, fu in lines:
            f.write(f"{n:.6g},{l:.6g},{T:.6g},{ei:.6g},{g:.6g},{fu:.6g}\n")
    print(f"make_nox_map.py: wrote {out} ({len(lines)} points, EI {min(x[3] for x in lines):.2f}"
          f"..{max(x[3] for x in lines):.2f} g/kg)")


if __name__ == "__main__":
    main()
