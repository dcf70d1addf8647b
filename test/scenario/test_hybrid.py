#!/usr/bin/python3
"""Scenario tests of hybrid_urban (48 V P1: vehicle -> EMS -> engine + e-machine -> battery, with
the aftertreatment and cooling nodes) on short stretches of the Urban mission:
nodes and nodelets give bit-identical bags; the torque chain vehicle -> EMS -> e-machine adds no
macro-step delay (Gauss-Seidel groups); the e-machine never exceeds its live (derated) limits and
the EMS never boosts or stops the engine while the engine/ATS warm up; the electric path (battery
terminal = e-machine DC + DC/DC + the pack's fan) and the battery and e-machine balances close; the LT circuit is
fed by the e-machine's heat; from a warm start (start:=warm) the engine stops at standstill, is
restarted by the e-machine, the bus still serves its stops, the one-box cools without flow and
doses nothing, and nodes = nodelets bit for bit over those warm engine stops."""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

from twin_tools.launch import run_util

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

LAUNCH = os.path.join(REPO, "launch", "hybrid_urban.launch")
UNTIL = 40.0
WARM_UNTIL = 150.0
MODE_BOOST, MODE_REGEN, MODE_STOPPED, MODE_CRANKING = 1, 2, 4, 5


def by_stamp(bag, topics):
    import rosbag
    out = {t: {} for t in topics}
    with rosbag.Bag(bag) as b:
        for topic, m, _ in b.read_messages(topics=topics):
            out[topic][m.header.stamp.to_nsec()] = m
    return out


