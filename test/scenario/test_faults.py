#!/usr/bin/python3
"""Fault injection, every participant: hybrid_urban in nodes mode (one process each), each of the
seven participants and the recorder killed (SIGKILL) and hung (SIGSTOP) once it is stepping, and
the stepper killed. The run stops within 2 s of the kill (the step timeout, 1 s) or at the timeout
of the hang, status.json "error" names the node (as one that did not answer: "node died or hung"),
and run.bag is closed and readable (the recorder killed: cut short, readable after
`rosbag reindex`). The stepper killed: roslaunch stops the run (the stepper is required) and the
status twin writes then (twin_tools.launch.lost_status) names it and the signal.
Faults of a model (a step that throws or yields NaN) are tested per model (their ModelDivergence
and InputError tests) and for the protocol in test/cosim; this test covers the processes."""
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

from twin_tools.launch import lost_status, run_util
from twin_tools.paths import REPO

LAUNCH = os.path.join(REPO, "launch", "hybrid_urban.launch")
PARTICIPANTS = ("vehicle", "engine", "aftertreatment", "cooling", "ems", "emachine", "battery", "recorder")
TIMEOUT_S = 1.0


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
            os.kill(pid, signal.SIGKILL)
        rc = run_util.wait(proc, 90)
        if not os.path.exists(path):
            return out, None, None, rc
        return out, run_util.read_status(out), os.path.getmtime(path) - t_sig, rc
    finally:
        run_util.stop(proc)


def readable(tc, out, name):
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
    tc.assertGreater(n, 100, (name, out))  # the vehicle's states of the stretch that ran


class Faults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_faults_")
        cls.table = []

    @classmethod
    def tearDownClass(cls):
        for row in cls.table:
            print("| %s | %s | %s | %.2f s |" % row)
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def check(self, name, sig, limit_s):
        # the recorder: late enough that its bag holds whole chunks (rosbag writes 768 KiB chunks)
        out, st, delay, _ = inject(self.tmp, name, sig, after_s=200.0 if name == "recorder" else 10.0)
        self.assertIsNotNone(st, (name, "no status.json"))
        self.assertEqual(st["status"], "error", (name, st))
        self.assertIn("%s (done through t = " % name, st["message"], (name, st["message"]))
        self.assertIn("node died or hung", st["message"])
        self.assertLess(delay, limit_s, (name, delay))
        readable(self, out, name)
        self.table.append((name, signal.Signals(sig).name, st["message"][:90], delay))

    def test_each_participant_killed(self):
        for name in PARTICIPANTS:
            with self.subTest(name=name):
                self.check(name, signal.SIGKILL, 2.0)

    def test_each_participant_hung(self):
        for name in PARTICIPANTS:
            with self.subTest(name=name):
                self.check(name, signal.SIGSTOP, TIMEOUT_S + 2.0)

    def test_stepper_killed(self):
        out, st, _, _ = inject(self.tmp, "stepper", signal.SIGKILL)
        self.assertIsNone(st, "a killed stepper writes nothing")
        lost = lost_status.lost_status(out)
        self.assertEqual(lost["status"], "error")
        self.assertIn("stepper died (killed by SIGKILL) before the run's end", lost["message"])
        self.assertGreater(lost["sim_time_s"], 10.0)
        readable(self, out, "stepper")


if __name__ == "__main__":
    run_util.unittest_main()
