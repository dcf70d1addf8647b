#!/usr/bin/python3
"""Fault injection, every participant: hybrid_urban in nodes mode (one process each), each of the
participants (twin_tools.wiring) and the recorder killed (SIGKILL) and hung (SIGSTOP) once it is stepping, and
the stepper killed and hung. The run stops within 2 s of the kill (the step timeout, 1 s) or at the timeout
of the hang, status.json "error" names the node (as one that did not answer: "node died or hung"),
and run.bag is closed and readable (the recorder killed: cut short, readable after
`rosbag reindex`). The stepper killed: roslaunch stops the run (the stepper is required) and the
status twin writes then (twin_tools.launch.lost_status) names it and the signal. The stepper
hung: every participant misses its heartbeat for 2 timeouts; the recorder closes the bag, writes
the status naming the stepper and ends it. The whole nodelet manager stopped (SIGSTOP; every
participant, the stepper and the recorder inside it) under `twin run`: its watcher ends the run at
the timeout, status.json "error" names the manager, and the bag is closed; the manager killed
(SIGKILL): roslaunch stops the run and twin's status names it and the signal.
Faults of a model (a step that throws or yields NaN) are tested per model (their ModelDivergence
and InputError tests) and for the protocol in test/cosim; this test covers the processes."""
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest
from concurrent.futures import ThreadPoolExecutor

from twin_tools import wiring
from twin_tools.launch import lost_status, manager_watch, ports, run_util
from twin_tools.paths import REPO

LAUNCH = os.path.join(REPO, "launch", "hybrid_urban.launch")
TWIN = os.path.join(REPO, "scripts", "twin")
PARTICIPANTS = wiring.participants() + ("recorder",)  # every participant of hybrid_urban, and the recorder
TIMEOUT_S = 1.0
MODEL_FAULT_AT_S = 3.0  # [s] simulated: when a model's step fails
MODEL_FAULT_JOBS = 4    # runs at a time
DEVEL_LIB = os.path.join(REPO, "build", "devel", "lib")  # scripts/twin builds into <repo>/build
FAULT_NODELETS = os.path.join(REPO, "build", "fault_lib", "libhbt_nodelets.so")
# what each participant's NaN shows as: its output topic and field (test/faults/fault_hooks.cpp)
NAN_OUTPUT = {"battery": "/battery/state: soc = nan", "aftertreatment": "/aftertreatment/state: outlet_temperature_k = nan",
              "cooling": "/cooling/state: coolant_ht_temperature_k = nan",
              "hvac": "/hvac/state: cabin_temperature_k = nan", "emachine": "/emachine/state: torque_nm = nan",
              "ems": ": engine_torque_request_nm = nan", "vehicle": ": engine_speed_rad_s = nan",
              "engine": "/engine/state: fuel_mass_flow_kg_s = nan"}


def inject(tmp, name, sig, after_s=20.0):
    """Starts the run, waits until it is stepping (past after_s of simulated time), sends `sig` to
    node `name`; returns (out, status or None, seconds from the signal to the status file, the
    roslaunch's exit)."""
    out = os.path.join(tmp, "%s_%s" % (name, signal.Signals(sig).name))
    proc = run_util.start_launch(LAUNCH, out, until=0, mode="nodes", timeout=TIMEOUT_S)
    try:
        pid = run_util.pid_of_node(proc, name)
        run_util.wait_until_stepping(out, proc, after_s)
        t_sig = time.time()
        os.kill(pid, sig)
        path = os.path.join(out, "status.json")
        while proc.poll() is None and not (os.path.exists(path) and os.path.getsize(path) > 0):
            time.sleep(0.05)
        if sig == signal.SIGSTOP:  # on record: end the hung process now (roslaunch would wait 15 s)
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:  # the hung stepper: the recorder ended it already
                pass
        rc = run_util.wait(proc, 90)
        if not os.path.exists(path):
            return out, None, None, rc
        return out, run_util.read_status(out), os.path.getmtime(path) - t_sig, rc
    finally:
        run_util.stop(proc)


