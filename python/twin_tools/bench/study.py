"""The ambient study: baseline against the 48 V P1 hybrid at 0, 25 and 40 degC (scripts/twin bench
study, and the study table of scripts/twin bench hybrid).

`twin bench study [--engine 1d|map] [--until S] [--jobs N] [--slurm]` runs the study's sweep,
config/sweeps/study.yaml (6 runs: both scenarios x 0/25/40 degC, full Urban, HVAC on, the 1D
engine unless --engine map), with `twin sweep` (N at a time here, default 2, or as a Slurm job
array), then prints the study table and the wall time and writes them to docs/bench/study.md
(--engine map: study_map.md; with --until: results/bench/). The runs and the sweep's own table are
in results/bench/study_<engine>/.

The study table has one row per engine, ambient and HVAC setting; its columns (STUDY_COLUMNS)
take the baseline's or the hybrid's summary.json value. The saving is the sweep's
(twin_tools.sweep.table.add_savings: twin_tools.report.hybrid.saving, SOC-corrected, against the
conventional run with the same parameters) -- the same function the report applies with
--baseline for `twin bench hybrid`.
"""
import json
import os
import subprocess
import sys
import time

from twin_tools.paths import REPO
from twin_tools.sweep import table as sweep_table

SPEC = os.path.join(REPO, "config", "sweeps", "study.yaml")
AMBIENTS_C = (0, 25, 40)

# (key, header, format); "b:" takes the baseline's value, "h:" the hybrid's; a header None joins
# the cell to the previous column ("baseline / hybrid").
STUDY_COLUMNS = [("b:fuel_kg", "fuel baseline [kg]", "%.2f"), ("h:fuel_soc_corrected_kg", "hybrid, SOC-corr. [kg]", "%.2f"),
                 ("h:fuel_saving_pct", "saving [%]", "%.1f"),
                 ("b:coolant_warm_s", "70 °C baseline [s]", "%.0f"), ("h:coolant_warm_s", "70 °C hybrid [s]", "%.0f"),
                 ("h:engine_off_s", "engine off [s]", "%.0f"), ("h:engine_starts", "starts", "%d"),
                 ("b:heater_fuel_kg", "heater fuel b/h [kg]", "%.2f"), ("h:heater_fuel_kg", None, "%.2f"),
                 ("h:hvac_kwh", "HVAC hybrid [kWh]", "%.1f"),
                 ("b:nox_engine_out_g", "NOx eo b/h [g]", "%.0f"), ("h:nox_engine_out_g", None, "%.0f"),
                 ("b:nox_tailpipe_g", "NOx tp b/h [g]", "%.0f"), ("h:nox_tailpipe_g", None, "%.0f"),
                 ("h:scr_standstill_mean_c", "SCR at stops, hybrid [°C]", "%.0f")]


def cell(s, key, fmt):
    """A summary value formatted, "-" when the run failed or has no such key."""
    return (fmt % s[key]) if s and key in s and s[key] is not None else "-"


def study_table(results, engines, hvacs, ambients=AMBIENTS_C):
    """The study's table in Markdown lines: one row per engine, ambient and HVAC setting.
    results: {(engine, ambient, hvac, scenario): (run folder, summary dict or None)}."""
    heads = [head for _, head, _ in STUDY_COLUMNS if head is not None]
    lines = ["| engine | °C | HVAC | " + " | ".join(heads) + " |", "|---" * (3 + len(heads)) + "|"]
    for engine in engines:
        for hvac in hvacs:
            for amb in ambients:
                b = results[(engine, amb, hvac, "baseline_urban")][1]
                h = results[(engine, amb, hvac, "hybrid_urban")][1]
                cells = []
                for key, head, fmt in STUDY_COLUMNS:
                    who, k = key.split(":")
                    c = cell(b if who == "b" else h, k, fmt)
                    if head is None:
                        cells[-1] += " / " + c
                    else:
                        cells.append(c)
                lines.append("| %s | %d | %s | %s |" % (engine, amb, hvac or "default", " | ".join(cells)))
    return lines


def study_checks(results, full_mission=True):
    """The invariants every study run must meet: (description, ok) per check. The engine's
    restart (with either engine model) is checked on the full mission only."""
    checks = []
    for (engine, amb, hvac, scen), (_, s) in sorted(results.items()):
        name = "%s %s %d °C%s" % (scen, engine, amb, " hvac:=" + hvac if hvac else "")
        if not s:
            checks.append(("%s: ended ok" % name, False))
            continue
        checks.append(("%s: %s/%s stops served" % (name, s.get("stops_served"), s.get("stops_total")),
                       s.get("stops_served") == s.get("stops_total")))
        if scen == "hybrid_urban":
            if full_mission:
                checks.append(("%s: %s engine starts" % (name, s.get("engine_starts")), s.get("engine_starts", 0) > 0))
            checks.append(("%s: em_clamped_s %s, battery_limited_s %s" % (name, s.get("em_clamped_s"),
                                                                         s.get("battery_limited_s")),
                           s.get("em_clamped_s") == 0.0 and s.get("battery_limited_s") == 0.0))
    return checks


