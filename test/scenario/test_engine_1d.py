#!/usr/bin/python3
"""baseline_urban with engine:=1d on the first seconds of the Urban mission (the full mission is
in `scripts/twin bench 1d`): the crank-angle 1D engine coupled to the vehicle through the step
protocol. Checks: the run completes; every output is finite; the brake work the engine reports
equals the work the vehicle's driveline received (1 %); the mean efficiency of the fuel is
plausible; engine-out NOx is produced; the solver is selectable (fsm and tvd both run); the idle
after the first bus stop (t = 51.5 s) settles (within 1 s, not the ~4 s oscillation of a trim
that integrates the engine's response time); nodes and
nodelets give the same bag."""
import math
import os
import re
import shutil
import tempfile
import unittest

from twin_tools.launch import run_util
from twin_tools.units import DIESEL_LHV_J_KG

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

LAUNCH = os.path.join(REPO, "launch", "baseline_urban.launch")


def messages(bag, topic):
    import rosbag
    with rosbag.Bag(bag) as b:
        return [m for _, m, _ in b.read_messages(topics=[topic])]


class Engine1DScenario(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_1d_")
        cls.runs = {}
        # fsm past t = 40 s: a cylinder's unburned zone empties there (zone-merge regression);
        # to 57 s: the first bus stop (neutral at standstill 51.5-57.0 s)
        # fsm_nodes: the first 10 s again, as separate processes (TCP), window 1
        for name, solver, until, mode, window in (("fsm", "fsm", 57.0, "nodelets", 50),
                                                  ("tvd", "tvd", 3.0, "nodelets", 50),
                                                  ("fsm_nodes", "fsm", 10.0, "nodes", 1)):
            out = os.path.join(cls.tmp, name)
            st = run_util.run_launch(LAUNCH, out, engine="1d", solver=solver, until=until,
                                     timeout=20.0, record_period=0, mode=mode, window_steps=window)
            cls.runs[name] = (out, st, until)

    def test_runs_complete(self):
        for solver, (out, st, until) in self.runs.items():
            self.assertEqual(st["status"], "ok", (solver, st))
            self.assertAlmostEqual(st["sim_time_s"], until, places=9)

    def test_chain_length_changes_neither_delay_nor_result(self):
        """1D engine: as for the map engine (test_baseline), the torque chain vehicle -> engine has
        no macro-step delay and one or two groups of thermal nodes after it give the same bag."""
        run_util.assert_chain_length(self, LAUNCH, self.tmp, 5.0, 500, engine="1d")

    def test_nodes_and_nodelets_bit_identical(self):
        """The crank-angle engine gives the same bag as nodes and as nodelets (different report
        windows too): nothing of wall time reaches run.bag (the engine's own thread CPU is in
        /diagnostics only)."""
        a = run_util.bag_messages(os.path.join(self.runs["fsm_nodes"][0], "run.bag"))
        b = [m for m in run_util.bag_messages(os.path.join(self.runs["fsm"][0], "run.bag"))
             if m[1] <= 10 * 10**9 and m[0] != "/twin/run_info"]
        a = [m for m in a if m[0] != "/twin/run_info"]
        self.assertGreater(len(a), 8000)
        self.assertEqual(a, b)  # the shorter run's end state (written at close) included

    def test_outputs_finite_and_physical(self):
        out = self.runs["fsm"][0]
        bag = os.path.join(out, "run.bag")
        eng = messages(bag, "/engine/state")
        exh = messages(bag, "/engine/exhaust")
        self.assertEqual(len(eng), 5701)
        for m in eng:
            for f in m.__slots__:
                v = getattr(m, f)
                if isinstance(v, float):
                    self.assertTrue(math.isfinite(v), (f, m.header.stamp.to_sec()))
        # (t = 0 is the state before the first engine cycle: no flow through the turbine yet)
        self.assertTrue(all(m.mass_flow_kg_s > 0 and 250 < m.temperature_k < 1200 for m in exh[1:]))
        self.assertGreater(exh[-1].nox_mass_kg, 0.0)
        # idle at t = 0..12 s: the engine holds ~700 rpm under the vehicle's idle governor
        idle = [m.engine_speed_rad_s * 60 / (2 * math.pi) for m in eng if 5.0 < m.header.stamp.to_sec() < 12.0]
        self.assertLess(max(abs(n - 700.0) for n in idle), 30.0)

    def test_idle_settles_after_the_first_stop(self):
        # from the standstill-neutral shift: speed within +-10 rpm of 700 and brake torque within
        # +-10 Nm of its last-second mean within 1 s (map engine: 0.48 s; 1D before the fix ~4 s,
        # -64..255 Nm); the torque never dips towards motoring
        bag = os.path.join(self.runs["fsm"][0], "run.bag")
        veh = messages(bag, "/vehicle/state")
        tq = {round(m.header.stamp.to_sec(), 2): m.brake_torque_nm for m in messages(bag, "/engine/state")}
        t0 = next(m.header.stamp.to_sec() for m in veh
                  if m.header.stamp.to_sec() > 45.0 and m.drive_mode == 0 and m.speed_m_s == 0.0)
        neutral = [(m.header.stamp.to_sec(), m.engine_speed_rad_s * 60 / (2 * math.pi),
                    tq[round(m.header.stamp.to_sec(), 2)]) for m in veh
                   if m.header.stamp.to_sec() >= t0 and m.drive_mode == 0]
        self.assertGreater(neutral[-1][0] - t0, 5.0)
        final = sum(T for t, _, T in neutral if t > neutral[-1][0] - 1.0) / \
            len([1 for t, _, _ in neutral if t > neutral[-1][0] - 1.0])
        late = [t - t0 for t, n, T in neutral if abs(n - 700.0) > 10.0 or abs(T - final) > 10.0]
        settle = (max(late) + 0.01) if late else 0.0
        print("1D idle after the first stop: settling %.2f s, %.1f-%.1f rpm, %.1f-%.1f Nm" % (
            settle, min(n for _, n, _ in neutral), max(n for _, n, _ in neutral),
            min(T for _, _, T in neutral), max(T for _, _, T in neutral)))
        self.assertLess(settle, 1.0)
        self.assertGreater(min(T for _, _, T in neutral), 20.0)

    def test_energy_consistency(self):
        bag = os.path.join(self.runs["fsm"][0], "run.bag")
        v = messages(bag, "/vehicle/state")[-1]
        e = messages(bag, "/engine/state")[-1]
        engine_work = e.positive_work_j + e.motoring_work_j
        self.assertGreater(v.engine_work_j, 5e4)
        self.assertAlmostEqual(engine_work / v.engine_work_j, 1.0, delta=0.01)
        eff = e.positive_work_j / (e.fuel_mass_kg * DIESEL_LHV_J_KG)
        self.assertGreater(eff, 0.05)
        self.assertLess(eff, 0.46)


class Engine1DLoops(unittest.TestCase):
    """The 1D engine's loops close: over the same 20 s (idle, then the first acceleration; the same driver demand, the idle
    governor's), a higher exhaust back-pressure from the ATS (DPF soot from the shipped load to 10 g/L) raises the
    fuel (more pumping work), and a cold coolant (cold start at 25 degC, the cooling node) burns
    more than the warm defaults of an engine without thermal nodes (oil-viscosity friction)."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_1d_loops_")
        cfg = os.path.join(cls.tmp, "config")
        shutil.copytree(os.path.join(REPO, "config"), cfg, ignore=shutil.ignore_patterns("data"))
        os.symlink(os.path.join(REPO, "config", "data"), os.path.join(cfg, "data"))
        p = os.path.join(cfg, "aftertreatment.yaml")
        with open(p) as f:
            text = f.read()
        loaded, n = re.subn(r"^(\s*soot_load_g_L:)\s*[0-9.eE+-]+", r"\1 10.0", text, count=1, flags=re.M)
        assert n == 1, "dpf_flow/soot_load_g_L not found in %s" % p
        with open(p, "w") as f:
            f.write(loaded)
        cls.runs = {}
        for name, args in (("base", {}), ("soot", {"config": cfg}), ("warm", {"thermal": "false"})):
            out = os.path.join(cls.tmp, name)
            st = run_util.run_launch(LAUNCH, out, engine="1d", until=20.0, timeout=20.0, **args)
            cls.runs[name] = (out, st)

    def last(self, name, topic):
        return messages(os.path.join(self.runs[name][0], "run.bag"), topic)[-1]

    def test_back_pressure_raises_fuel(self):
        for n, (_, st) in self.runs.items():
            self.assertEqual(st["status"], "ok", (n, st))
        a, b = self.last("base", "/engine/state"), self.last("soot", "/engine/state")
        self.assertGreater(b.back_pressure_pa, a.back_pressure_pa + 300.0)
        # fuel per positive brake work (the pumping loss): measured +0.11 %. Fuel over the fixed
        # 20 s also depends on the work delivered, which the 1D torque trim gives after the
        # engine's response time, without an overshoot: -0.03 % there.
        ratio = (b.fuel_mass_kg / b.positive_work_j) / (a.fuel_mass_kg / a.positive_work_j)
        self.assertGreater(ratio, 1.0004)

    def test_cold_coolant_raises_fuel(self):
        a, w = self.last("base", "/engine/state"), self.last("warm", "/engine/state")
        self.assertLess(a.coolant_temperature_k, 310.0)  # still cold after 20 s
        self.assertEqual(w.coolant_temperature_k, 0.0)   # no cooling node: warm default used
        self.assertGreater(a.fuel_mass_kg, w.fuel_mass_kg * 1.05)


if __name__ == "__main__":
    unittest.main(verbosity=2)
