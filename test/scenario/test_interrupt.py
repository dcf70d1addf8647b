#!/usr/bin/python3
"""Interrupted runs, as a user stops them: Ctrl-C on `twin run` (SIGINT to its whole process
group) of baseline_urban in nodelets, and SIGTERM to the twin process alone of hybrid_urban in
nodes. Either way: exit status 130; status.json "interrupted" with "interrupted at t = X s";
run.bag closed and readable up to X; summary.json and report.md of the stretch that ran, marked
partial; everything within 60 s of the signal."""
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

from twin_tools.launch import run_util
from twin_tools.paths import REPO

TWIN = os.path.join(REPO, "scripts", "twin")
# report window W of the lock-step [s]: window_steps x dt_s, the defaults of launch/include/urban.launch
WINDOW_S = 50 * 0.01


class Interrupted(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_interrupt_")
        cls.runs = {}
        env = dict(os.environ, HBT_SETUP_DONE="1")  # the suite built the tree already
        for name, scenario, args, how in (("ctrl_c", "baseline_urban", [], "group SIGINT"),
                                          ("sigterm", "hybrid_urban", ["mode:=nodes"], "SIGTERM to twin")):
            out = os.path.join(cls.tmp, name)
            os.makedirs(out)
            proc = subprocess.Popen([TWIN, "run", scenario, "--out", out] + args, env=env,
                                    stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
            try:
                run_util.wait_until_stepping(out, proc, after_s=50.0)
                t0 = time.time()
                if how == "group SIGINT":
                    os.killpg(proc.pid, signal.SIGINT)  # what Ctrl-C in a terminal does
                else:
                    os.kill(proc.pid, signal.SIGTERM)
                text = proc.communicate(timeout=120)[0].decode(errors="replace")
                cls.runs[name] = (out, proc.returncode, time.time() - t0, text)
            finally:
                if proc.poll() is None:
                    os.killpg(proc.pid, signal.SIGKILL)

    @classmethod
    def tearDownClass(cls):
        for name, (out, rc, wall, text) in cls.runs.items():  # what the user saw (the test log keeps it)
            print("%s: exit %s, %.1f s after the signal" % (name, rc, wall))
            for line in text.splitlines():
                if line.startswith("twin: "):
                    print("  " + line)
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_exit_status_and_status_file(self):
        for name, (out, rc, dt, text) in self.runs.items():
            self.assertEqual(rc, 130, (name, text[-2000:]))
            self.assertLess(dt, 60.0, name)
            st = run_util.read_status(out)
            self.assertEqual(st["status"], "interrupted", (name, st))
            self.assertTrue(st["message"].startswith("interrupted at t = "), st["message"])
            self.assertGreater(st["sim_time_s"], 50.0, name)
            self.assertIn("twin: run INTERRUPTED: interrupted at t = ", text, name)

    def test_bag_closed_and_readable_up_to_the_interruption(self):
        import rosbag
        for name, (out, _, _, _) in self.runs.items():
            st = run_util.read_status(out)
            self.assertFalse(os.path.exists(os.path.join(out, "run.bag.active")), name)
            last, dist_at_x = 0.0, None
            with rosbag.Bag(os.path.join(out, "run.bag")) as b:
                for _, m, _ in b.read_messages(topics=["/vehicle/state"]):
                    t = m.header.stamp.to_sec()
                    last = max(last, t)
                    if t <= st["sim_time_s"] + 1e-9:
                        dist_at_x = m.distance_m
            # recorded every 0.1 s up to the time every participant was done through (X); some
            # participants may have run up to two report windows further (the grant horizon)
            self.assertGreater(last, st["sim_time_s"] - 0.2 - 1e-9, name)
            self.assertLessEqual(last, st["sim_time_s"] + 2 * WINDOW_S + 1e-9, name)
            # the partial report covers 0..X, the same stretch for every topic
            with open(os.path.join(out, "summary.json")) as f:
                s = json.load(f)
            self.assertEqual(s["distance_km"], dist_at_x / 1000.0, name)

    def test_report_of_the_stretch_that_ran_says_it_is_partial(self):
        for name, (out, _, _, _) in self.runs.items():
            st = run_util.read_status(out)
            with open(os.path.join(out, "summary.json")) as f:
                s = json.load(f)
            self.assertIs(s.get("partial"), True, name)
            self.assertEqual(s["interrupted_at_s"], st["sim_time_s"], name)
            self.assertLess(s["stops_served"], 121, name)
            with open(os.path.join(out, "report.md")) as f:
                rep = f.read()
            self.assertIn("**Partial report**", rep, name)


if __name__ == "__main__":
    run_util.unittest_main()
