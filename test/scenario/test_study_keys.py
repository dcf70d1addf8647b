#!/usr/bin/python3
"""The study's summary keys and checks on constructed traces with known answers (no ROS):
coolant_warm_s is the first time the HT coolant reaches the EMS's threshold (config/ems.yaml);
the SCR at standstill is the time mean and minimum of the brick over standing samples after the
light-off; the study checks fail a hybrid that never restarted or whose request was clamped."""
import unittest

import numpy as np
import yaml

from twin_tools.bench import study
from twin_tools.paths import REPO
from twin_tools.report import thermal


class StudyKeys(unittest.TestCase):
    def test_warm_threshold_is_the_ems_one(self):
        with open(REPO + "/config/ems.yaml") as f:
            self.assertEqual(thermal.coolant_warm_K(), yaml.safe_load(f)["warmup"]["coolant_warm_K"])

    def test_first_time_at_or_above(self):
        t = np.arange(0.0, 100.0, 0.1)
        x = 273.15 + t  # 1 K/s from 0 degC: 70 degC at t = 70 s
        self.assertAlmostEqual(thermal.first_time_at_or_above(t, x, 343.15), 70.0, places=9)
        self.assertIsNone(thermal.first_time_at_or_above(t, x, 400.0))

    def test_oil_warm_time_and_oil_heat_in_the_cooling_balance(self):
        t = np.arange(0.0, 200.0, 0.1)
        n = len(t)
        cool = {"t": t, "oil_temperature_k": 273.15 + t,  # 1 K/s from 0 degC: 80 degC at t = 80 s
                "coolant_ht_temperature_k": np.full(n, 300.0), "warmup_time_s": np.full(n, -1.0),
                "fan_drive_energy_j": np.zeros(n), "pump_energy_j": np.zeros(n),
                "engine_heat_j": np.full(n, 3.0e6), "engine_oil_heat_j": np.full(n, 1.0e6),
                "lt_heat_j": np.zeros(n), "energy_residual_j": np.full(n, 4.0)}
        s = thermal.thermal_summary({thermal.COOLING_STATE: cool})
        self.assertAlmostEqual(s["oil_80c_s"], thermal.OIL_WARM_K - 273.15, places=9)
        self.assertAlmostEqual(s["cooling_balance_closure"], 4.0 / 4.0e6, places=15)  # metal + oil heat in

    def test_standstill_scr_mean_and_min(self):
        t = np.arange(0.0, 40.0, 0.1)
        ats = {"t": t, "scr_temperature_k": 500.0 - t}  # cools at 1 K/s
        speed = np.where((t >= 10.0) & (t < 20.0), 0.0, 5.0)  # stands from 10 to 20 s
        veh = {"t": t, "speed_m_s": speed}
        mean, lo = thermal.standstill_scr(ats, veh, after_s=0.0)
        # samples 10.0 ... 19.9 s stand: brick 490 ... 480.1 K, interval-weighted by the step ending there
        self.assertAlmostEqual(mean, np.mean(500.0 - t[(t >= 10.0 - 1e-9) & (t < 20.0 - 1e-9)]), places=9)
        self.assertAlmostEqual(lo, 500.0 - 19.9, places=9)
        self.assertIsNone(thermal.standstill_scr(ats, veh, after_s=30.0))  # never stands after 30 s

    def test_study_checks_fail_what_they_should(self):
        good = {"stops_served": 121, "stops_total": 121, "engine_starts": 80, "em_clamped_s": 0.0,
                "battery_limited_s": 0.0}
        runs = {("map", 25, "", "hybrid_urban"): ("out", dict(good)),
                ("1d", 25, "", "hybrid_urban"): ("out", dict(good, engine_starts=0)),
                ("1d", 0, "", "hybrid_urban"): ("out", dict(good, em_clamped_s=0.5)),
                ("1d", 40, "", "baseline_urban"): ("out", dict(good, stops_served=120)),
                ("map", 0, "", "baseline_urban"): ("out", None)}
        failed = sorted(what for what, ok in study.study_checks(runs) if not ok)
        self.assertEqual(len(failed), 4, failed)
        self.assertTrue(any("0 engine starts" in f for f in failed))
        self.assertTrue(any("em_clamped_s 0.5" in f for f in failed))
        self.assertTrue(any("120/121" in f for f in failed))
        self.assertTrue(any("ended ok" in f for f in failed))


if __name__ == "__main__":
    unittest.main()
