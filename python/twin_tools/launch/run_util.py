"""Helpers for the ROS-level tests: run a launch file in its own roslaunch (own master on a free
port), read the status file and bags written by a run."""
import json
import os
import signal
import subprocess
import time
from twin_tools import wiring
from twin_tools.launch import ports

# topics (twin_tools.wiring: the participants' topics.yaml)
ENGINE_STATE = wiring.topic("engine", "state")
VEHICLE_ENGINE_COMMAND = wiring.topic("vehicle", "engine_command")
# The topics a baseline_urban run records at every stamp (conventional, thermal, hvac:=on).
BASELINE_TOPICS = tuple(wiring.topic(p, k) for p, k in (
    ("vehicle", "state"), ("vehicle", "engine_command"), ("vehicle", "to_cooling"),
    ("engine", "state"), ("engine", "exhaust"), ("engine", "heat"),
    ("aftertreatment", "state"), ("cooling", "state"), ("hvac", "state")))


def start_launch(launch_file, out_dir, env=None, **args):
    """Starts roslaunch on a private master; returns the Popen (its own process group). `env`:
    variables added to the environment of roslaunch and its nodes. The master's port is reserved
    (twin_tools.launch.ports: not one roslaunch's own XML-RPC server can take) for as long as the
    Popen lives (its `port_lock`)."""
    os.makedirs(out_dir, exist_ok=True)
    port, lock = ports.reserve_port(os.getpid() % (ports.PORT_HI - ports.PORT_LO))
    env = dict(os.environ, **(env or {}), ROS_MASTER_URI="http://127.0.0.1:%d" % port, ROS_HOME=out_dir)
    cmd = ["roslaunch", "--no-summary", "-p", str(port), launch_file, "out:=" + out_dir]
    cmd += ["%s:=%s" % (k, v) for k, v in args.items()]
    with open(os.path.join(out_dir, "roslaunch.log"), "w") as log:
        proc = subprocess.Popen(cmd, env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    proc.port_lock = lock
    return proc


def release_port(proc):
    """Frees the master port a finished launch held (start_launch)."""
    lock = getattr(proc, "port_lock", None)
    if lock is not None:
        os.close(lock)
        proc.port_lock = None


def stop(proc):
    """Ends a launched run (and its nodes) if it is still going, and frees its port: for test
    clean-up."""
    if proc.poll() is None:
        try:
            os.killpg(proc.pid, signal.SIGINT)
            proc.wait(timeout=20)
        except (ProcessLookupError, subprocess.TimeoutExpired):
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait(timeout=20)
    release_port(proc)


def wait(proc, timeout_s):
    try:
        return proc.wait(timeout=timeout_s)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGINT)
        proc.wait(timeout=20)
        raise


def run_launch(launch_file, out_dir, timeout_s=300, **args):
    """Runs a launch file to its end; returns its status.json. A run that did not end "ok" prints
    the end of its roslaunch.log (to stderr, for the test log: why a node did not answer)."""
    import sys
    proc = start_launch(launch_file, out_dir, **args)
    try:
        wait(proc, timeout_s)
    finally:
        release_port(proc)
    st = read_status(out_dir)
    if st.get("status") != "ok":
        with open(os.path.join(out_dir, "roslaunch.log"), errors="replace") as f:
            tail = f.readlines()[-40:]
        sys.stderr.write("run_launch %s %s: %s\n--- end of %s/roslaunch.log ---\n%s---\n" % (
            os.path.basename(launch_file), args, st.get("message"), out_dir, "".join(tail)))
    return st


def wait_until_stepping(out_dir, proc, after_s, timeout_s=120.0):
    """Until the stepper's progress line in out_dir/roslaunch.log is past after_s of simulated
    time (the run is stepping); AssertionError if `proc` ends first or the timeout passes."""
    from twin_tools.launch.lost_status import PROGRESS
    log = os.path.join(out_dir, "roslaunch.log")
    t0 = time.time()
    while time.time() - t0 < timeout_s:
        if proc.poll() is not None:
            raise AssertionError("the run ended (rc %s) before it stepped past %.0f s" % (proc.returncode, after_s))
        if os.path.exists(log):
            with open(log, errors="replace") as f:
                if any(float(t) > after_s for t in PROGRESS.findall(f.read())):
                    return
        time.sleep(0.1)
    raise AssertionError("the run did not step past %.0f s within %.0f s" % (after_s, timeout_s))


