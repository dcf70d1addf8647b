"""status.json for a run whose stepper could not write it (the stepper itself killed, the manager
that hosts it crashed while shutting down): what roslaunch.log says ended the run. Usage:
    python3 -m twin_tools.launch.lost_status OUT [--interrupted]
                                          (writes OUT/status.json, prints its message)
The status is "error", the message names the process that died and how (exit code, signal); with
--interrupted (twin run stopped by Ctrl-C or SIGTERM) it is "interrupted", as the stepper writes
it. sim_time_s: the last state of run.bag where it is readable, else the stepper's last progress
line (0 if none)."""
import json
import os
import re
import signal
import sys

DIED = re.compile(r"process has died \[pid (\d+), exit code (-?\d+), cmd (\S+)[^\]]*?__name:=(\S+)")
PROGRESS = re.compile(r"t = +([0-9.]+) s")


def describe_exit(code):
    if code < 0:
        try:
            return "killed by %s" % signal.Signals(-code).name
        except ValueError:
            return "killed by signal %d" % -code
    return "exit code %d" % code


def last_bag_time(out):
    """The last header stamp of /vehicle/state in OUT/run.bag [s], or None where unreadable."""
    try:
        import rosbag
        last = None
        with rosbag.Bag(os.path.join(out, "run.bag")) as b:
            for _, m, _ in b.read_messages(topics=["/vehicle/state"]):
                last = m.header.stamp.to_sec()
        return last
    except Exception:  # no bag, cut short, no ROS on the path: the progress line instead
        return None


def lost_status(out, interrupted=False):
    log = os.path.join(out, "roslaunch.log")
    text = ""
    if os.path.exists(log):
        with open(log, errors="replace") as f:
            text = f.read()
    died = [(m.group(4), int(m.group(2))) for m in DIED.finditer(text)]
    times = [float(t) for t in PROGRESS.findall(text)]
    t_bag = last_bag_time(out)
    t_s = t_bag if t_bag is not None else (max(times) if times else 0.0)
    if interrupted:
        return {"status": "interrupted", "message": "interrupted at t = %g s (the run was stopped from outside: "
                "SIGINT/SIGTERM; status recorded by twin)" % t_s, "sim_time_s": t_s, "wall_time_s": 0.0,
                "steps": 0, "macro_step_s": 0.0, "compute_time_s": {}, "process_cpu_s": {}}
    if died:
        name, code = died[0]
        message = ("%s died (%s) before the run's end, and the stepper wrote no status: see %s"
                   % (name, describe_exit(code), log))
    else:
        message = "the run ended without a status from the stepper and no process death in %s" % log
    return {"status": "error", "message": message, "sim_time_s": t_s,
            "wall_time_s": 0.0, "steps": 0, "macro_step_s": 0.0, "compute_time_s": {}, "process_cpu_s": {}}


def main():
    if len(sys.argv) not in (2, 3) or (len(sys.argv) == 3 and sys.argv[2] != "--interrupted"):
        sys.exit(__doc__)
    st = lost_status(sys.argv[1], interrupted=len(sys.argv) == 3)
    reserve = os.path.join(sys.argv[1], "status.json.reserve")  # the stepper's, left by its death
    if os.path.exists(reserve):
        os.remove(reserve)
    with open(os.path.join(sys.argv[1], "status.json"), "w") as f:
        json.dump(st, f, indent=2)
        f.write("\n")
    print(st["message"])


if __name__ == "__main__":
    main()