def summarise(out, *args):
    """summary.json of a run, with its launch arguments (name:=value) as `twin run` passes them."""
    r = subprocess.run(["/usr/bin/python3", "-m", "twin_tools.report.postprocess", out,
                        "--scenario", "hybrid_urban"] + list(args), capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


class Hybrid(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_hybrid_")
        cls.runs = {}
        for name, mode in (("nodes", "nodes"), ("nodelets", "nodelets")):
            out = os.path.join(cls.tmp, name)
            st = run_util.run_launch(LAUNCH, out, mode=mode, until=UNTIL, record_period=0, timeout=10.0)
            cls.runs[name] = (out, st)
        # warm start (start:=warm, a bus mid-shift): stop-start and boost act from the first stop;
        # in both modes, so that nodes = nodelets is checked over warm engine stops too
        cls.warm = {}
        for mode in ("nodes", "nodelets"):
            out = os.path.join(cls.tmp, "warm_" + mode)
            cls.warm[mode] = (out, run_util.run_launch(LAUNCH, out, mode=mode, until=WARM_UNTIL, start="warm",
                                                       timeout=10.0))

    def test_runs_complete_and_modes_bit_identical(self):
        for name, (out, st) in list(self.runs.items()) + [("warm_" + m, r) for m, r in self.warm.items()]:
            self.assertEqual(st["status"], "ok", (name, st))
        for runs in (self.runs, self.warm):
            a = run_util.bag_messages(os.path.join(runs["nodes"][0], "run.bag"))
            b = run_util.bag_messages(os.path.join(runs["nodelets"][0], "run.bag"))
            self.assertEqual(a, b)

    def test_torque_chain_has_no_macro_step_delay(self):
        """Groups [vehicle, ...], [ems], [engine, emachine], [battery]: the e-machine and the
        engine step on the EMS's command stamped like their own output (fresh), the EMS on the
        vehicle's demand of the same stamp, the battery on the e-machine's power of the same stamp."""
        bag = os.path.join(self.runs["nodes"][0], "run.bag")
        d = by_stamp(bag, ["/ems/command", "/emachine/state", "/ems/engine_command", "/vehicle/driver_demand",
                           "/battery/state"])
        n = 0
        for t, m in d["/emachine/state"].items():
            if t == 0:
                continue
            c = d["/ems/command"][t]
            self.assertEqual(m.torque_request_nm, c.em_torque_request_nm, t)
            self.assertEqual(c.engine_speed_rad_s, d["/vehicle/driver_demand"][t].engine_speed_rad_s, t)
            bs = d["/battery/state"][t]  # request = e-machine DC + DC/DC + the pack's own fan
            self.assertAlmostEqual(bs.request_w - bs.dcdc_power_w - bs.fan_power_w,
                                   m.electrical_power_w, delta=1e-9 * (1.0 + abs(m.electrical_power_w)), msg=t)
            n += 1
        self.assertGreater(n, 3000)

    def test_live_limits_and_warmup_inhibit(self):
        bag = os.path.join(self.runs["nodes"][0], "run.bag")
        d = by_stamp(bag, ["/emachine/state", "/ems/command"])
        em = d["/emachine/state"]
        ts = sorted(em)
        for a, b in zip(ts[:-1], ts[1:]):  # the limits published at t bound the torque of the next step
            self.assertLessEqual(em[b].torque_nm, em[a].torque_max_nm + 1e-9, b)
            self.assertGreaterEqual(em[b].torque_nm, em[a].torque_min_nm - 1e-9, b)
        modes = {m.mode for m in d["/ems/command"].values()}
        self.assertNotIn(MODE_BOOST, modes)  # a cold start at 25 degC: still warming up
        self.assertNotIn(MODE_STOPPED, modes)
        self.assertTrue(all(not m.warm for m in d["/ems/command"].values()))
        self.assertIn(MODE_REGEN, modes)

    def test_balances_close(self):
        out = os.path.join(self.tmp, "summary")
        shutil.copytree(self.runs["nodes"][0], out)
        s = summarise(out)
        self.assertLess(s["electric_path_closure"], 0.01)
        self.assertLess(s["battery_balance_closure"], 1e-6)
        self.assertLess(s["em_balance_closure"], 1e-6)
        self.assertLess(s["energy_ledger_closure"], 1e-3)
        self.assertGreater(s["em_brake_kwh"], 0.0)
        # the EMS asked nothing beyond the live limits of the e-machine and the battery
        self.assertEqual(s["em_clamped_s"], 0.0)
        self.assertEqual(s["battery_limited_s"], 0.0)
        L = s["energy_kwh"]
        # e-machine: its crank work + losses = DC energy (independently booked by its own node)
        self.assertAlmostEqual(L["em_motoring"] + L["em_generating"] + L["em_losses"], L["em_dc"],
                               delta=1e-3 * abs(L["em_dc"]) + 1e-9)

    def test_lt_circuit_fed_by_the_emachine(self):
        bag = os.path.join(self.runs["nodes"][0], "run.bag")
        d = by_stamp(bag, ["/emachine/state", "/cooling/state"])
        n = 0
        for t, c in d["/cooling/state"].items():
            if t < 2 * 10**8:
                continue
            # the mean LT heat of the e-machine's last 0.1 s before the cooling node's step start
            e0, e1 = d["/emachine/state"][t - 2 * 10**8], d["/emachine/state"][t - 10**8]
            self.assertAlmostEqual(c.lt_heat_w, (e1.heat_to_coolant_energy_j - e0.heat_to_coolant_energy_j) / 0.1,
                                   delta=1e-6 * (1.0 + abs(c.lt_heat_w)), msg=t)
            n += 1
        self.assertGreater(n, 300)
        self.assertGreater(max(c.lt_heat_w for c in d["/cooling/state"].values()), 0.0)

    def test_stop_start_when_warm(self):
        out, st = self.warm["nodelets"]
        self.assertEqual(st["status"], "ok", st)
        s = summarise(out, "start:=warm")
        self.assertEqual(s["start"], "warm")
        self.assertEqual(s["warmup_inhibit_s"], 0.0)  # warm from t = 0
        self.assertGreater(s["engine_off_s"], 5.0)
        self.assertGreaterEqual(s["engine_starts"], 2)  # warm engine stops, each restarted
        self.assertGreater(s["em_boost_kwh"], 0.0)
        self.assertEqual(s["stops_served"], s["stops_total"])
        self.assertEqual(s["battery_limited_s"], 0.0)
        self.assertLess(s["electric_path_closure"], 0.01)
        self.assertLess(s["ats_balance_closure"], 1e-9)
        self.assertLess(s["cooling_balance_closure"], 1e-9)
        self.assertEqual(s["warnings"], [])
        d = by_stamp(os.path.join(out, "run.bag"), ["/ems/command", "/engine/state", "/vehicle/state",
                                                    "/engine/exhaust", "/aftertreatment/state"])
        off = sorted(t for t, c in d["/ems/command"].items() if c.mode == MODE_STOPPED)
        self.assertGreater(len(off), 10)
        for t in off:  # the engine burns nothing while stopped, its crank comes to rest
            if t in d["/engine/state"]:
                self.assertEqual(d["/engine/state"][t].fuel_mass_flow_kg_s, 0.0, t)
        self.assertLess(min(d["/vehicle/state"][t].engine_speed_rad_s for t in off if t in d["/vehicle/state"]), 1.0)
        # the warm one-box at an engine stop: no flow, no dosing, the SCR cools, every input physical
        ats = d["/aftertreatment/state"]
        stops, run = [], []  # contiguous stretches of recorded stopped samples
        for t in off:
            if t not in ats:
                continue
            if run and t - run[-1] > 10**8:
                stops.append(run)
                run = []
            run.append(t)
        stops.append(run)
        stops = [r for r in stops if r[-1] - r[0] >= 5 * 10**9]
        self.assertGreaterEqual(len(stops), 1)
        for r in stops:  # over a stop of >= 5 s the SCR ends cooler than it began (can loss only)
            self.assertLess(ats[r[-1]].scr_temperature_k, ats[r[0]].scr_temperature_k, r[0])
            for t in r[10:]:  # past the first second (spin-down flow): no dosing
                self.assertEqual(ats[t].urea_mass_flow_kg_s, 0.0, t)
                self.assertGreater(ats[t].scr_temperature_k, 273.15 + 25.0, t)
        for t, x in d["/engine/exhaust"].items():
            self.assertGreater(x.temperature_k, 250.0, t)


if __name__ == "__main__":
    unittest.main()
