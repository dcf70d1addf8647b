#!/usr/bin/python3
"""Scenario tests of baseline_urban on short stretches of the Urban mission (until:=...):
nodes vs nodelets and repeated runs (with report windows of 50, 1 and 37 base steps) give
bit-identical bags; the driveline energy balance of the
run closes and the engine's own brake work agrees with the work the vehicle received (a killed
node: test_faults.py, every participant); bad input (missing, malformed or
truncated cycle, negative mass, unknown key, NaN, a macro step that is not a multiple of the base
step, a bad thread name, a bad `order`) is rejected before the first step with a message naming the file and the key;
the engine at twice the base step, stepped after the vehicle, runs and is recorded by its held
value."""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

from twin_tools.launch import run_util
from twin_tools.units import DIESEL_LHV_J_KG

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

LAUNCH = os.path.join(REPO, "launch", "baseline_urban.launch")
UNTIL = 60.0


def last(bag, topic):
    import rosbag
    with rosbag.Bag(bag) as b:
        msg = None
        for _, msg, _ in b.read_messages(topics=[topic]):
            pass
    return msg


class Baseline(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_baseline_")
        cls.runs = {}
        # nodes2: a repeat with a report window of 1 base step (the stepper's grants then follow
        # every step), nodelets with 37: the bag depends on neither the mode nor the window
        for name, mode, window in (("nodes", "nodes", 50), ("nodes2", "nodes", 1), ("nodelets", "nodelets", 37)):
            out = os.path.join(cls.tmp, name)
            # timeout 10 s: a hang detector; 1 s tripped on this 2-core machine under a load of 10+
            st = run_util.run_launch(LAUNCH, out, mode=mode, until=UNTIL, record_period=0, timeout=10.0,
                                     window_steps=window)
            cls.runs[name] = (out, st)
        # the same stretch at 80 kPa (about 2000 m above sea level): launch argument pressure:=
        cls.p80 = os.path.join(cls.tmp, "p80")
        cls.p80_status = run_util.run_launch(LAUNCH, cls.p80, until=UNTIL, record_period=0, timeout=10.0,
                                             pressure=80)

    def test_runs_complete(self):
        for name, (out, st) in self.runs.items():
            self.assertEqual(st["status"], "ok", (name, st))
            self.assertAlmostEqual(st["sim_time_s"], UNTIL, places=9)

    def test_modes_and_repeats_bit_identical(self):
        bags = {n: run_util.bag_messages(os.path.join(o, "run.bag")) for n, (o, _) in self.runs.items()}
        n_steps = int(round(UNTIL / 0.01)) + 1
        self.assertEqual({m[0] for m in bags["nodes"]}, set(run_util.BASELINE_TOPICS))
        self.assertEqual(len(bags["nodes"]), len(run_util.BASELINE_TOPICS) * n_steps, "every topic at every stamp incl. t=0")
        self.assertEqual(bags["nodes"], bags["nodes2"])
        self.assertEqual(bags["nodes"], bags["nodelets"])

    def test_energy_balance(self):
        bag = os.path.join(self.runs["nodes"][0], "run.bag")
        v = last(bag, "/vehicle/state")
        e = last(bag, "/engine/state")
        losses = (v.aux_work_j + v.gearbox_drag_loss_j + v.converter_loss_j + v.gear_loss_j +
                  v.retarder_loss_j + v.axle_loss_j + v.shift_loss_j + v.rolling_loss_j +
                  v.aero_loss_j + v.potential_energy_j + v.friction_brake_loss_j)
        # driveline: work the crank received = every loss + change of kinetic energy (1%)
        self.assertGreater(v.engine_work_j, 1e5)
        self.assertAlmostEqual((losses + v.kinetic_energy_change_j) / v.engine_work_j, 1.0, delta=0.01)
        # engine side: its brake work (own speed and torque) = work booked by the vehicle (1%)
        engine_work = e.positive_work_j + e.motoring_work_j
        self.assertAlmostEqual(engine_work / v.engine_work_j, 1.0, delta=0.01)
        # fuel energy covers the brake work with a plausible mean efficiency (urban, idling)
        eff = e.positive_work_j / (e.fuel_mass_kg * DIESEL_LHV_J_KG)
        self.assertGreater(eff, 0.10)
        self.assertLess(eff, 0.46)


    def test_thermal_loops_visible_and_held(self):
        """The engine steps on the coolant temperature and back-pressure stamped for its step
        (Jacobi: the state at t - dt; the cooling and aftertreatment nodes step every 0.1 s, so
        their values are held: stamped floor((t - dt) / 0.1 s) * 0.1 s); the vehicle's fan work
        is the cooling node's."""
        import rosbag
        bag = os.path.join(self.runs["nodes"][0], "run.bag")
        by = {"/engine/state": {}, "/cooling/state": {}, "/aftertreatment/state": {}}
        with rosbag.Bag(bag) as b:
            for topic, m, _ in b.read_messages(topics=list(by)):
                by[topic][m.header.stamp.to_nsec()] = m
        dt, P = 10**7, 10**8
        checked = 0
        for t, e in by["/engine/state"].items():
            if t < dt:
                continue
            tc = (t - dt) // P * P
            self.assertEqual(e.coolant_temperature_k, by["/cooling/state"][tc].coolant_ht_temperature_k, t)
            self.assertEqual(e.back_pressure_pa, by["/aftertreatment/state"][tc].back_pressure_pa, t)
            checked += 1
        self.assertGreater(checked, 5000)
        e = by["/engine/state"][max(by["/engine/state"])]
        self.assertGreater(e.friction_correction_nm, 0.0)  # a cold start at 25 degC: cold oil
        self.assertGreater(e.back_pressure_pa, 101325.0)

    def test_one_ambient_pressure(self):
        """pressure:=80 (kPa) reaches every node that uses the ambient pressure -- the vehicle's
        air density and its command to the engine, the tailpipe of the aftertreatment -- and
        nothing else changes it: aerodynamic drag work scales with rho = p/(R T) (the same speed
        trace within the driver's tracking), the back-pressure sits above 80 kPa, not 101.325."""
        import rosbag
        self.assertEqual(self.p80_status["status"], "ok", self.p80_status)
        ref = os.path.join(self.runs["nodelets"][0], "run.bag")
        low = os.path.join(self.p80, "run.bag")
        with rosbag.Bag(low) as b:
            demands = [m.ambient_pressure_pa for _, m, _ in b.read_messages(topics=["/vehicle/engine_command"])]
        self.assertGreater(len(demands), 5000)
        self.assertTrue(all(p == 80000.0 for p in demands))
        for bag, p_amb in ((ref, 101325.0), (low, 80000.0)):
            a = last(bag, "/aftertreatment/state")
            self.assertGreater(a.back_pressure_pa, p_amb)  # exhaust flowing: above ambient
            self.assertLess(a.back_pressure_pa, p_amb + 10e3)  # idle/low load: a few kPa at most
        v_ref, v_low = last(ref, "/vehicle/state"), last(low, "/vehicle/state")
        self.assertGreater(v_ref.aero_loss_j, 1e3)
        self.assertAlmostEqual(v_low.aero_loss_j / v_ref.aero_loss_j, 80000.0 / 101325.0, delta=0.01)
        self.assertAlmostEqual(v_low.rolling_loss_j / v_ref.rolling_loss_j, 1.0, delta=0.01)

    def test_stop_service_from_the_run_config(self):
        """The report counts served stops and idle-at-stop fuel with the run's own definition
        (config/mission.yaml stop_service/, as resolved_config/vehicle.csv records it): with a
        standstill speed of 0 nothing ever stands, so no stop is served and no fuel is idle at a
        stop; without the key the report stops naming file and key."""
        def report(edit):
            out = tempfile.mkdtemp(prefix="stop_service_", dir=self.tmp)
            shutil.rmtree(out)
            shutil.copytree(self.runs["nodes"][0], out)
            path = os.path.join(out, "resolved_config", "vehicle.csv")
            with open(path) as f:
                lines = [edit(line) for line in f]
            with open(path, "w") as f:
                f.writelines(line for line in lines if line is not None)
            r = subprocess.run(["/usr/bin/python3", "-m", "twin_tools.report.postprocess", out,
                                "--scenario", "baseline_urban"], capture_output=True, text=True)
            s = json.load(open(os.path.join(out, "summary.json"))) if r.returncode == 0 else None
            return r, s

        r, s = report(lambda line: line)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertGreaterEqual(s["stops_total"], 1)
        self.assertEqual(s["stops_served"], s["stops_total"])
        self.assertGreater(s["fuel_by_state_kg"]["idle_at_stop"], 0.0)
        r, s = report(lambda line: line.replace(",stop_service/standstill_speed_m_s,0.1388888888888889,",
                                                ",stop_service/standstill_speed_m_s,0,"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(s["stops_served"], 0)
        self.assertEqual(s["fuel_by_state_kg"]["idle_at_stop"], 0.0)
        r, _ = report(lambda line: None if "stop_service/served_fraction" in line else line)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("stop_service/served_fraction", r.stderr)
        self.assertIn("vehicle.csv", r.stderr)

    def test_energy_ledger_in_summary(self):
        """summary.json carries the ledger; it closes to 0.1 % and every key is finite."""
        import math
        out = os.path.join(self.tmp, "ledger")  # a copy: the report appends the run info to the bag
        shutil.copytree(self.runs["nodes"][0], out)
        r = subprocess.run(["/usr/bin/python3", "-m", "twin_tools.report.postprocess", out,
                            "--scenario", "baseline_urban"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        self.assertEqual(s["gearbox_set"], "typical")  # the default gear loss set, stated like aux_set
        with open(os.path.join(out, "resolved_config", "vehicle.csv")) as f:  # and it reached the bus
            self.assertIn("config/gearbox/typical.yaml,gearbox/gear_loss_map_file,", f.read())
        L = s["energy_kwh"]
        for k, v in L.items():
            self.assertTrue(math.isfinite(v), k)
        # driveline balance recomputed here from the terms (independent of the vehicle's residual)
        sinks = sum(L[k] for k in ("aux_steering", "aux_pneumatic", "aux_electric", "aux_hvac", "fan",
                                   "gearbox_drag", "converter", "gear_load", "retarder", "axle",
                                   "shift", "rolling", "aero", "grade", "friction_brakes",
                                   "kinetic_change"))
        self.assertGreater(L["crank_engine"], 0.01)
        self.assertLess(abs(L["crank_engine"] + L["crank_em"] - sinks), 1e-3 * L["crank_engine"])
        self.assertLess(s["energy_ledger_closure"], 1e-3)
        # aux consumers add up to the aux work the vehicle booked
        self.assertAlmostEqual(L["aux_steering"] + L["aux_pneumatic"] + L["aux_electric"] + L["aux_hvac"] + L["fan"],
                               L["aux_total"], delta=1e-9 + 1e-9 * L["aux_total"])
        # fuel: the engine's coolant heat and brake work are each a part of the fuel energy
        self.assertGreater(L["engine_heat_to_coolant"], 0.0)
        self.assertGreater(L["engine_exhaust_and_other"], 0.0)
        # the engine's brake work and its coolant heat cannot exceed the fuel's energy
        self.assertLess(L["engine_net"] + L["engine_heat_to_coolant"], L["fuel_chemical"])
        # the engine's own work and the work the driveline received differ by the exchange delay only
        self.assertLess(abs(L["coupling_delay"]), 0.01 * L["crank_engine"])
        # fuel and time by operating state add up to the totals
        self.assertAlmostEqual(sum(s["fuel_by_state_kg"].values()), s["fuel_kg"], delta=1e-12)
        self.assertAlmostEqual(sum(s["time_by_state_s"].values()), UNTIL, delta=1e-6)
        self.assertGreater(s["fuel_by_state_kg"]["idle_at_stop"], 0.0)  # the mission starts at a stop
        self.assertGreater(s["fuel_by_state_kg"]["traction"], 0.0)
        with open(os.path.join(out, "report.md")) as f:
            rep = f.read()
        self.assertIn("## Energy ledger", rep)
        self.assertTrue(os.path.exists(os.path.join(out, "energy_ledger.png")))
        self.assertTrue(os.path.exists(os.path.join(out, "operating_map.png")))
        # the same report from the bag alone (scripts/twin report) is identical
        again = os.path.join(self.tmp, "from_bag")
        r = subprocess.run(["/usr/bin/python3", "-m", "twin_tools.report.postprocess",
                            "--bag", os.path.join(out, "run.bag"), again], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        for f in ("summary.json", "report.md"):
            with open(os.path.join(out, f)) as a, open(os.path.join(again, f)) as b:
                self.assertEqual(a.read(), b.read(), f)


class Failures(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="hbt_fail_")

    def config_copy(self, edit_file=None, edit=None):
        cfg = os.path.join(self.tmp, "config")
        shutil.copytree(os.path.join(REPO, "config"), cfg, ignore=shutil.ignore_patterns("data"))
        os.symlink(os.path.join(REPO, "config", "data"), os.path.join(cfg, "data"))
        if edit_file:
            p = os.path.join(cfg, edit_file)
            with open(p) as f:
                text = f.read()
            with open(p, "w") as f:
                f.write(edit(text))
        return cfg

    def expect_rejected(self, file_part, key_part, **args):
        out = os.path.join(self.tmp, "out")
        st = run_util.run_launch(LAUNCH, out, until=5.0, **args)
        self.assertEqual(st["status"], "error", st)
        self.assertEqual(st["steps"], 0, "rejected before the first step")
        self.assertIn(file_part, st["message"])
        self.assertIn(key_part, st["message"])

    def write_cycle(self, text):
        p = os.path.join(self.tmp, "bad.vdri")
        with open(p, "w") as f:
            f.write(text)
        return p

    def test_missing_cycle_file(self):
        self.expect_rejected("nonexistent.vdri", "(file)", cycle_file=os.path.join(self.tmp, "nonexistent.vdri"))

    def test_malformed_cycle(self):
        p = self.write_cycle("<s>,<v>,<grad>,<stop>\n0,0,0,10\n100,abc,0,0\n")
        self.expect_rejected("bad.vdri", "'v'", cycle_file=p)

    def test_truncated_cycle(self):
        p = self.write_cycle("<s>,<v>,<grad>,<stop>\n0,0,0,10\n100,30,0,0\n200,30\n")
        self.expect_rejected("bad.vdri", "line 4", cycle_file=p)

    def test_nan_in_cycle(self):
        p = self.write_cycle("<s>,<v>,<grad>,<stop>\n0,0,0,10\n100,nan,0,0\n")
        self.expect_rejected("bad.vdri", "'v'", cycle_file=p)

    def test_negative_mass(self):
        cfg = self.config_copy("vehicle.yaml", lambda t: t.replace("curb_mass_kg: 15160.0", "curb_mass_kg: -15160.0", 1))
        self.expect_rejected("vehicle.yaml", "chassis/curb_mass_kg", config=cfg)

    def test_unknown_key(self):
        cfg = self.config_copy("engine_map.yaml", lambda t: t + "\nfuel_lhv_j_per_kg: 42.7e6\n")
        self.expect_rejected("engine_map.yaml", "fuel_lhv_j_per_kg", config=cfg)

    def test_one_idle_speed(self):
        """The idle speed is defined once, in engine_map.yaml: 750 rpm there moves the engine's
        start, the vehicle's crank and the idle governor's set point together; the vehicle's
        resolved configuration names that file; without the key the run stops naming it."""
        import math
        import rosbag
        w = 750.0 * math.pi / 30.0
        cfg = self.config_copy("engine_map.yaml", lambda t: t.replace("idle_speed_rad_s: 73.3038",
                                                                       "idle_speed_rad_s: %.6f" % w))
        out = os.path.join(self.tmp, "idle750")
        st = run_util.run_launch(LAUNCH, out, until=5.0, config=cfg, record_period=0)
        self.assertEqual(st["status"], "ok", st)
        with rosbag.Bag(os.path.join(out, "run.bag")) as b:
            v0 = next(m for _, m, _ in b.read_messages(topics=["/vehicle/state"]))
            e0 = next(m for _, m, _ in b.read_messages(topics=["/engine/state"]))
            v_end = None
            for _, v_end, _ in b.read_messages(topics=["/vehicle/state"]):
                pass
        self.assertAlmostEqual(v0.engine_speed_rad_s, w, places=5)
        self.assertAlmostEqual(e0.engine_speed_rad_s, w, places=5)
        self.assertAlmostEqual(v_end.engine_speed_rad_s, w, delta=3.0)  # the governor holds it (at rest)
        with open(os.path.join(out, "resolved_config", "vehicle.csv")) as f:
            self.assertIn("engine_map.yaml,idle_speed_rad_s,%.6f" % w, f.read())
        shutil.rmtree(os.path.join(self.tmp, "config"))
        cfg = self.config_copy("engine_map.yaml", lambda t: t.replace("idle_speed_rad_s: 73.3038", ""))
        self.expect_rejected("engine_map.yaml", "idle_speed_rad_s", config=cfg)

    def test_nan_parameter(self):
        cfg = self.config_copy("engine_map.yaml", lambda t: t.replace("volumetric_efficiency: 0.90", "volumetric_efficiency: .nan", 1))
        self.expect_rejected("engine_map.yaml", "volumetric_efficiency", config=cfg)

    def test_bad_macro_step(self):
        cfg = self.config_copy("engine_map.yaml", lambda t: t + "\ncosim:\n  macro_step_s: 0.015\n")
        self.expect_rejected("engine_map.yaml", "cosim/macro_step_s", config=cfg)

    def test_bad_thread_name(self):
        # a participant's own YAML key (the thermal nodes' thread is the scenario's: thermal_thread)
        cfg = self.config_copy("engine_map.yaml", lambda t: t + "\ncosim:\n  thread: 'the rmal'\n")
        self.expect_rejected("engine_map.yaml", "cosim/thread", config=cfg)

    def test_unknown_engine_model(self):
        """The scenario's engine model (launch argument engine, /scenario/engine_model) is map | 1d:
        anything else stops the run before the first step naming the argument (here with a YAML
        for it present)."""
        cfg = self.config_copy()
        shutil.copy(os.path.join(cfg, "engine_map.yaml"), os.path.join(cfg, "engine_v8.yaml"))
        self.expect_rejected("engine", "launch argument engine): key 'engine_model': 'v8' is not an engine model: map | 1d",
                             config=cfg, engine="v8")

    def test_bad_order(self):
        self.expect_rejected("stepper", "'order'", order="[[vehicle], [engine], [vehicle]]")

    def test_chain_length_changes_neither_delay_nor_result(self):
        """Map engine: the torque chain vehicle -> engine has no macro-step delay (the engine steps
        on the speed commanded for that very step) and the run is the same bag whether the
        thermal nodes after it form one group or two (data-driven stepping: groups order the
        reads, not the wall-clock work)."""
        run_util.assert_chain_length(self, LAUNCH, self.tmp, 20.0, 2000)

    def test_multirate_ordered_run(self):
        """The engine at 20 ms (its YAML's cosim/ key passes the model's unknown-key check),
        vehicle then engine (Gauss-Seidel): the run completes, recorded every 10 ms."""
        cfg = self.config_copy("engine_map.yaml", lambda t: t + "\ncosim:\n  macro_step_s: 0.02\n")
        out = os.path.join(self.tmp, "mr")
        st = run_util.run_launch(LAUNCH, out, until=5.0, config=cfg, order="[[vehicle], [engine], [aftertreatment, cooling, hvac]]",
                                 record_period=0.01)
        self.assertEqual(st["status"], "ok", st)
        self.assertEqual(st["steps"], 500)
        import struct
        got = []
        for topic, t, raw in run_util.bag_messages(os.path.join(out, "run.bag")):
            if topic == "/engine/state":
                sec, nsec = struct.unpack("<II", raw[4:12])  # std_msgs/Header: seq, stamp
                got.append((t, sec * 10**9 + nsec))
        ms = 1000000
        # the engine's state held between its steps: stamped floor(t / 20 ms) * 20 ms
        self.assertEqual(got, [(max(1, i * 10 * ms), i * 10 * ms // (20 * ms) * 20 * ms) for i in range(501)])


if __name__ == "__main__":
    unittest.main(verbosity=2)
