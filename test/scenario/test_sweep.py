#!/usr/bin/python3
"""`scripts/twin sweep` on this machine: hybrid_urban at 0 and 25 degC x 7 (the default) and 0
cells in parallel (a value the battery node rejects) for 20 s, 2 at a time. Checks: the two
good runs complete and the two bad ones fail with the node's message naming the file and the key,
the sweep's exit status says so; every row of sweep.csv equals its run's summary.json; the
runs overlap in time, each with its own master port; the console shows the progress line and
none of the runs' output; the config copy holds the swept value; plots are written."""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

SPEC = """\
scenarios: [hybrid_urban]
jobs: 2
fixed: {until: 20, timeout: 10}
vary:
  ambient: [0, 25]
config:
  battery.yaml:
    pack/cells_in_parallel: [7, 0]
"""


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


class LocalSweep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_sweep_")
        cls.addClassCleanup(shutil.rmtree, cls.tmp, True)
        spec = os.path.join(cls.tmp, "tiny.yaml")
        with open(spec, "w") as f:
            f.write(SPEC)
        cls.out = os.path.join(cls.tmp, "out")
        cls.proc = subprocess.run([os.path.join(REPO, "scripts", "twin"), "sweep", spec, "--out", cls.out],
                                  capture_output=True, text=True, timeout=600)
        cls.rows = {r["run"]: r for r in read_csv(os.path.join(cls.out, "sweep.csv"))}

    def run_dir(self, rid):
        return os.path.join(self.out, "runs", rid)

    def test_rows_status_and_reasons(self):
        self.assertEqual(self.proc.returncode, 1, self.proc.stderr)
        self.assertEqual(sorted(self.rows), [
            "000_hybrid_urban_ambient0_cells_in_parallel7", "001_hybrid_urban_ambient0_cells_in_parallel0",
            "002_hybrid_urban_ambient25_cells_in_parallel7", "003_hybrid_urban_ambient25_cells_in_parallel0"])
        for rid, r in self.rows.items():
            cells = r["battery.yaml:pack/cells_in_parallel"]
            self.assertEqual(r["ambient"], "0" if "ambient0_" in rid else "25")
            if cells == "7":
                self.assertEqual(r["status"], "ok", r)
                self.assertEqual(r["reason"], "")
            else:
                self.assertEqual(r["status"], "failed", r)
                # the battery node's input error names the file and the key
                self.assertIn("cells_in_parallel", r["reason"])
                self.assertIn("runs/%s/config/battery.yaml" % rid, r["reason"])
                self.assertEqual(r["fuel_kg"], "")  # a failed run's totals are not compared
                self.assertIn("sweep: run %s FAILED: " % rid, self.proc.stderr)
        self.assertIn("2/4 runs ok", self.proc.stdout)

    def test_rows_equal_the_summaries(self):
        for rid, r in self.rows.items():
            if r["status"] != "ok":
                continue
            with open(os.path.join(self.run_dir(rid), "summary.json")) as f:
                s = json.load(f)
            for col in ("sim_time_s", "distance_km", "fuel_kg", "nox_engine_out_g", "nox_tailpipe_g", "soc_final"):
                self.assertEqual(r[col], repr(s[col]), (rid, col))
            self.assertEqual(float(r["sim_time_s"]), 20.0)
            self.assertEqual(r["fuel_l_per_100km"], "")  # under 1 km: no consumption per distance
            self.assertGreater(float(r["fuel_kg"]), 0.0)
            for f in ("run.bag", "report.md", "roslaunch.log", "twin.log"):
                self.assertTrue(os.path.exists(os.path.join(self.run_dir(rid), f)), (rid, f))
        # the engine starts cold: more fuel at 0 degC than at 25 degC over the same 20 s
        self.assertGreater(float(self.rows["000_hybrid_urban_ambient0_cells_in_parallel7"]["fuel_kg"]),
                           float(self.rows["002_hybrid_urban_ambient25_cells_in_parallel7"]["fuel_kg"]))

    def test_parallel_runs_have_their_own_masters(self):
        tasks = {}
        for rid in self.rows:
            with open(os.path.join(self.run_dir(rid), "sweep_task.json")) as f:
                tasks[rid] = json.load(f)
        spans = sorted((t["start_unix_s"], t["start_unix_s"] + t["wall_s"], t["port"]) for t in tasks.values())
        overlapping = [(a, b) for i, a in enumerate(spans) for b in spans[i + 1:] if b[0] < a[1]]
        self.assertTrue(overlapping)
        for a, b in overlapping:
            self.assertNotEqual(a[2], b[2])
        for rid, t in tasks.items():  # twin run used the port the sweep reserved
            with open(os.path.join(self.run_dir(rid), "roslaunch.log")) as f:
                log = f.read()
            self.assertIn(":%d/" % t["port"], log, rid)

    def test_console_is_one_progress_line(self):
        out = self.proc.stdout
        self.assertIn("sweep: 4/4 done (2 failed), 0 running, 0 waiting", out)
        for noise in ("roslaunch", "[INFO]", "process[", "twin: running"):
            self.assertNotIn(noise, out)

    def test_config_copy_and_outputs(self):
        p = os.path.join(self.run_dir("001_hybrid_urban_ambient0_cells_in_parallel0"), "config", "battery.yaml")
        with open(p) as f:
            self.assertIn("\n  cells_in_parallel: 0\n", f.read())
        self.assertFalse(os.path.exists(os.path.join(self.run_dir("000_hybrid_urban_ambient0_cells_in_parallel7"),
                                                     "config", "sweeps")))
        with open(os.path.join(self.out, "sweep.md")) as f:
            md = f.read()
        self.assertEqual(md.count("| 00"), 4)
        self.assertIn("2 ok, 2 failed", md)
        for q in ("fuel_kg", "soc_final", "nox_tailpipe_g"):
            self.assertGreater(os.path.getsize(os.path.join(self.out, "plots", q + ".png")), 5000)
            self.assertIn("plots/%s.png" % q, md)


if __name__ == "__main__":
    unittest.main(verbosity=2)
