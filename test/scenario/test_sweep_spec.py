#!/usr/bin/python3
"""Sweep specs without running anything (twin_tools.sweep: spec, config_edit, table,
slurm): the example specs expand to their matrices; every kind of bad input is rejected
before anything starts with a message naming the spec file and the key; a config key is set in a
copy that differs from the original on that line only (never added when missing); the saving of a
hybrid run is taken against the conventional run with the same parameters; the sbatch script
runs one plan entry per array task, N at a time; the ETA of the progress line."""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

import yaml

from twin_tools.launch import ports
from twin_tools.sweep import cli as sweep
from twin_tools.sweep import config_edit as sweep_yaml
from twin_tools.sweep import run as sweep_run
from twin_tools.sweep import slurm as sweep_slurm
from twin_tools.sweep import spec as sweep_spec
from twin_tools.sweep import table as sweep_table

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class SpecCase(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="hbt_sweep_spec_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def spec(self, d, name="s.yaml"):
        p = os.path.join(self.tmp, name)
        with open(p, "w") as f:
            yaml.safe_dump(d, f)
        return p

    def rejected(self, d, *words, cli=()):
        p = self.spec(d)
        with self.assertRaises(sweep_spec.SpecError) as cm:
            sweep_spec.Spec(p, REPO, cli)
        msg = str(cm.exception)
        self.assertIn(p, msg)
        for w in words:
            self.assertIn(w, msg)
        return msg


class Examples(SpecCase):
    def test_ambient_study(self):
        s = sweep_spec.Spec(os.path.join(REPO, "config", "sweeps", "ambient_study.yaml"), REPO, ["until:=300"])
        runs = s.runs("/o")
        self.assertEqual([r["id"] for r in runs], [
            "000_baseline_urban_ambient0", "001_baseline_urban_ambient25", "002_baseline_urban_ambient40",
            "003_hybrid_urban_ambient0", "004_hybrid_urban_ambient25", "005_hybrid_urban_ambient40"])
        self.assertEqual(runs[5]["args"], ["ambient:=40.0", "engine:=map", "until:=300.0"])
        self.assertEqual(runs[5]["dir"], "/o/runs/005_hybrid_urban_ambient40")
        self.assertEqual(s.jobs, 2)

    def test_config_axis_and_cli(self):
        s = sweep_spec.Spec(os.path.join(REPO, "config", "sweeps", "battery_cells.yaml"), REPO, ["until:=60"], jobs=3)
        runs = s.runs("/o")
        self.assertEqual(len(runs), 6)
        self.assertEqual(s.jobs, 3)
        r = runs[4]
        self.assertEqual(r["values"], {"ambient": 25, "battery.yaml:pack/cells_in_parallel": 7})
        self.assertEqual(r["edits"], [("battery.yaml", "pack/cells_in_parallel", 7)])
        self.assertEqual(r["args"][0], "config:=/o/runs/004_hybrid_urban_ambient25_cells_in_parallel7/config")


class Rejected(SpecCase):
    base = {"scenarios": ["baseline_urban"], "vary": {"ambient": [0, 25]}}

    def with_(self, **kw):
        d = dict(self.base)
        d.update(kw)
        return d

    def test_missing_config_key_names_file_and_key(self):
        msg = self.rejected(self.with_(config={"battery.yaml": {"pack/cells_parallel": [5, 7]}}),
                            "battery.yaml:pack/cells_parallel", "no key 'cells_parallel' under pack",
                            "cells_in_parallel", os.path.join(REPO, "config", "battery.yaml"))
        self.assertEqual(msg.count("\n"), 0)  # one message for the key, not one per value

    def test_an_empty_axis_is_an_error(self):
        self.rejected(self.with_(vary={}), "vary", "empty")
        self.rejected(self.with_(vary=None), "vary", "empty")
        self.rejected(self.with_(config={}), "config", "empty")

    def test_wrong_types_and_groups(self):
        self.rejected(self.with_(config={"battery.yaml": {"pack/cells_in_parallel": [7.5]}}),
                      "battery.yaml:pack/cells_in_parallel", "integer (7)", "7.5")
        self.rejected(self.with_(config={"vehicle.yaml": {"shift/neutral_at_stop": [1]}}),
                      "vehicle.yaml:shift/neutral_at_stop", "boolean")
        self.rejected(self.with_(config={"battery.yaml": {"pack": [1]}}), "group of keys")
        self.rejected(self.with_(config={"vehicle.yaml": {"driveline/gear_ratios/6": [1.0]}}),
                      "list of 6 elements")

    def test_unknown_file_and_shadowed_keys(self):
        self.rejected(self.with_(config={"batery.yaml": {"pack/cells_in_parallel": [5]}}),
                      "config/batery.yaml", "no such file", "battery.yaml")
        self.rejected(self.with_(config={"data/x.yaml": {"a": [1]}}), "config/data/x.yaml")
        self.rejected(self.with_(config={"vehicle.yaml": {"chassis/payload_kg": [1000.0]}}),
                      "vehicle.yaml:chassis/payload_kg", "payload")
        self.rejected(self.with_(config={"mission.yaml": {"vehicle/mass_kg": [1.0]}}), "mission.yaml:vehicle/mass_kg")

    def test_launch_arguments(self):
        self.rejected(self.with_(vary={"ambient": [0, 500]}), "vary/ambient", "500 is outside")
        self.rejected(self.with_(vary={"speed": [1]}), "vary/speed", "unknown launch argument")
        self.rejected(self.with_(vary={"ambient": 25}), "vary/ambient", "non-empty list")
        self.rejected(self.with_(vary={"ambient": [0, 0]}), "vary/ambient", "twice")
        self.rejected(self.with_(fixed={"engine": "turbo"}), "fixed/engine", "map, 1d")
        self.rejected(self.with_(fixed={"ambient": 10}), "fixed/ambient", "also an axis")
        self.rejected(self.with_(fixed={"out": "/x"}), "fixed/out", "cannot be set")
        self.rejected(self.base, "command line", "until:=x", cli=["until:=x"])
        self.rejected(self.base, "ambient is an axis", cli=["ambient:=3"])

    def test_top_level(self):
        self.rejected(self.with_(scenarios=["hybrid_city"]), "scenarios", "hybrid_city", "hybrid_urban")
        self.rejected(self.with_(jobs=0), "jobs")
        self.rejected(self.with_(matrix={}), "matrix: unknown key")
        self.rejected(self.with_(slurm={"partitoin": "x"}), "slurm/partitoin")
        self.rejected({"vary": {"ambient": [0]}}, "scenarios: missing")

    def test_all_errors_at_once_and_cli_exit_status(self):
        p = self.spec(self.with_(jobs=0, vary={"ambient": [500]}, config={"battery.yaml": {"x": [1]}}))
        r = subprocess.run(["/usr/bin/python3", "-m", "twin_tools.sweep.cli", "--check", p],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(len(r.stderr.strip().split("\n")), 3, r.stderr)
        for w in ("jobs", "vary/ambient", "battery.yaml:x"):
            self.assertIn(w, r.stderr)

    def test_twin_checks_before_setup(self):
        p = self.spec(self.with_(vary={"ambient": [500]}))
        r = subprocess.run([os.path.join(REPO, "scripts", "twin"), "sweep", p], capture_output=True, text=True)
        self.assertEqual(r.returncode, 2)
        self.assertIn("%s: vary/ambient: 500 is outside" % p, r.stderr)
        self.assertNotIn("building", r.stdout + r.stderr)  # stopped before apt-get and the build

    def test_out_folder_must_be_a_sweeps(self):
        os.makedirs(os.path.join(self.tmp, "other"))
        open(os.path.join(self.tmp, "other", "keep.txt"), "w").close()
        r = subprocess.run(["/usr/bin/python3", "-m", "twin_tools.sweep.cli",
                            self.spec(self.base), "--out", os.path.join(self.tmp, "other")],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 2)
        self.assertIn("not a sweep's folder", r.stderr)
        self.assertTrue(os.path.exists(os.path.join(self.tmp, "other", "keep.txt")))


class ConfigCopy(SpecCase):
    def test_copy_differs_on_the_key_line_only(self):
        p = self.spec({"scenarios": ["hybrid_urban"], "config": {
            "battery.yaml": {"pack/cells_in_parallel": [9]},
            "emachine.yaml": {"envelope/continuous_power_W": [20000]}}})
        run = sweep_spec.Spec(p, REPO).runs(os.path.join(self.tmp, "out"))[0]
        os.makedirs(run["dir"])
        sweep.prepare_config(run)
        cfg = os.path.join(run["dir"], "config")
        self.assertEqual(os.path.realpath(os.path.join(cfg, "data")), os.path.join(REPO, "config", "data"))
        self.assertTrue(os.path.islink(os.path.join(cfg, "data")))
        self.assertFalse(os.path.exists(os.path.join(cfg, "sweeps")))
        for f, old, new in (("battery.yaml", "  cells_in_parallel: 7", "  cells_in_parallel: 9"),
                            ("emachine.yaml", "  continuous_power_W: 15000.0",
                             "  continuous_power_W: 20000.0")):
            a = open(os.path.join(REPO, "config", f)).read().split("\n")
            b = open(os.path.join(cfg, f)).read().split("\n")
            diff = [(x, y) for x, y in zip(a, b) if x != y]
            self.assertEqual(len(a), len(b))
            self.assertEqual(len(diff), 1, diff)
            self.assertEqual(diff[0][0].split("#")[0].rstrip(), old)
            self.assertEqual(diff[0][1].split("#")[0].rstrip(), new)
        self.assertEqual(yaml.safe_load(open(os.path.join(cfg, "emachine.yaml")))["envelope"]["continuous_power_W"], 20000.0)
        self.assertIsInstance(yaml.safe_load(open(os.path.join(cfg, "emachine.yaml")))["envelope"]["continuous_power_W"], float)
        for f in ("vehicle.yaml", "ems.yaml", "aux/fan_only.yaml"):
            self.assertEqual(open(os.path.join(REPO, "config", f)).read(), open(os.path.join(cfg, f)).read())

    def test_yaml_editing(self):
        text = "a:\n  # c\n  b: [1.0, 2.0]   # list\n  s: 'x'\n  n: 42.7e6  # as yaml-cpp reads it\nc:\n  - 1\n  - 2\n"
        new, old, _ = sweep_yaml.set_key(text, "a/b/1", 3.5)
        self.assertEqual(old, 2.0)
        self.assertEqual(new.split("\n")[2], "  b: [1.0, 3.5]   # list")
        new, old, w = sweep_yaml.set_key(text, "a/n", 43e6)
        self.assertEqual(yaml.safe_load(new)["a"]["n"], 43e6)
        self.assertIn("# as yaml-cpp reads it", new)
        new, _, _ = sweep_yaml.set_key(text, "c/1", 5)  # a block list: the whole file written
        self.assertEqual(yaml.safe_load(new), {"a": {"b": [1.0, 2.0], "s": "x", "n": "42.7e6"}, "c": [1, 5]})
        with self.assertRaises(sweep_yaml.KeyPathError):
            sweep_yaml.set_key(text, "a/s", 1)
        with self.assertRaises(sweep_yaml.KeyPathError):
            sweep_yaml.set_key(text, "a/z", 1)


class Table(unittest.TestCase):
    def test_saving_against_the_same_parameters(self):
        def row(run, scenario, amb, fuel, **extra):
            s = {"fuel_kg": fuel, "architecture": "p1_48v" if scenario == "hybrid_urban" else "conventional"}
            s.update(extra)
            return {"run": run, "scenario": scenario, "values": {"ambient": amb}, "summary": s,
                    "status": "ok", "reason": "", "wall_s": 1.0}
        rows = [row("b0", "baseline_urban", 0, 2.0), row("b25", "baseline_urban", 25, 1.6),
                row("h0", "hybrid_urban", 0, 1.9, fuel_soc_corrected_kg=1.8), row("h25", "hybrid_urban", 25, 1.5)]
        sweep_table.add_savings(rows, ["ambient"])
        self.assertAlmostEqual(rows[2]["fuel_saving_pct"], 100 * (2.0 - 1.8) / 2.0, places=12)
        self.assertEqual(rows[2]["saving_against"], "b0")
        self.assertAlmostEqual(rows[3]["fuel_saving_pct"], 100 * (1.6 - 1.5) / 1.6, places=12)
        self.assertIsNone(rows[0]["fuel_saving_pct"])
        self.assertEqual(sweep_table.cell(rows[2], "fuel_saving_pct", ["ambient"], md=True), "10.00")
        self.assertEqual(sweep_table.cell(rows[2], "fuel_saving_pct", ["ambient"], md=False), repr(rows[2]["fuel_saving_pct"]))

    def test_sbatch_script(self):
        plan = {"name": "s", "out": "/o", "repo": "/r", "runs": [{}, {}, {}]}
        text = sweep_slurm.script(plan, 2, {"time": "00:10:00"})
        self.assertIn("#SBATCH --array=0-2%2\n", text)
        self.assertIn("#SBATCH --time=00:10:00\n", text)
        self.assertIn("#SBATCH --output=/o/slurm/task_%a.out\n", text)
        self.assertIn("export PYTHONPATH=/r/python${PYTHONPATH:+:$PYTHONPATH}\n", text)
        self.assertTrue(text.rstrip().endswith(
            'exec /usr/bin/python3 -m twin_tools.sweep.cli task /o/plan.json "$SLURM_ARRAY_TASK_ID"'))

    def test_eta(self):
        # 2 finished (10 s, 20 s: mean 15 s), 3 waiting, one running for 5 s, 2 at a time
        self.assertAlmostEqual(sweep_run.eta(3, [5.0], [10.0, 20.0], 2), (3 * 15.0 + 10.0) / 2)
        self.assertIsNone(sweep_run.eta(3, [5.0], [], 2))
        self.assertEqual(sweep_run.fmt_time(3725), "1h02m05s")

    def test_port_reservation_is_exclusive(self):
        p1, fd1 = ports.reserve_port(0)
        p2, fd2 = ports.reserve_port(p1 - ports.PORT_LO)  # asks for the same first: gets another
        try:
            self.assertNotEqual(p1, p2)
            self.assertTrue(ports.PORT_LO <= p1 < ports.PORT_HI)
        finally:
            os.close(fd1)
            os.close(fd2)


if __name__ == "__main__":
    unittest.main(verbosity=2)