def fault_overlay(tmp, name):
    """A catkin workspace prefix put first on CMAKE_PREFIX_PATH, whose lib/ holds the test builds of
    test/faults: lib/hybrid_bus_twin/ the package's executables with <name>_node replaced by
    <name>_fault_node (roslaunch takes a node's executable from the first workspace that has the
    package), lib/libhbt_nodelets.so the nodelets with every hook (pluginlib tries each prefix's
    lib/ in turn). Returns the environment."""
    ws = os.path.join(tmp, "overlay_" + name)
    lib = os.path.join(ws, "lib", "hybrid_bus_twin")
    if not os.path.isdir(lib):
        os.makedirs(lib)
        open(os.path.join(ws, ".catkin"), "w").close()
        real = os.path.join(DEVEL_LIB, "hybrid_bus_twin")
        for f in os.listdir(real):
            os.symlink(os.path.join(real, f), os.path.join(lib, f))
        os.remove(os.path.join(lib, name + "_node"))
        os.symlink(os.path.join(real, name + "_fault_node"), os.path.join(lib, name + "_node"))
        os.symlink(FAULT_NODELETS, os.path.join(ws, "lib", "libhbt_nodelets.so"))
    return {"CMAKE_PREFIX_PATH": ws + os.pathsep + os.environ.get("CMAKE_PREFIX_PATH", "")}


def model_fault(tmp, name, kind, mode, at_s=MODEL_FAULT_AT_S):
    """hybrid_urban with participant `name`'s model step failing (kind "throw" or "nan") at
    simulated time at_s; returns (out, status, the roslaunch's exit)."""
    out = os.path.join(tmp, "%s_%s_%s" % (name, kind, mode))
    env = dict(fault_overlay(tmp, name), HBT_FAULT_PARTICIPANT=name, HBT_FAULT=kind, HBT_FAULT_AT_S=str(at_s))
    proc = run_util.start_launch(LAUNCH, out, env=env, until=0, mode=mode, timeout=TIMEOUT_S)
    try:
        rc = run_util.wait(proc, 120)
        return out, run_util.read_status(out), rc
    finally:
        run_util.stop(proc)


def readable(tc, out, name, min_states=100):
    import rosbag
    bag = os.path.join(out, "run.bag")
    try:
        rosbag.Bag(bag).close()
    except rosbag.ROSBagUnindexedException:  # the writer itself killed: its last chunk is lost
        tc.assertEqual(name, "recorder", "only the recorder's own death cuts its bag short")
        r = subprocess.run(["rosbag", "reindex", bag], capture_output=True, text=True, cwd=out)
        tc.assertEqual(r.returncode, 0, r.stderr)
    n = 0
    with rosbag.Bag(bag) as b:
        for _ in b.read_messages(topics=["/vehicle/state"]):
            n += 1
    tc.assertGreater(n, min_states, (name, out))  # the vehicle's states of the stretch that ran


