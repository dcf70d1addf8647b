"""The one watcher outside the nodelet manager. In mode:=nodelets every participant, the stepper
and the recorder live in one process, so a manager stopped from outside (SIGSTOP, or a debugger's
stop: process state T or t) leaves nothing inside it able to notice. `twin run` starts this
watcher beside roslaunch:

  python3 -m twin_tools.launch.manager_watch watch OUT PORT ROSLAUNCH_PID [name:=value ...]
      (mode:=nodelets) polls the state of the manager of the run on master port PORT every
      POLL_S; once it has been stopped for the run's `timeout` (the launch argument, default from
      launch/include/urban.launch), writes OUT/manager_stopped.json, sends the manager SIGINT and
      SIGCONT (it shuts down as on Ctrl-C: the recorder closes the bag) and roslaunch SIGINT.
      Ends with roslaunch.
  python3 -m twin_tools.launch.manager_watch status OUT
      after roslaunch: OUT/status.json becomes "error" with a message naming the manager, how long
      it was stopped and the simulated time the run reached (from the status the stepper wrote on
      its shutdown, else from the bag or the progress line); prints the message.
mode:=nodes needs no watcher: each participant is a process the stepper watches, and the stepper
one the recorder watches."""
import json
import os
import signal
import sys
import time
import xml.etree.ElementTree as ET

from twin_tools.paths import REPO

POLL_S = 0.1  # [s] wall: how often the manager's state is read
STOPPED_STATES = ("T", "t")  # /proc/<pid>/stat: stopped by a signal, stopped by a tracer
MANAGER_NAME = "twin_manager"
RECORD = "manager_stopped.json"


def manager_pid(port):
    """The pid of the nodelet manager of the run on master port `port`, or None."""
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                cmd = f.read()
            if b"__name:=" + MANAGER_NAME.encode() not in cmd:
                continue
            with open("/proc/%s/environ" % pid, "rb") as f:
                env = f.read().split(b"\0")
        except OSError:
            continue
        # roslaunch hands its nodes the master's URI with a trailing slash
        if any(e.startswith(b"ROS_MASTER_URI=") and e.rstrip(b"/").endswith(b":%d" % port) for e in env):
            return int(pid)
    return None


def process_state(pid):
    """The one-letter state of process pid (R, S, D, T, t, Z, ...), or None once it is gone."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().rsplit(")", 1)[1].split()[0]  # the name in parentheses may hold spaces
    except (OSError, IndexError):
        return None


def launch_arg(args, name):
    """Launch argument `name` of a run: from its arguments name:=value, else urban.launch's default."""
    for a in args:
        if a.startswith(name + ":="):
            return a.split(":=", 1)[1]
    root = ET.parse(os.path.join(REPO, "launch", "include", "urban.launch")).getroot()
    return next(a.get("default") for a in root.iter("arg") if a.get("name") == name)


def alive(pid):
    try:
        os.kill(pid, 0)
        return True
    except ProcessLookupError:
        return False
    except PermissionError:
        return True


def watch(out, port, roslaunch_pid, timeout_s):
    manager, stopped_since = None, None
    while alive(roslaunch_pid):
        time.sleep(POLL_S)
        if manager is None:
            manager = manager_pid(port)
            continue
        state = process_state(manager)
        if state is None:
            return 0  # the manager ended: roslaunch reports it
        if state not in STOPPED_STATES:
            stopped_since = None
            continue
        now = time.time()
        stopped_since = stopped_since or now
        if now - stopped_since < timeout_s:
            continue
        with open(os.path.join(out, RECORD), "w") as f:
            json.dump({"pid": manager, "state": state, "stopped_s": now - stopped_since, "timeout_s": timeout_s}, f)
        for pid, sig in ((manager, signal.SIGINT), (manager, signal.SIGCONT), (roslaunch_pid, signal.SIGINT)):
            try:
                os.kill(pid, sig)
            except ProcessLookupError:
                pass
        return 0
    return 0


def rewrite_status(out):
    """status.json "error" naming the stopped manager; returns its message."""
    with open(os.path.join(out, RECORD)) as f:
        rec = json.load(f)
    path = os.path.join(out, "status.json")
    try:
        with open(path) as f:
            st = json.load(f)
    except (OSError, ValueError):
        from twin_tools.launch import lost_status
        st = lost_status.lost_status(out, interrupted=True)
    how = "SIGSTOP" if rec["state"] == "T" else "a tracer"
    st["status"] = "error"
    st["message"] = ("the nodelet manager %s (pid %d), which holds every participant, the stepper and the recorder, "
                     "was stopped from outside (%s: process state %s) for %.1f s, the run's timeout (%g s): nothing "
                     "in it could step or report. twin ended the run at t = %g s; the recorder closed the bag"
                     % (MANAGER_NAME, rec["pid"], how, rec["state"], rec["stopped_s"], rec["timeout_s"],
                        st.get("sim_time_s", 0.0)))
    with open(path + ".tmp", "w") as f:
        json.dump(st, f, indent=2)
        f.write("\n")
    os.replace(path + ".tmp", path)
    return st["message"]


def main(argv):
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C on twin run is roslaunch's to handle
    if len(argv) >= 4 and argv[0] == "watch":
        out, port, rl_pid, args = argv[1], int(argv[2]), int(argv[3]), argv[4:]
        if launch_arg(args, "mode") != "nodelets":
            return 0  # no manager
        return watch(out, port, rl_pid, float(launch_arg(args, "timeout")))
    if len(argv) == 2 and argv[0] == "status":
        print(rewrite_status(argv[1]))
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
