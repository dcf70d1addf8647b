"""The comparison table and plots of a sweep, from its runs' folders (twin_tools.sweep.cli): one row
per run of OUT/plan.json with the varied parameters, ok/failed (+ the reason), and from the run's
summary.json (twin_tools.report.postprocess) fuel, L/100 km, NOx, final SOC, warnings; fuel_saving_pct
of a hybrid run against the conventional run with the same parameters (SOC-corrected,
twin_tools.report.hybrid); the run's wall time (sweep_task.json; for a Slurm array, sweep.md also
names the node that ran each run). Written as OUT/sweep.csv (full
precision), OUT/sweep.md and OUT/plots/<quantity>.png (each quantity against the first numeric
axis, one line per combination of the other parameters).
"""
import csv
import json
import math
import os
import re

from twin_tools.report import hybrid
from twin_tools.sweep import run as sweep_run

# (column, summary key, format in the Markdown table, unit/meaning)
QUANTITIES = [
    ("sim_time_s", "sim_time_s", "%.1f", "simulated time [s]"),
    ("distance_km", "distance_km", "%.3f", "distance [km]"),
    ("fuel_kg", "fuel_kg", "%.4f", "fuel [kg]"),
    ("fuel_l_per_100km", "fuel_l_per_100km", "%.2f", "fuel [L/100 km] (from 1 km on)"),
    ("nox_engine_out_g", "nox_engine_out_g", "%.2f", "engine-out NOx [g]"),
    ("nox_tailpipe_g", "nox_tailpipe_g", "%.3f", "tailpipe NOx [g]"),
    ("soc_final", "soc_final", "%.4f", "final battery SOC [-] (hybrid)"),
    ("fuel_saving_pct", None, "%.2f", "fuel saving vs the conventional run with the same parameters, SOC-corrected [%]"),
]
AXIS_UNITS = {"ambient": "ambient [°C]", "payload": "payload [kg]", "until": "until [s]", "step": "step [s]"}
PLOTTED = ["fuel_kg", "fuel_l_per_100km", "nox_tailpipe_g", "soc_final", "fuel_saving_pct"]