class Faults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_faults_")
        cls.table = []

    @classmethod
    def tearDownClass(cls):
        for name, fault, message, delay in cls.table:  # delay: from the signal to the status file
            print("| %s | %s | %s | %s |" % (name, fault, message, "at the step" if delay is None else "%.2f s" % delay))
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def check(self, name, sig, limit_s, result):
        out, st, delay, _ = result
        self.assertIsNotNone(st, (name, "no status.json"))
        self.assertEqual(st["status"], "error", (name, st))
        self.assertIn("%s (done through t = " % name, st["message"], (name, st["message"]))
        self.assertIn("node died or hung", st["message"])
        self.assertLess(delay, limit_s, (name, delay))
        readable(self, out, name)
        self.table.append((name, signal.Signals(sig).name, st["message"][:90], delay))

    def test_each_participant_killed_and_hung(self):
        # three runs at a time (the delays are measured from each run's own signal)
        cases = [(name, sig) for sig in (signal.SIGKILL, signal.SIGSTOP) for name in PARTICIPANTS]

        def one(case):
            name, sig = case
            # the recorder: late enough that its bag holds whole chunks (rosbag writes 768 KiB chunks)
            return case, inject(self.tmp, name, sig, after_s=200.0 if name == "recorder" else 10.0)
        with ThreadPoolExecutor(3) as pool:
            results = dict(pool.map(one, cases))
        for name, sig in cases:
            with self.subTest(name=name, signal=signal.Signals(sig).name):
                self.check(name, sig, 2.0 if sig == signal.SIGKILL else TIMEOUT_S + 2.0, results[(name, sig)])

    def test_stepper_killed(self):
        out, st, _, _ = inject(self.tmp, "stepper", signal.SIGKILL)
        self.assertIsNone(st, "a killed stepper writes nothing")
        lost = lost_status.lost_status(out)
        self.assertEqual(lost["status"], "error")
        self.assertIn("stepper died (killed by SIGKILL) before the run's end", lost["message"])
        self.assertGreater(lost["sim_time_s"], 10.0)
        readable(self, out, "stepper")

    def model_faults(self, cases):
        """Runs the (name, kind, mode) cases MODEL_FAULT_JOBS at a time (their checks do not time
        anything); returns {case: (out, status, exit, seconds from the start to the end)}."""
        def one(case):
            t0 = time.time()
            out, st, rc = model_fault(self.tmp, *case)
            return case, (out, st, rc, time.time() - t0)
        for name in {c[0] for c in cases}:
            fault_overlay(self.tmp, name)  # made once, before the runs that share it
        with ThreadPoolExecutor(MODEL_FAULT_JOBS) as pool:
            return dict(pool.map(one, cases))

    def check_model_fault(self, case, result):
        name, kind, mode = case
        out, st, rc, wall = result
        self.assertEqual(st.get("status"), "error", (case, st))
        m = st["message"]
        if kind == "hang":  # named by the stepper on its own thread, the bag closed on the recorder's
            self.assertRegex(m, r"did not answer within %g s: node died or hung.*; in the stepper's process, %s has "
                             r"been inside its model step \(from t = %.3f s\) for [0-9.]+ s"
                             # the stepper may first have granted the silent ones more time as
                             # starved of CPU (runs share the machine); the message then says so
                             r"(; waited [0-9.]+ s more for [a-z, ]+ \(starved of CPU\))?$"
                             % (TIMEOUT_S, name, MODEL_FAULT_AT_S), case)
            self.assertLess(wall, 60.0, case)  # the manager that cannot shut down was ended
        else:
            self.assertRegex(m, r"^%s: step \d+ \(t = %.6f s\) failed: " % (name, MODEL_FAULT_AT_S), (case, m))
            if kind == "throw":
                self.assertIn("::step: state: diverged at t = %g s" % MODEL_FAULT_AT_S, m)
            else:
                self.assertIn(NAN_OUTPUT[name], m)
                # stamped at the end of the failed step: t + its macro step (10 ms, or 100 ms)
                self.assertRegex(m, r"not finite in the output stamped t = 3\.(010|100) s$")
        self.assertAlmostEqual(st["sim_time_s"], MODEL_FAULT_AT_S, delta=0.2)
        self.assertIsNotNone(rc)  # the launch ended
        readable(self, out, name, min_states=10)
        self.table.append((name, "%s (%s)" % (kind, mode), m[-90:] if kind == "hang" else m[:90], None))

    def test_each_model_step_throws_yields_nan_or_hangs(self):
        # throw and NaN: each model in both modes; a model that never returns: mode:=nodelets (in
        # mode:=nodes it is a process that does not answer, as the SIGSTOP cases above)
        models = PARTICIPANTS[:-1]
        cases = [(n, k, m) for m in ("nodes", "nodelets") for k in ("throw", "nan") for n in models]
        cases += [(n, "hang", "nodelets") for n in models]
        results = self.model_faults(cases)
        for case in cases:
            with self.subTest(case=case):
                self.check_model_fault(case, results[case])

    def test_stepper_hung(self):
        # every participant hears nothing for 2 timeouts; the recorder closes the bag, writes the
        # status and ends the stepper, so roslaunch stops (the stepper is required)
        out, st, delay, _ = inject(self.tmp, "stepper", signal.SIGSTOP, after_s=10.0)
        self.assertIsNotNone(st, "no status.json")
        self.assertEqual(st["status"], "error", st)
        self.assertRegex(st["message"], r"^stepper \(.+:\d+\): no command from the stepper for [0-9.]+ s .*"
                         r"the stepper died or hung; closed at t = [0-9.]+ s; the recorder closed .*run.bag")
        self.assertGreater(st["sim_time_s"], 10.0)
        self.assertLess(delay, 2 * TIMEOUT_S + 2.0)
        readable(self, out, "stepper")
        self.table.append(("stepper", "SIGSTOP", st["message"][:90], delay))

    def manager_fault(self, sig, after_s):
        """twin run of hybrid_urban (nodelets) with `sig` sent to the nodelet manager once the run
        is stepping past after_s [s]; returns (out, status, exit status, twin's output, manager
        pid, seconds from the signal to the watcher's record or to the status file)."""
        out = os.path.join(self.tmp, "manager_" + signal.Signals(sig).name)
        port, lock = ports.reserve_port(os.getpid() % 1000 + sig)
        env = dict(os.environ, HBT_SETUP_DONE="1", HBT_ROS_PORT=str(port))
        proc = subprocess.Popen([TWIN, "run", "hybrid_urban", "--out", out, "timeout:=%g" % TIMEOUT_S], env=env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            run_util.wait_until_stepping(out, proc, after_s=after_s)
            pid = manager_watch.manager_pid(port)
            self.assertIsNotNone(pid, "no nodelet manager on port %d" % port)
            t_sig = time.time()
            os.kill(pid, sig)
            marker, status = os.path.join(out, manager_watch.RECORD), os.path.join(out, "status.json")
            while proc.poll() is None and not os.path.exists(marker) and not (
                    os.path.exists(status) and os.path.getsize(status) > 0):
                time.sleep(0.05)
            delay = time.time() - t_sig
            text = proc.communicate(timeout=120)[0].decode(errors="replace")
        finally:
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGKILL)
            os.close(lock)
        return out, run_util.read_status(out), proc.returncode, text, pid, delay

    def test_nodelet_manager_stopped(self):
        # nodelets under twin run (its watcher lives beside roslaunch): SIGSTOP to the manager ends
        # the run at the timeout with the manager named and the bag closed by the recorder
        out, st, rc, text, pid, delay = self.manager_fault(signal.SIGSTOP, 10.0)
        self.assertNotEqual(rc, 0, text[-2000:])
        self.assertEqual(st["status"], "error", st)
        self.assertRegex(st["message"], r"^the nodelet manager twin_manager \(pid %d\), which holds every participant, "
                         r"the stepper and the recorder, was stopped from outside \(SIGSTOP: process state T\) for "
                         r"[0-9.]+ s, the run's timeout \(%g s\).*twin ended the run at t = [0-9.]+ s" % (pid, TIMEOUT_S))
        self.assertIn("twin: run FAILED: the nodelet manager twin_manager", text)
        self.assertGreater(st["sim_time_s"], 10.0)
        self.assertLess(delay, TIMEOUT_S + 2.0)  # noticed at the timeout (polled every 0.1 s)
        self.assertFalse(os.path.exists(os.path.join(out, "run.bag.active")))
        readable(self, out, "manager")
        self.table.append(("nodelet manager", "SIGSTOP", st["message"][:90], delay))

    def test_nodelet_manager_killed(self):
        # nodelets: the manager (every participant, the stepper, the recorder) killed: roslaunch
        # stops the run; twin's status names the manager and the signal; the recorder died with
        # it, so the bag is cut short and readable after `rosbag reindex`
        # (late enough that the bag holds whole chunks, as for the recorder above)
        out, st, rc, text, pid, delay = self.manager_fault(signal.SIGKILL, 200.0)
        self.assertNotEqual(rc, 0, text[-2000:])
        self.assertEqual(st["status"], "error", st)
        self.assertIn("twin_manager died (killed by SIGKILL) before the run's end", st["message"])
        self.assertIn("twin: run FAILED: twin_manager died (killed by SIGKILL)", text)
        self.assertGreater(st["sim_time_s"], 200.0)
        self.assertLess(delay, 2.0)  # roslaunch sees the death at once
        readable(self, out, "recorder")  # the recorder's own death: reindexed
        self.table.append(("nodelet manager", "SIGKILL", st["message"][:90], delay))

if __name__ == "__main__":
    run_util.unittest_main()
