"""Parameter sweeps of the twin: a matrix of scenarios (scripts/twin sweep).

  twin sweep SPEC.yaml [--out DIR] [--jobs N] [--slurm] [name:=value ...]
      checks the whole spec (twin_tools.sweep.spec), writes DIR/plan.json and every run's config
      copy, runs each entry with `twin run` into DIR/runs/<run-id>/ (its own ROS master and port),
      N at a time on this machine under one progress line, or with --slurm as a Slurm job array
      (twin_tools.sweep.slurm); then DIR/sweep.csv, DIR/sweep.md and DIR/plots/ (twin_tools.sweep.table).
      name:=value: launch arguments for every run (override the spec's `fixed`), e.g. until:=300.
  python3 -m twin_tools.sweep.cli --check SPEC.yaml [...]   only the checks (scripts/twin sweep
                                     runs them before setup)
  python3 -m twin_tools.sweep.cli task PLAN.json INDEX      one run of a plan (what each Slurm
                                     array task runs)
  python3 -m twin_tools.sweep.cli table DIR                 the table and plots again from
                                     DIR/plan.json and the runs
Exit status: 0 every run ok, 1 a run failed (the table says which and why), 2 a bad spec or
command line (nothing started).
"""
import argparse
import json
import os
import shutil
import sys
import time

from twin_tools.paths import REPO
from twin_tools.sweep import config_edit as sweep_yaml
from twin_tools.sweep import run as sweep_run
from twin_tools.sweep import spec as sweep_spec
from twin_tools.sweep import table as sweep_table

SWEEP_FILES = ("plan.json", "sweep.csv", "sweep.md", "timing.json")
SWEEP_DIRS = ("runs", "plots", "slurm")


def fail(msg):
    print("sweep: " + msg.replace("\n", "\nsweep: "), file=sys.stderr)
    sys.exit(2)


def make_plan(spec, out):
    name = os.path.splitext(os.path.basename(spec.path))[0]
    return {"name": name, "spec": spec.path, "repo": REPO, "out": out,
            "fixed_args": ["%s:=%s" % kv for kv in spec.fixed.items()],
            "axes": [{"name": a[0], "kind": a[1], "values": a[2]} for a in spec.axes],
            "jobs": spec.jobs, "slurm": spec.slurm, "runs": spec.runs(out)}


def clear_out(out):
    """An existing folder may be reused only if it holds an earlier sweep (its plan.json)."""
    if os.path.isdir(out) and os.listdir(out):
        if not os.path.exists(os.path.join(out, "plan.json")):
            fail("%s exists and is not a sweep's folder (no plan.json): choose another --out" % out)
        for f in SWEEP_FILES:
            if os.path.exists(os.path.join(out, f)):
                os.remove(os.path.join(out, f))
        for d in SWEEP_DIRS:
            shutil.rmtree(os.path.join(out, d), ignore_errors=True)


def prepare_config(run):
    """The run's copy of its config folder (data/ linked, not copied) with the spec's keys set."""
    if not run["edits"]:
        return
    base, dst = run["base_config"], os.path.join(run["dir"], "config")
    shutil.copytree(base, dst, symlinks=True, ignore=shutil.ignore_patterns("data", "sweeps"))
    if os.path.exists(os.path.join(base, "data")):
        os.symlink(os.path.realpath(os.path.join(base, "data")), os.path.join(dst, "data"))
    for fname, key, value in run["edits"]:
        p = os.path.join(dst, fname)
        with open(p) as f:
            text = f.read()
        new, _, _ = sweep_yaml.set_key(text, key, value)  # checked with the spec: cannot fail here
        with open(p, "w") as f:
            f.write(new)