def _read(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def _last_twin_line(d):
    """The last message of `twin run` in the run's twin.log (why a run stopped before its bag)."""
    try:
        with open(os.path.join(d, "twin.log"), errors="replace") as f:
            lines = [l.strip() for l in f.read().replace("\r", "\n").split("\n")]
    except OSError:
        return None
    msgs = [l for l in lines if l.startswith(("twin:", "sweep:")) and not l.startswith("sweep: /")]
    bad = [l for l in msgs if "FAILED" in l or "unknown" in l or "argument" in l or "could not" in l
           or "without" in l or "failed" in l]
    return (bad or msgs or [None])[-1]


def run_row(r):
    """One run's row: dict of the plan's values, status, reason, summary quantities, wall time."""
    d = r["dir"]
    task = _read(os.path.join(d, sweep_run.TASK_FILE))
    status = _read(os.path.join(d, "status.json"))
    summary = _read(os.path.join(d, "summary.json"))
    row = {"run": r["id"], "scenario": r["scenario"], "values": r["values"], "summary": summary or {}}
    if task is None:
        slurm_log = os.path.join(os.path.dirname(os.path.dirname(d)), "slurm", "task_%d.out" % r["index"])
        row["status"], row["reason"] = "failed", "no result: the run did not run to its end (see %s)" % (
            os.path.join("slurm", os.path.basename(slurm_log)) if os.path.exists(slurm_log)
            else os.path.join("runs", r["id"], "twin.log"))
    elif task["rc"] == 0 and status and status.get("status") == "ok" and summary:
        row["status"], row["reason"] = "ok", ""
    else:
        row["status"] = "failed"
        if status and status.get("status") != "ok":
            row["reason"] = "%s: %s" % (status.get("status"), status.get("message", ""))
        else:
            row["reason"] = _last_twin_line(d) or "exit status %s" % task["rc"]
    row["reason"] = row["reason"].replace(os.path.dirname(os.path.dirname(d)) + os.sep, "")  # runs/<id>/...
    row["wall_s"] = task["wall_s"] if task else None
    row["node"] = task.get("slurm_node") if task else None
    return row


def architecture(row):
    return row["summary"].get("architecture") or row["values"].get("architecture") or (
        "p1_48v" if row["scenario"] == "hybrid_urban" else "conventional")


def add_savings(rows, axes):
    """fuel_saving_pct of each hybrid row against the conventional row with the same values of
    every axis but the scenario and the architecture."""
    same = [a for a in axes if a != "architecture"]
    key = lambda row: tuple(json.dumps(row["values"].get(a), sort_keys=True) for a in same)
    base = {}
    for row in rows:
        if row["status"] == "ok" and architecture(row) == "conventional":
            base.setdefault(key(row), row)
    for row in rows:
        row["fuel_saving_pct"] = None
        b = base.get(key(row))
        if row["status"] == "ok" and architecture(row) != "conventional" and b is not None:
            row["fuel_saving_pct"] = hybrid.saving(b["summary"], row["summary"])
            row["saving_against"] = b["run"]


def value(row, col):
    """A quantity of the row; of a failed run only the simulated time it reached (its other
    totals stop part-way and would mislead a comparison)."""
    if row["status"] != "ok" and col != "sim_time_s":
        return None
    if col == "fuel_saving_pct":
        return row.get("fuel_saving_pct")
    return row["summary"].get(col)


def columns(axes):
    return (["run", "scenario"] + axes + ["status", "reason"] + [q[0] for q in QUANTITIES]
            + ["warnings", "wall_s"])


def cell(row, col, axes, md):
    if col in ("run", "scenario", "status"):
        return row[col]
    if col == "reason":
        return row["reason"].replace("|", "/").replace("\n", " ") if md else row["reason"]
    if col in axes:
        v = row["values"].get(col)
        return json.dumps(v) if isinstance(v, (list, dict, bool)) else str(v)
    if col == "warnings":
        w = row["summary"].get("warnings")
        if w is None:
            return ""
        return str(len(w)) if md else json.dumps(w)
    if col == "wall_s":
        v = row["wall_s"]
        return "" if v is None else (("%.1f" % v) if md else repr(v))
    fmt = {q[0]: q[2] for q in QUANTITIES}[col]
    v = value(row, col)
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return ""
    return (fmt % v) if md else repr(v)


def write_csv(path, rows, axes):
    cols = columns(axes)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for row in rows:
            w.writerow([cell(row, c, axes, md=False) for c in cols])


def _numeric_axis(rows, axes):
    for a in axes:
        vals = {json.dumps(r["values"].get(a)) for r in rows}
        if len(vals) > 1 and all(isinstance(r["values"].get(a), (int, float)) and not isinstance(
                r["values"].get(a), bool) for r in rows):
            return a
    return None


def plots(out, rows, axes):
    """plots/<quantity>.png; returns the file names (relative to out)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    d = os.path.join(out, "plots")
    os.makedirs(d, exist_ok=True)
    x_axis = _numeric_axis(rows, axes)
    others = ["scenario"] + [a for a in axes if a != x_axis
                             and len({json.dumps(r["values"].get(a)) for r in rows}) > 1]
    label = {q[0]: q[3] for q in QUANTITIES}
    files = []
    for q in PLOTTED:
        pts = [(r, value(r, q)) for r in rows if r["status"] == "ok" and value(r, q) is not None]
        if not pts:
            continue
        fig, ax = plt.subplots(figsize=(7, 4))
        if x_axis:
            series = {}
            for r, v in pts:
                name = ", ".join("%s" % r["scenario"] if o == "scenario" else "%s=%s" % (
                    o.split("/")[-1], r["values"].get(o)) for o in others)
                series.setdefault(name, []).append((r["values"][x_axis], v))
            for name, xy in series.items():
                xy.sort()
                ax.plot([p[0] for p in xy], [p[1] for p in xy], "o-", label=name)
            ax.set_xlabel(AXIS_UNITS.get(x_axis, x_axis))
            ax.legend(fontsize=8)
        else:
            ax.bar(range(len(pts)), [v for _, v in pts])
            ax.set_xticks(range(len(pts)))
            ax.set_xticklabels([r["run"] for r, _ in pts], rotation=30, ha="right", fontsize=7)
        ax.set_ylabel(label[q])
        ax.set_title(label[q].split(" [")[0] + (" vs " + x_axis if x_axis else " per run"))
        ax.grid(alpha=0.3)
        fig.tight_layout()
        name = "%s.png" % q
        fig.savefig(os.path.join(d, name), dpi=100)
        plt.close(fig)
        files.append(os.path.join("plots", name))
    return files


def write_md(path, plan, rows, axes, timing, files):
    ok = sum(r["status"] == "ok" for r in rows)
    lines = ["# Sweep %s" % plan["name"], "",
             "Spec `%s`; %d runs (%d ok, %d failed)%s." % (
                 plan["spec"], len(rows), ok, len(rows) - ok,
                 "; fixed arguments: " + ", ".join("`%s`" % a for a in plan["fixed_args"]) if plan["fixed_args"] else ""),
             ""]
    walls = [r["wall_s"] for r in rows if r["wall_s"] is not None]
    if timing and walls:
        lines += ["Sweep wall time %.1f s (%s, %s); sum of the runs' wall times %.1f s: %.2fx." % (
            timing["wall_s"], "Slurm job array %s" % timing["slurm_job"] if timing.get("slurm_job")
            else "this machine", "%d at a time" % timing["jobs"], sum(walls), sum(walls) / timing["wall_s"]), ""]
    nodes = {}
    for r in rows:
        if r.get("node"):
            nodes.setdefault(r["node"], []).append(r["run"][:3])
    if nodes:  # a Slurm array: which compute node ran which run (sweep_task.json slurm_node)
        lines += ["Slurm nodes: " + "; ".join("%s ran %s" % (n, ", ".join(ids)) for n, ids in sorted(nodes.items())) + ".", ""]
    cols = columns(axes)
    lines.append("| " + " | ".join(cols) + " |")
    lines.append("|" + "---|" * len(cols))
    for row in rows:
        lines.append("| " + " | ".join(cell(row, c, axes, md=True) for c in cols) + " |")
    lines += ["", "Columns: " + "; ".join("`%s` %s" % (q[0], q[3]) for q in QUANTITIES)
              + "; `warnings` the number of entries of the run's summary.json `warnings`; `wall_s` the "
              "run's wall time (`twin run` from start to report) [s]. Each run's folder: `runs/<run>/` "
              "(report.md, summary.json, roslaunch.log, twin.log).", ""]
    for f in files:
        lines.append("![%s](%s)" % (os.path.basename(f), f))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def aggregate(plan, timing=None):
    """Writes OUT/sweep.csv, OUT/sweep.md, OUT/plots/; returns the rows."""
    axes = [a["name"] for a in plan["axes"]]
    rows = [run_row(r) for r in plan["runs"]]
    add_savings(rows, axes)
    out = plan["out"]
    write_csv(os.path.join(out, "sweep.csv"), rows, axes)
    files = plots(out, rows, axes)
    write_md(os.path.join(out, "sweep.md"), plan, rows, axes, timing, files)
    return rows
