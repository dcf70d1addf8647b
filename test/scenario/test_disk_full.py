#!/usr/bin/python3
"""A disk that fills up while the run writes its bag: `twin run baseline_urban --out` on an 8 MiB
tmpfs (made and removed here; skipped where mounting is not allowed). The run stops with status
"error" naming the bag being written and the cause (no space left), twin exits non-zero saying the
run failed and how to recover the bag, nothing hangs, and what was written stays readable
(`rosbag reindex` of a copy: the vehicle's states up to the failure)."""
import os
import shutil
import subprocess
import tempfile
import time
import unittest

from twin_tools.launch import run_util
from twin_tools.paths import REPO

TWIN = os.path.join(REPO, "scripts", "twin")
SIZE = "8m"  # the profile (4 MB) fits; the bags soon do not


class DiskFull(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_disk_full_")
        cls.mnt = os.path.join(cls.tmp, "small_disk")
        os.makedirs(cls.mnt)
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=" + SIZE, "tmpfs", cls.mnt],
                           capture_output=True, text=True)
        if r.returncode != 0:
            shutil.rmtree(cls.tmp, ignore_errors=True)
            raise unittest.SkipTest("cannot mount a tmpfs here (%s)" % r.stderr.strip())
        cls.out = os.path.join(cls.mnt, "run")
        t0 = time.time()
        r = subprocess.run([TWIN, "run", "baseline_urban", "--out", cls.out], capture_output=True, text=True,
                           env=dict(os.environ, HBT_SETUP_DONE="1"), timeout=300)
        cls.rc, cls.text, cls.wall_s = r.returncode, r.stdout + r.stderr, time.time() - t0

    @classmethod
    def tearDownClass(cls):
        for line in cls.text.splitlines():  # what the user saw (the test log keeps it)
            if line.startswith("twin: "):
                print(line)
        subprocess.run(["umount", cls.mnt])
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_run_stops_naming_the_bag_and_the_cause(self):
        self.assertNotEqual(self.rc, 0, self.text[-3000:])
        self.assertLess(self.wall_s, 240.0)
        st = run_util.read_status(self.out)
        self.assertEqual(st["status"], "error", st)
        self.assertRegex(st["message"], r"writing %s/(run|diagnostics)\.bag" % self.out)
        self.assertIn("no space left on the device", st["message"])
        self.assertIn("twin: run FAILED: " + st["message"], self.text)

    def test_what_was_written_stays_readable(self):
        import rosbag
        st = run_util.read_status(self.out)
        copy = os.path.join(self.tmp, "run.bag")
        shutil.copy(os.path.join(self.out, "run.bag"), copy)
        try:
            rosbag.Bag(copy).close()
        except rosbag.ROSBagUnindexedException:  # cut short: what twin's message says to do
            self.assertIn("rosbag reindex", self.text)
            r = subprocess.run(["rosbag", "reindex", copy], capture_output=True, text=True, cwd=self.tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
        stamps = []
        with rosbag.Bag(copy) as b:
            for _, m, _ in b.read_messages(topics=["/vehicle/state"]):
                stamps.append(m.header.stamp.to_sec())
        self.assertGreater(len(stamps), 100)
        self.assertLessEqual(max(stamps), st["sim_time_s"] + 1e-6)


if __name__ == "__main__":
    run_util.unittest_main()