def main_sweep(argv):
    ap = argparse.ArgumentParser(prog="twin sweep", description=__doc__.split("\n")[0])
    ap.add_argument("spec")
    ap.add_argument("--out", help="results folder (default: the spec's out, else results/sweeps/<spec name>)")
    ap.add_argument("--jobs", type=int, help="runs at a time (default: the spec's jobs, else 2)")
    ap.add_argument("--slurm", action="store_true", help="run as a Slurm job array (sbatch)")
    ap.add_argument("--check", action="store_true", help="only check the spec")
    ap.add_argument("args", nargs="*", help="name:=value launch arguments for every run")
    a = ap.parse_intermixed_args(argv)
    out = os.path.abspath(a.out) if a.out else None
    try:
        spec = sweep_spec.Spec(a.spec, REPO, a.args, jobs=a.jobs, out=out)
    except sweep_spec.SpecError as e:
        fail(str(e))
    out = spec.out or os.path.join(REPO, "results", "sweeps", os.path.splitext(os.path.basename(a.spec))[0])
    out = os.path.abspath(out)
    plan = make_plan(spec, out)
    if a.check:
        print("sweep: %s: %d runs, checked" % (a.spec, len(plan["runs"])))
        return 0
    clear_out(out)
    os.makedirs(os.path.join(out, "runs"), exist_ok=True)
    for r in plan["runs"]:
        os.makedirs(r["dir"], exist_ok=True)
        prepare_config(r)
    with open(os.path.join(out, "plan.json"), "w") as f:
        json.dump(plan, f, indent=1)
        f.write("\n")
    n = len(plan["runs"])
    print("sweep: %d runs of %s -> %s (%s)" % (
        n, a.spec, out, "Slurm job array, %d at a time" % spec.jobs if a.slurm else "%d at a time" % spec.jobs),
        flush=True)
    t0 = time.time()
    timing = {"jobs": spec.jobs, "slurm_job": None}
    if a.slurm:
        from twin_tools.sweep import slurm as sweep_slurm
        try:
            timing["slurm_job"] = sweep_slurm.run_slurm(plan, spec.jobs, spec.slurm)
        except RuntimeError as e:
            fail(str(e))
    else:
        sweep_run.run_local(plan, spec.jobs)
    timing["wall_s"] = time.time() - t0
    with open(os.path.join(out, "timing.json"), "w") as f:
        json.dump(timing, f, indent=1)
    return report(plan, timing)


def report(plan, timing):
    rows = sweep_table.aggregate(plan, timing)
    failed = [r for r in rows if r["status"] != "ok"]
    for r in failed:
        print("sweep: run %s FAILED: %s" % (r["run"], r["reason"]), file=sys.stderr)
    print("sweep: %d/%d runs ok; table %s (and sweep.csv), plots in %s" % (
        len(rows) - len(failed), len(rows), os.path.join(plan["out"], "sweep.md"), os.path.join(plan["out"], "plots")))
    return 1 if failed else 0


def main(argv):
    if argv[:1] == ["task"]:
        if len(argv) != 3 or not argv[2].isdigit():
            fail("usage: python3 -m twin_tools.sweep.cli task PLAN.json INDEX")
        with open(argv[1]) as f:
            plan = json.load(f)
        i = int(argv[2])
        if i >= len(plan["runs"]):
            fail("task %d: the plan has %d runs" % (i, len(plan["runs"])))
        rc = sweep_run.run_task(plan, i)
        print("sweep: run %s ended with exit status %d" % (plan["runs"][i]["id"], rc))
        return 0 if rc == 0 else 1
    if argv[:1] == ["table"]:
        if len(argv) != 2:
            fail("usage: python3 -m twin_tools.sweep.cli table DIR")
        p = os.path.join(argv[1], "plan.json")
        if not os.path.exists(p):
            fail("%s: no plan.json (not a sweep's folder)" % argv[1])
        with open(p) as f:
            plan = json.load(f)
        timing = None
        if os.path.exists(os.path.join(argv[1], "timing.json")):
            with open(os.path.join(argv[1], "timing.json")) as f:
                timing = json.load(f)
        return report(plan, timing)
    return main_sweep(argv)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
