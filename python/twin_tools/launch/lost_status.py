"""status.json for a run whose stepper could not write it (the stepper itself killed, the manager
that hosts it crashed): what roslaunch.log says ended the run. Usage:
    python3 -m twin_tools.launch.lost_status OUT     (writes OUT/status.json, prints its message)
The status is "error"; the message names the process that died and how (exit code, signal), and
sim_time_s is the last simulated time of the stepper's progress line (0 if none)."""
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


def lost_status(out):
    log = os.path.join(out, "roslaunch.log")
    text = open(log, errors="replace").read() if os.path.exists(log) else ""
    died = [(m.group(4), int(m.group(2))) for m in DIED.finditer(text)]
    times = [float(t) for t in PROGRESS.findall(text)]
    if died:
        name, code = died[0]
        message = ("%s died (%s) before the run's end, and the stepper wrote no status: see %s"
                   % (name, describe_exit(code), log))
    else:
        message = "the run ended without a status from the stepper and no process death in %s" % log
    return {"status": "error", "message": message, "sim_time_s": max(times) if times else 0.0,
            "wall_time_s": 0.0, "steps": 0, "macro_step_s": 0.0, "compute_time_s": {}, "process_cpu_s": {}}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    st = lost_status(sys.argv[1])
    reserve = os.path.join(sys.argv[1], "status.json.reserve")  # the stepper's, left by its death
    if os.path.exists(reserve):
        os.remove(reserve)
    with open(os.path.join(sys.argv[1], "status.json"), "w") as f:
        json.dump(st, f, indent=2)
        f.write("\n")
    print(st["message"])


if __name__ == "__main__":
    main()