def fixed_arg(plan, name, default=""):
    """The value of a launch argument every run of the plan has (its `fixed` or a CLI name:=value)."""
    for a in plan["fixed_args"]:
        if a.startswith(name + ":="):
            return a.split(":=", 1)[1]
    return default


def study_results(plan):
    """The study's runs from a sweep's folder: {(engine, ambient, hvac, scenario): (run folder,
    summary or None for a failed run)}, each hybrid's summary with the sweep's fuel_saving_pct."""
    axes = [a["name"] for a in plan["axes"]]
    rows = [sweep_table.run_row(r) for r in plan["runs"]]
    sweep_table.add_savings(rows, axes)
    engine, hvac = fixed_arg(plan, "engine", "map"), fixed_arg(plan, "hvac", "on")
    results = {}
    for r, row in zip(plan["runs"], rows):
        s = None
        if row["status"] == "ok":
            s = dict(row["summary"])
            if row["fuel_saving_pct"] is not None:
                s["fuel_saving_pct"] = row["fuel_saving_pct"]
        results[(engine, int(r["values"]["ambient"]), hvac, r["scenario"])] = (r["dir"], s)
    return results, rows


def wall_line(plan, rows):
    """The sweep's wall time against the sum of its runs' (timing.json, sweep_task.json)."""
    try:
        with open(os.path.join(plan["out"], "timing.json")) as f:
            timing = json.load(f)
    except (OSError, ValueError):
        return "Wall time: not recorded (the sweep did not finish)."
    walls = [row["wall_s"] for row in rows if row["wall_s"] is not None]
    where = ("as Slurm job array %s" % timing["slurm_job"]) if timing.get("slurm_job") else "on this machine"
    return ("Wall time of the study: **%.1f s** (%.1f min) for %d runs, %d at a time %s; the runs' own wall "
            "times sum to %.1f s (%.1f–%.1f s each)." % (
                timing["wall_s"], timing["wall_s"] / 60.0, len(rows), timing["jobs"], where, sum(walls),
                min(walls) if walls else float("nan"), max(walls) if walls else float("nan")))


def study_lines(plan, until):
    """The study's Markdown: what ran, the wall time, the table, the checks; and whether all passed."""
    results, rows = study_results(plan)
    engine, hvac = fixed_arg(plan, "engine", "map"), fixed_arg(plan, "hvac", "on")
    ambients = sorted({k[1] for k in results})
    checks = study_checks(results, full_mission=not until)
    lines = ["VECTO Urban%s, cold start at the ambient, %s engine, hvac:=%s, nodelets, each scenario with its "
             "own group order; the sweep `%s` in `%s` (its table: sweep.md there). Saving = (baseline fuel - "
             "hybrid fuel corrected for the battery's energy change) / baseline fuel (twin_tools.report.hybrid)."
             % (" (first %g s)" % until if until else ", full mission", engine, hvac,
                os.path.relpath(plan["spec"], REPO), os.path.relpath(plan["out"], REPO)),
             "", wall_line(plan, rows), ""]
    lines += study_table(results, [engine], [hvac], ambients)
    lines += ["", "Checks:", ""] + ["- %s %s" % ("ok:" if ok else "FAILED:", what) for what, ok in checks] + [""]
    failed = [row["run"] for row in rows if row["status"] != "ok"]
    lines += ["Failed runs: %s (reasons in sweep.md)." % ", ".join(failed), ""] if failed else []
    return lines, not failed and all(ok for _, ok in checks)


def bench_study(a):
    """Runs the study's sweep (here or on Slurm) and writes its table; exit status 0 when every run
    ended ok and every check passed."""
    engine = a.engine
    out = os.path.join(REPO, "results", "bench", "study_%s" % engine)
    cmd = [sys.executable, "-m", "twin_tools.sweep.cli", SPEC, "--out", out, "--jobs", str(a.jobs or 2),
           "engine:=" + engine] + (["until:=%g" % a.until] if a.until else []) + (["--slurm"] if a.slurm else [])
    print("bench: the study: %s" % " ".join(os.path.relpath(c, REPO) if c.startswith(REPO) else c for c in cmd[1:]),
          flush=True)
    t0 = time.time()
    rc = subprocess.call(cmd)
    if rc == 2 or not os.path.exists(os.path.join(out, "plan.json")):
        print("bench: the study's sweep did not start (exit status %d)" % rc, file=sys.stderr)
        return 1
    with open(os.path.join(out, "plan.json")) as f:
        plan = json.load(f)
    lines, ok = study_lines(plan, a.until)
    print("\n" + "\n".join(lines) + "bench: study wall time %.1f s (sweep and table)" % (time.time() - t0))
    name = "study" if engine == "1d" else "study_%s" % engine
    a.measurement.write(name, "The ambient study: baseline against 48 V P1 hybrid, %s engine" % engine, lines,
                        bool(a.until))
    return 0 if ok else 1
