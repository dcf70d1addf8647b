"""One run of a sweep (a plain `scripts/twin run` into OUT/runs/<run-id>/) and the local pool
that runs N of them at a time under one progress line (twin_tools.sweep.cli).

Each run has its own ROS master on its own port: the port comes from a range below the kernel's
ephemeral ports (so no bind(0) of another program ever gets it), is locked for the whole run
with flock on /tmp/hbt_ros_ports/<port>.lock (so no other sweep run on this machine, of this
sweep or another, picks it) and must be free when the run starts; `twin run` uses it through
HBT_ROS_PORT. A run's own output goes to its folder (twin.log: twin's console; roslaunch.log:
every node); its exit code, wall time, host and (a Slurm task) job id and node name to
sweep_task.json, which the table reads.
"""
import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time

from twin_tools.launch.ports import reserve_port

TASK_FILE = "sweep_task.json"


def write_json(path, d):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(d, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)  # atomic: a reader (the Slurm progress line) never sees half a file


def run_task(plan, i, started=None):
    """Runs entry i of the plan with `twin run`; returns its exit code. started(proc) is called
    with the Popen (its own process group) once it runs."""
    r = plan["runs"][i]
    d = r["dir"]
    os.makedirs(d, exist_ok=True)
    task_file = os.path.join(d, TASK_FILE)
    if os.path.exists(task_file):
        os.remove(task_file)
    port, lock = reserve_port(i)
    t0 = time.time()
    try:
        env = dict(os.environ, HBT_ROS_PORT=str(port))
        cmd = [os.path.join(plan["repo"], "scripts", "twin"), "run", r["scenario"], "--out", d] + r["args"]
        with open(os.path.join(d, "twin.log"), "w") as log:
            log.write("sweep: %s\n" % " ".join(cmd))
            log.flush()
            p = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                 env=env, start_new_session=True)
            if started:
                started(p)
            rc = p.wait()
    finally:
        os.close(lock)
    write_json(task_file, {"rc": rc, "wall_s": time.time() - t0, "start_unix_s": t0, "port": port,
                           "host": socket.gethostname(), "slurm_job": os.environ.get("SLURM_ARRAY_JOB_ID"),
                           "slurm_node": os.environ.get("SLURMD_NODENAME")})
    return rc


def fmt_time(s):
    if s is None:
        return "?"
    s = int(round(s))
    return "%dh%02dm%02ds" % (s // 3600, s // 60 % 60, s % 60) if s >= 3600 else (
        "%dm%02ds" % (s // 60, s % 60) if s >= 60 else "%ds" % s)


def eta(n_waiting, running_ages, walls, slots):
    """Remaining wall time [s]: the mean duration of the finished runs for every waiting run and
    the rest of every running one, shared over `slots` runs at a time; None before any finished."""
    if not walls:
        return None
    mean = sum(walls) / len(walls)
    work = n_waiting * mean + sum(max(mean - a, 0.0) for a in running_ages)
    return work / max(1, slots)


def progress_line(label, n, done, failed, running, waiting, elapsed, eta_s):
    return "%s: %d/%d done%s, %d running, %d waiting | %s elapsed, ETA %s" % (
        label, done, n, (" (%d failed)" % failed) if failed else "", running, waiting,
        fmt_time(elapsed), fmt_time(eta_s) if (running or waiting) else "0s")


class Console:
    """One progress line, rewritten in place (\\r) on a terminal; on a pipe or file a new line
    only when the counts change (a log stays short)."""

    def __init__(self, stream=sys.stdout):
        self.stream, self.tty, self.last, self.width = stream, stream.isatty(), None, 0

    def show(self, line, counts):
        if self.tty:
            self.stream.write("\r" + line.ljust(self.width))
            self.width = len(line)
        elif counts != self.last:
            self.stream.write(line + "\n")
        self.last = counts
        self.stream.flush()

    def end(self, line, counts):
        self.last = None
        self.show(line, counts)
        if self.tty:
            self.stream.write("\n")
            self.stream.flush()


def run_local(plan, jobs, console=None):
    """Every run of the plan, `jobs` at a time; returns the number of failed runs."""
    console = console or Console()
    runs = plan["runs"]
    n = len(runs)
    state = ["waiting"] * n
    t_start, walls, procs, rcs = {}, [], {}, {}
    lock = threading.Lock()
    stop = threading.Event()
    queue = list(range(n))

    def worker():
        while not stop.is_set():
            with lock:
                if not queue:
                    return
                i = queue.pop(0)
                state[i] = "running"
                t_start[i] = time.time()
            try:
                rc = run_task(plan, i, started=lambda p, i=i: procs.__setitem__(i, p))
            except Exception as e:  # noqa: BLE001 (a run that could not start is a failed run)
                with open(os.path.join(runs[i]["dir"], "twin.log"), "a") as log:
                    log.write("sweep: the run could not start: %s\n" % e)
                rc = -1
            with lock:
                rcs[i] = rc
                state[i] = "ok" if rc == 0 else "failed"
                walls.append(time.time() - t_start[i])
                procs.pop(i, None)

    t0 = time.time()
    threads = [threading.Thread(target=worker, daemon=True) for _ in range(min(jobs, n))]
    for t in threads:
        t.start()

    def line():
        with lock:
            done = sum(s in ("ok", "failed") for s in state)
            failed = state.count("failed")
            running = [time.time() - t_start[i] for i in range(n) if state[i] == "running"]
            waiting = state.count("waiting")
            e = eta(waiting, running, walls, jobs)
        return (progress_line("sweep", n, done, failed, len(running), waiting, time.time() - t0, e),
                (done, failed, len(running)))

    try:
        while any(t.is_alive() for t in threads):
            console.show(*line())
            for t in threads:
                t.join(timeout=1.0 / len(threads))
    except KeyboardInterrupt:
        stop.set()
        with lock:
            for p in procs.values():  # roslaunch ends its nodes on SIGINT
                try:
                    os.killpg(p.pid, signal.SIGINT)
                except ProcessLookupError:
                    pass
        for t in threads:
            t.join()
        console.end(*line())
        raise
    console.end(*line())
    return sum(1 for rc in rcs.values() if rc != 0)
