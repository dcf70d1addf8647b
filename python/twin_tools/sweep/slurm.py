"""A sweep as a Slurm job array (`twin sweep --slurm`): task k = run k of OUT/plan.json, run
by `python3 -m twin_tools.sweep.cli task OUT/plan.json k` (the same code as a local run: `twin run` into
OUT/runs/<run-id>/ on its own ROS master), at most `jobs` tasks at a time (`--array=0-(N-1)%jobs`).
OUT and the repository must be visible at the same path on the compute nodes (a shared file
system). The sweep waits for the array to leave the queue (squeue polling, one progress line),
then the table is built exactly as for a local sweep. Ctrl-C cancels the array (scancel).
"""
import json
import os
import shlex
import subprocess
import sys
import time

from twin_tools.sweep import run as sweep_run


def script(plan, jobs, options):
    """Text of the sbatch script."""
    out, n = plan["out"], len(plan["runs"])
    lines = ["#!/bin/bash",
             "# hybrid_bus_twin sweep %s: %d runs (written by scripts/twin sweep --slurm)" % (plan["name"], n),
             "#SBATCH --job-name=hbt_sweep_%s" % plan["name"],
             "#SBATCH --array=0-%d%%%d" % (n - 1, jobs),
             "#SBATCH --output=%s" % os.path.join(out, "slurm", "task_%a.out"),
             "#SBATCH --chdir=%s" % plan["repo"],
             "#SBATCH --ntasks=1"]
    lines += ["#SBATCH --%s=%s" % kv for kv in sorted(options.items())]
    lines += ["set -eu",
              # the package from the repository itself: a compute node's shell has no devel space
              "export PYTHONPATH=%s${PYTHONPATH:+:$PYTHONPATH}" % shlex.quote(os.path.join(plan["repo"], "python")),
              "exec /usr/bin/python3 -m twin_tools.sweep.cli task %s \"$SLURM_ARRAY_TASK_ID\"" % (
                  shlex.quote(os.path.join(out, "plan.json")))]
    return "\n".join(lines) + "\n"


def _cmd(args):
    return subprocess.run(args, capture_output=True, text=True)


def submit(plan, jobs, options):
    """Writes OUT/slurm/sweep.sbatch and submits it; returns the job id."""
    d = os.path.join(plan["out"], "slurm")
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, "sweep.sbatch")
    with open(path, "w") as f:
        f.write(script(plan, jobs, options))
    r = _cmd(["sbatch", "--parsable", path])
    if r.returncode != 0:
        raise RuntimeError("sbatch %s failed: %s" % (path, (r.stderr or r.stdout).strip()))
    return r.stdout.strip().split(";")[0]


def queue_states(job):
    """{task index: Slurm state} of the array's tasks still in the queue; None once the job has
    left it (squeue no longer knows it)."""
    r = _cmd(["squeue", "-h", "-r", "-j", job, "-o", "%K %T"])
    if r.returncode != 0:
        if "Invalid job id" in r.stderr:
            return None
        raise RuntimeError(r.stderr.strip())
    states = {}
    for line in r.stdout.split("\n"):
        parts = line.split()
        if len(parts) == 2 and parts[0].isdigit():
            states[int(parts[0])] = parts[1]
    return states or None


def wait(plan, job, jobs, console=None, poll_s=2.0):
    """Polls the array until it has left the queue, with one progress line."""
    console = console or sweep_run.Console()
    n = len(plan["runs"])
    t0, seen_running = time.time(), {}
    errors = 0
    try:
        while True:
            try:
                states = queue_states(job)
                errors = 0
            except RuntimeError as e:  # the controller busy: try again, give up after a minute
                errors += 1
                if errors * poll_s > 60:
                    raise RuntimeError("squeue keeps failing: %s" % e)
                time.sleep(poll_s)
                continue
            results = [sweep_run_result(r) for r in plan["runs"]]
            done = sum(x is not None for x in results)
            failed = sum(1 for x in results if x is not None and x["rc"] != 0)
            walls = [x["wall_s"] for x in results if x is not None]
            now = time.time()
            running = [k for k, s in (states or {}).items() if s in ("RUNNING", "COMPLETING") and results[k] is None]
            for k in running:
                seen_running.setdefault(k, now)
            waiting = n - done - len(running)
            e = sweep_run.eta(waiting, [now - seen_running[k] for k in running], walls, jobs)
            line = sweep_run.progress_line("sweep (Slurm job %s)" % job, n, done, failed, len(running),
                                           waiting, now - t0, e)
            if states is None:
                console.end(line, (done, failed, len(running)))
                return
            console.show(line, (done, failed, len(running)))
            time.sleep(poll_s)
    except KeyboardInterrupt:
        _cmd(["scancel", job])
        print("\nsweep: cancelled Slurm job %s" % job, file=sys.stderr)
        raise


def sweep_run_result(r):
    p = os.path.join(r["dir"], sweep_run.TASK_FILE)
    try:
        with open(p) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def run_slurm(plan, jobs, options, console=None):
    """Submits the array, waits for its end; returns the job id."""
    for tool in ("sbatch", "squeue", "scancel"):
        if not any(os.access(os.path.join(p, tool), os.X_OK) for p in os.environ.get("PATH", "").split(os.pathsep)):
            raise RuntimeError("%s not found: Slurm's client commands are needed for --slurm "
                               "(Debian: apt-get install slurm-client)" % tool)
    job = submit(plan, jobs, options)
    print("sweep: submitted Slurm job array %s (%d tasks, script %s)" % (
        job, len(plan["runs"]), os.path.join(plan["out"], "slurm", "sweep.sbatch")), flush=True)
    wait(plan, job, jobs, console)
    # a shared file system may show a task's last file a moment after the job ended
    t0 = time.time()
    while time.time() - t0 < 10 and any(sweep_run_result(r) is None for r in plan["runs"]):
        time.sleep(1)
    return job
