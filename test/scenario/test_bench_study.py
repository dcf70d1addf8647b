#!/usr/bin/python3
"""`twin bench study`'s table assembled from a sweep's folder (no ROS): the plan of the shipped
study spec (config/sweeps/study.yaml) with run folders written here with known numbers. Checks,
by hand arithmetic: each hybrid is paired with the baseline at its own ambient and its saving is
the SOC-corrected one, 100 (f_b - f_h,corr) / f_b; the engine and the HVAC setting come from the
run arguments (a CLI engine:=map overrides the spec's 1d); a failed run leaves "-" in its cells,
fails the checks and is named; the wall line sums the runs' wall times."""
import json
import os
import shutil
import tempfile
import unittest

from twin_tools.bench import study
from twin_tools.paths import REPO
from twin_tools.sweep import cli as sweep_cli
from twin_tools.sweep import spec as sweep_spec

# ambient -> (baseline fuel, hybrid fuel, hybrid SOC-corrected fuel) [kg]
FUEL = {0: (40.0, 35.0, 36.0), 25: (50.0, 46.0, 47.0), 40: (60.0, None, None)}
GOOD = {"stops_served": 121, "stops_total": 121, "engine_starts": 80, "em_clamped_s": 0.0, "battery_limited_s": 0.0,
        "engine_off_s": 1500.0}


def write(path, d):
    with open(path, "w") as f:
        json.dump(d, f)


class BenchStudyTable(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_bench_study_")
        cls.addClassCleanup(shutil.rmtree, cls.tmp, True)
        out = os.path.join(cls.tmp, "out")
        spec = sweep_spec.Spec(study.SPEC, REPO, ["engine:=map", "until:=300"], out=out)
        cls.plan = sweep_cli.make_plan(spec, out)
        for i, r in enumerate(cls.plan["runs"]):
            os.makedirs(r["dir"])
            amb, hybrid = r["values"]["ambient"], r["scenario"] == "hybrid_urban"
            fb, fh, fc = FUEL[amb]
            failed = hybrid and fh is None
            write(os.path.join(r["dir"], "sweep_task.json"), {"rc": 1 if failed else 0, "wall_s": 10.0 + i})
            write(os.path.join(r["dir"], "status.json"), {"status": "error", "message": "battery: died"}
                  if failed else {"status": "ok"})
            if not failed:
                s = dict(GOOD, fuel_kg=fh if hybrid else fb, architecture="p1_48v" if hybrid else "conventional")
                if hybrid:
                    s["fuel_soc_corrected_kg"] = fc
                write(os.path.join(r["dir"], "summary.json"), s)
        write(os.path.join(out, "timing.json"), {"jobs": 2, "slurm_job": None, "wall_s": 40.0})
        cls.results, cls.rows = study.study_results(cls.plan)
        cls.lines, cls.ok = study.study_lines(cls.plan, until=300.0)

    def test_pairs_by_ambient_and_saving_is_soc_corrected(self):
        self.assertEqual(self.results[("map", 0, "on", "hybrid_urban")][1]["fuel_saving_pct"], 100.0 * (40.0 - 36.0) / 40.0)
        self.assertEqual(self.results[("map", 25, "on", "hybrid_urban")][1]["fuel_saving_pct"], 100.0 * (50.0 - 47.0) / 50.0)
        table = study.study_table(self.results, ["map"], ["on"])
        heads = [h.strip() for h in table[0].strip("|").split("|")]
        rows = [[c.strip() for c in line.strip("|").split("|")] for line in table[2:]]
        self.assertEqual([r[:3] for r in rows], [["map", "0", "on"], ["map", "25", "on"], ["map", "40", "on"]])
        col = lambda name: [r[heads.index(name)] for r in rows]
        self.assertEqual(col("fuel baseline [kg]"), ["40.00", "50.00", "60.00"])
        self.assertEqual(col("hybrid, SOC-corr. [kg]"), ["36.00", "47.00", "-"])
        self.assertEqual(col("saving [%]"), ["10.0", "6.0", "-"])
        self.assertEqual(col("engine off [s]"), ["1500", "1500", "-"])

    def test_failed_run_fails_the_checks_and_is_named(self):
        self.assertFalse(self.ok)
        self.assertIn("- FAILED: hybrid_urban map 40 °C hvac:=on: ended ok", self.lines)
        self.assertIn("Failed runs: 005_hybrid_urban_ambient40 (reasons in sweep.md).", self.lines)
        self.assertIn("- ok: hybrid_urban map 0 °C hvac:=on: em_clamped_s 0.0, battery_limited_s 0.0", self.lines)
        self.assertFalse(any("engine starts" in l for l in self.lines))  # --until: no restart expected

    def test_wall_line(self):
        walls = [10.0 + i for i in range(6)]
        line = [l for l in self.lines if l.startswith("Wall time")][0]
        self.assertIn("**40.0 s**", line)
        self.assertIn("for 6 runs, 2 at a time on this machine", line)
        self.assertIn("sum to %.1f s (10.0–15.0 s each)" % sum(walls), line)


if __name__ == "__main__":
    unittest.main()