def read_status(out_dir):
    with open(os.path.join(out_dir, "status.json")) as f:
        return json.load(f)


def bag_messages(bag_path):
    """[(topic, stamp_ns, serialized bytes)] in bag order."""
    import rosbag
    out = []
    with rosbag.Bag(bag_path) as bag:
        for topic, raw, t in bag.read_messages(raw=True):
            out.append((topic, t.to_nsec(), bytes(raw[1])))
    return out


def pid_of_node(proc, name, timeout_s=30.0):
    """PID of the process started with __name:=<name> by the roslaunch `proc` (its direct
    child: other runs on the machine are never touched)."""
    t0 = time.time()
    while time.time() - t0 < timeout_s:
        r = subprocess.run(["pgrep", "-P", str(proc.pid), "-f", "__name:=%s( |$)" % name],
                           capture_output=True, text=True)
        pids = [int(p) for p in r.stdout.split()]
        if pids:
            return pids[0]
        time.sleep(0.1)
    raise RuntimeError("node %s not found" % name)


CHAINS = ("[[vehicle], [engine], [aftertreatment, cooling, hvac]]",
          "[[vehicle], [engine], [aftertreatment], [cooling, hvac]]")


def chain_length_check(launch_file, tmp, until, **args):
    """The baseline with the torque chain vehicle -> engine and the thermal nodes after it, in
    one group and in two (a chain of 3 or 4 groups, the same data dependencies): returns
    (bag messages of the two runs without /twin/run_info, statuses, number of stamps at which
    the engine's state used the speed the vehicle commanded for that very step -- no macro-step
    delay -- and number of stamps compared)."""
    import rosbag
    bags, statuses = [], []
    for i, order in enumerate(CHAINS):
        out = os.path.join(tmp, "chain%d" % i)
        statuses.append(run_launch(launch_file, out, until=until, record_period=0, order=order,
                                   timeout=20.0, **args))
        bags.append([m for m in bag_messages(os.path.join(out, "run.bag")) if m[0] != "/twin/run_info"])
    eng, cmd = {}, {}
    with rosbag.Bag(os.path.join(tmp, "chain1", "run.bag")) as b:
        for topic, m, _ in b.read_messages(topics=[ENGINE_STATE, VEHICLE_ENGINE_COMMAND]):
            (eng if topic == ENGINE_STATE else cmd)[m.header.stamp.to_nsec()] = m
    same = sum(1 for t, e in eng.items() if t > 0 and e.engine_speed_rad_s == cmd[t].engine_speed_rad_s)
    return bags, statuses, same, sum(1 for t in eng if t > 0)


def assert_chain_length(tc, launch_file, tmp, until, n_steps, **args):
    """chain_length_check's assertions for a unittest.TestCase tc: both runs ok, n_steps stamps,
    the engine on the commanded speed of its own stamp at every one, the two bags equal."""
    bags, sts, same, n = chain_length_check(launch_file, tmp, until, **args)
    for st in sts:
        tc.assertEqual(st["status"], "ok", st)
    tc.assertEqual(n, n_steps)
    tc.assertEqual(same, n)
    tc.assertEqual(bags[0], bags[1])


SKIP = 77  # ctest SKIP_RETURN_CODE of the ROS tests (CMakeLists.txt hbt_add_ros_test)


def unittest_main(**kwargs):
    """unittest.main for a ROS test whose tools may be missing: exits SKIP (ctest: "Not Run",
    skipped) when every test was skipped -- a whole class skipped in setUpClass included -- so a
    test that could not run never reports "Passed"; 0 or 1 otherwise."""
    import sys
    import unittest
    prog = unittest.main(exit=False, **kwargs)
    r = prog.result
    if not r.wasSuccessful():
        sys.exit(1)
    if r.skipped and len(r.skipped) >= r.testsRun:
        print("SKIPPED: %s" % "; ".join(sorted(set(why for _, why in r.skipped))))
        sys.exit(SKIP)
    sys.exit(0)
