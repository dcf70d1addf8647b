#!/usr/bin/python3
"""Launch arguments of `twin run` (twin_tools.launch.args): every class of bad input is rejected
before anything starts, naming the argument; numbers in scientific notation are normalised to
the plain decimals roslaunch reads as numbers, never silently replaced by a default."""
import os
import subprocess
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = ["-m", "twin_tools.launch.args"]


def check(*args, scenario="baseline_urban"):
    r = subprocess.run(["/usr/bin/python3", *TOOL, REPO, scenario, *args],
                       capture_output=True, text=True)
    return r.returncode, r.stdout.split(), r.stderr


class LaunchArgs(unittest.TestCase):
    def rejected(self, arg, *words):
        rc, _, err = check(arg)
        self.assertNotEqual(rc, 0, arg)
        self.assertIn(arg.partition(":=")[0], err)
        for w in words:
            self.assertIn(w, err)

    def test_scientific_notation_normalised(self):
        rc, out, _ = check("step:=1e-3", "until:=1e3", "record_period:=1e-5")
        self.assertEqual(rc, 0)
        self.assertEqual(out, ["step:=0.001", "until:=1000.0", "record_period:=0.00001"])

    def test_out_of_range(self):
        self.rejected("until:=-5", "outside")
        self.rejected("ambient:=500", "outside")
        self.rejected("step:=2", "outside")
        self.rejected("payload:=-1", "outside")
        self.rejected("pressure:=101325", "outside")  # kPa, not Pa
        self.rejected("pressure:=20", "outside")
        self.rejected("window_steps:=0", "outside")
        self.rejected("window_steps:=2.5", "not an integer")
        rc, out, _ = check("window_steps:=1e2")
        self.assertEqual((rc, out), (0, ["window_steps:=100"]))

    def test_thread_names(self):
        self.rejected("thermal_thread:=the rmal", "not a thread name")
        self.rejected("thermal_thread:=" + "t" * 65, "not a thread name")
        for ok in ("thermal_thread:=lockstep", "thermal_thread:=thermal", "thermal_thread:=my_2nd"):
            rc, out, _ = check(ok)
            self.assertEqual((rc, out), (0, [ok]))

    def test_architecture_that_contradicts_the_scenario(self):
        for scenario, arch, other in (("baseline_urban", "p1_48v", "hybrid_urban"),
                                      ("hybrid_urban", "conventional", "baseline_urban")):
            rc, _, err = check("architecture:=" + arch, scenario=scenario)
            self.assertNotEqual(rc, 0, scenario)
            self.assertIn("architecture", err)
            self.assertIn("contradicts", err)
            self.assertIn(other, err)  # what to run instead
        rc, out, _ = check("architecture:=p1_48v", scenario="hybrid_urban")  # repeating it is fine
        self.assertEqual((rc, out), (0, ["architecture:=p1_48v"]))

    def test_not_a_number(self):
        self.rejected("ambient:=warm", "not a number")
        self.rejected("payload:=nan", "not finite")
        self.rejected("until:=inf", "not finite")

    def test_unknown_choices(self):
        self.rejected("mode:=bar", "nodes, nodelets")
        self.rejected("engine:=foo", "map, 1d")
        self.rejected("solver:=euler", "fsm, tvd")
        self.rejected("rviz:=yes", "true, false")
        self.rejected("hvac:=auto", "on, off")

    def test_missing_files(self):
        self.rejected("aux:=foo", "fan_only", "vecto_p1_example")
        self.rejected("gearbox:=measured", "argument 'gearbox'", "typical", "vecto_standard")
        self.rejected("pack:=13s9p", "argument 'pack'", "production_13s2p")
        self.rejected("cycle:=Nowhere", "Urban")
        self.rejected("cycle_file:=/nonexistent.vdri", "not found")
        self.rejected("config:=/nonexistent_dir", "not found")

    def test_unknown_and_repeated_arguments(self):
        self.rejected("speed:=3", "unknown argument")
        rc, _, err = check("ambient:=0", "ambient:=25")
        self.assertNotEqual(rc, 0)
        self.assertIn("twice", err)
        rc, _, err = check("ambient=25")
        self.assertNotEqual(rc, 0)
        self.assertIn("name:=value", err)

    def test_remote_participants(self):
        """remote:=... names participants of this scenario and comes with its host."""
        self.rejected("remote:=engine", "remote_host")
        self.rejected("remote_host:=10.0.0.2", "without remote")
        rc, _, err = check("remote:=battery", "remote_host:=10.0.0.2")  # baseline has no battery
        self.assertNotEqual(rc, 0)
        self.assertIn("battery is not a participant of baseline_urban", err)
        rc, _, err = check("remote:=cooling", "remote_host:=h", "thermal:=false")
        self.assertIn("cooling is not a participant", err)
        rc, _, err = check("remote:=hvac", "remote_host:=h", "hvac:=off")
        self.assertIn("hvac is not a participant", err)
        rc, _, err = check("remote:=stepper", "remote_host:=h")
        self.assertIn("'stepper' is not a participant that can run remotely", err)
        rc, _, err = check("remote:=engine", "remote_host:=h;rm", )
        self.assertIn("not a host name", err)
        rc, _, err = check("remote:=engine", "remote_host:=h", "remote_env_loader:=env.sh")
        self.assertIn("not an absolute path", err)
        rc, out, _ = check("remote:=engine, cooling", "remote_host:=10.0.0.2", "remote_ssh_port:=2222")
        self.assertEqual(rc, 0)
        self.assertEqual(out, ["remote:=engine,cooling", "remote_host:=10.0.0.2", "remote_ssh_port:=2222"])

    def test_fmu_arguments(self):
        """<participant>_fmu:= an existing .fmu for a participant of this scenario; _fmu_map:= an
        existing YAML mapping, only with its _fmu (the FMU's content is the participant's check)"""
        import tempfile
        with tempfile.TemporaryDirectory() as d:
            fmu = os.path.join(d, "pack.fmu")
            other = os.path.join(d, "pack.zip")
            good, empty = os.path.join(d, "map.yaml"), os.path.join(d, "empty.yaml")
            for path, text in ((fmu, "x"), (other, "x"), (good, "interface: cs\n"), (empty, "")):
                with open(path, "w") as f:
                    f.write(text)
            self.rejected("engine_fmu:=%s/none.fmu" % d, "not found")
            self.rejected("engine_fmu:=" + other, "not an .fmu file")
            self.rejected("engine_fmu:=" + d, "not found")  # a folder
            rc, _, err = check("battery_fmu:=" + fmu)  # baseline has no battery
            self.assertIn("battery is not a participant of baseline_urban", err)
            rc, _, err = check("engine_fmu_map:=" + good)
            self.assertIn("engine_fmu_map' given without engine_fmu", err)
            rc, _, err = check("engine_fmu:=" + fmu, "engine_fmu_map:=" + empty)
            self.assertIn("empty", err)
            rc, out, _ = check("battery_fmu:=" + fmu, "battery_fmu_map:=" + good, scenario="hybrid_urban")
            self.assertEqual(rc, 0)
            self.assertEqual(out, ["battery_fmu:=" + fmu, "battery_fmu_map:=" + good])
            # a pack set or a warm start the FMU would not receive: refused naming both arguments
            rc, _, err = check("battery_fmu:=" + fmu, "pack:=production_13s2p", scenario="hybrid_urban")
            self.assertNotEqual(rc, 0)
            for w in ("'pack:=production_13s2p' cannot reach battery_fmu:=" + fmu, "scenario.<name>"):
                self.assertIn(w, err)
            rc, _, err = check("cooling_fmu:=" + fmu, "start:=warm", scenario="hybrid_urban")
            self.assertNotEqual(rc, 0)
            self.assertIn("'start:=warm' cannot reach cooling_fmu:=" + fmu, err)
            # ... but not where no FMU reads it: the native battery gets the pack, the e-machine
            # model has no warm start; start:=cold is what the FMU does anyway
            for args in (("emachine_fmu:=" + fmu, "pack:=production_13s2p"), ("emachine_fmu:=" + fmu, "start:=warm"),
                         ("battery_fmu:=" + fmu, "start:=cold")):
                rc, _, err = check(*args, scenario="hybrid_urban")
                self.assertEqual(rc, 0, err)

    def test_config_files_empty_or_garbage(self):
        """every YAML of the config folder must parse and hold keys: roslaunch would load an
        empty file as nothing (the model on its defaults) and name no file for garbage"""
        import shutil
        import tempfile
        tmp = tempfile.mkdtemp(prefix="hbt_cfg_")
        try:
            cfg = os.path.join(tmp, "config")
            shutil.copytree(os.path.join(REPO, "config"), cfg, ignore=shutil.ignore_patterns("data"))
            rc, _, err = check("config:=" + cfg)
            self.assertEqual(rc, 0, err)
            open(os.path.join(cfg, "cooling.yaml"), "w").close()
            rc, _, err = check("config:=" + cfg)
            self.assertNotEqual(rc, 0)
            self.assertIn(os.path.join(cfg, "cooling.yaml") + ": empty", err)
            with open(os.path.join(cfg, "cooling.yaml"), "wb") as f:
                f.write(bytes(range(256)))
            rc, _, err = check("config:=" + cfg)
            self.assertIn(os.path.join(cfg, "cooling.yaml") + ": not UTF-8", err)
            with open(os.path.join(cfg, "aux", "fan_only.yaml"), "w") as f:
                f.write("aux: [unclosed\n")
            shutil.copy(os.path.join(REPO, "config", "cooling.yaml"), cfg)
            rc, _, err = check("config:=" + cfg)
            self.assertIn(os.path.join(cfg, "aux", "fan_only.yaml") + ": not valid YAML", err)
            shutil.copy(os.path.join(REPO, "config", "aux", "fan_only.yaml"), os.path.join(cfg, "aux"))
            os.remove(os.path.join(cfg, "battery.yaml"))
            os.mkdir(os.path.join(cfg, "battery.yaml"))  # a folder where a config file belongs
            rc, _, err = check("config:=" + cfg)
            self.assertNotEqual(rc, 0)
            self.assertNotIn("Traceback", err)
            self.assertIn(os.path.join(cfg, "battery.yaml") + ": a folder", err)
        finally:
            shutil.rmtree(tmp)

    def test_valid_arguments_pass_unchanged(self):
        args = ["ambient:=0", "engine:=1d", "solver:=tvd", "mode:=nodelets", "aux:=fan_only",
                "gearbox:=vecto_standard", "pack:=production_13s2p", "cycle:=Urban", "rviz:=false", "hvac:=off"]
        rc, out, _ = check(*args)
        self.assertEqual(rc, 0)
        self.assertEqual(out, ["ambient:=0.0"] + args[1:])


if __name__ == "__main__":
    unittest.main(verbosity=2)
