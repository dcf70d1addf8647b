#!/usr/bin/python3
"""The product's scenarios run to the end: baseline_urban and hybrid_urban with the map engine,
as nodelets, the whole VECTO Urban mission at 0 and 40 degC (twin_tools.references:
SUITE_MISSIONS; 25 degC too with `scripts/twin references`), two at a time. Each asserts the
mission invariants against what is independent of the run: the run ended "end of mission" at the cycle's last second; 121/121 stops served; the
distance the cycle file gives; every balance of the summary closed (closure < 1e-9); no warning
but the stored cold-SCR ones (from a cold start the exhaust line's steel delays the SCR's
light-off past the warning's 300 s grace at every ambient, and at 0 degC the SCR also falls
below light-off in the slow urban stretch). The hybrid also: the engine stopped and
was restarted by the e-machine, SOC stayed inside the battery's window, the EMS never asked
beyond the e-machine's or the battery's live limits (em_clamped_s = battery_limited_s = 0), and its SOC-corrected
fuel is below the baseline's at the same ambient. The hvac (on by default): fuel_kg = engine +
fuel-fired heater, the heater's fuel x LHV x efficiency = its heat into the coolant, the heater
burns at 0 degC and not at 40 degC, the A/C cools at 40 degC and not at 0 degC, the cabin's
temperature finite and within its bounds (its balance closes with the others). Finally each summary equals the stored one
(test/scenario/reference/missions) within mission_reference.REL_TOL."""
import os
import shutil
import tempfile
import unittest

import yaml

from twin_tools import references as mr
from twin_tools.units import DIESEL_LHV_J_KG

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

CLOSURE_BOUND = 1e-9
STOP_POSITION_TOL_KM = 0.01  # a stop is served within metres of its position (stop_service/)


def cycle_end(path):
    """(last distance [m], number of stops) of a VECTO .vdri distance-based cycle: the columns
    <s>,<v>,<grad>,<stop>; a stop is a row with a stop time > 0."""
    s_last, stops = 0.0, 0
    with open(path) as f:
        for line in f:
            parts = [p.strip() for p in line.split(",")]
            if len(parts) < 4 or not parts[0] or parts[0].startswith("<") or parts[0].startswith("#"):
                continue
            s_last = float(parts[0])
            stops += float(parts[3]) > 0.0
    return s_last, stops


def config(name):
    with open(os.path.join(REPO, "config", name)) as f:
        return yaml.safe_load(f)


class Missions(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_missions_")
        cls.results = mr.run_all(mr.SUITE_MISSIONS, cls.tmp, jobs=2)
        cls.distance_m, cls.stops = cycle_end(
            os.path.join(REPO, "config", "data", "cycles", "vecto", "Urban.vdri"))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def each(self):
        """(name, scenario, ambient, summary) of every mission, failing on one that did not end."""
        for scenario, ambient in mr.SUITE_MISSIONS:
            n = mr.name(scenario, ambient)
            out, st, summ = self.results[n]
            self.assertEqual(st.get("status"), "ok", "%s: %s" % (n, st.get("message")))
            self.assertIsNotNone(summ, n)
            yield n, scenario, ambient, summ

    def test_every_mission_runs_to_its_end(self):
        for n, scenario, ambient, s in self.each():
            self.assertEqual((s["scenario"], s["ambient_c"], s["start"], s["engine_model"]),
                             (scenario, ambient, "cold", "map"), n)  # the summary says what ran
            st = self.results[n][1]
            self.assertEqual(st["message"], "end of mission", n)
            self.assertGreater(s["sim_time_s"], 8000.0, n)

    def test_every_stop_served_over_the_cycle_distance(self):
        self.assertEqual(self.stops, 121)  # the Urban cycle file itself
        for n, _, _, s in self.each():
            self.assertEqual(s["stops_total"], self.stops, n)
            self.assertEqual(s["stops_served"], self.stops, n)
            self.assertAlmostEqual(s["distance_km"], self.distance_m / 1e3, delta=STOP_POSITION_TOL_KM, msg=n)

    def test_every_balance_closes(self):
        for n, _, _, s in self.each():
            closures = {k: v for k, v in s.items() if k.endswith("_closure")}
            self.assertGreaterEqual(len(closures), 3, n)  # ledger, cooling, aftertreatment (+ hybrid's)
            for k, v in closures.items():
                self.assertLess(abs(v), CLOSURE_BOUND, "%s: %s = %g" % (n, k, v))

    def test_no_warning_but_the_stored_cold_scr(self):
        for n, scenario, ambient, s in self.each():
            got = [(w["node"], w["warning"]) for w in s["warnings"]]
            self.assertEqual(got, [(w["node"], w["warning"]) for w in mr.read_reference(scenario, ambient)["warnings"]], n)
            # only the cold SCR
            self.assertTrue(all(w == ("aftertreatment", "ats_below_light_off") for w in got), (n, got))

    def test_hybrid_stops_and_restarts_its_engine_within_its_soc_window(self):
        limits = config("battery.yaml")["limits"]  # the battery's usable SOC window
        for n, scenario, ambient, s in self.each():
            if scenario != "hybrid_urban":
                continue
            self.assertGreater(s["engine_starts"], 10, n)  # restarted by the e-machine
            # at 40 degC the belt-driven A/C's engine run request keeps the engine running at
            # most stops (src/ems: ClimateRequest)
            self.assertGreater(s["engine_off_s"], 100.0 if ambient >= 40 else 300.0, n)
            self.assertGreater(s["cranking_s"], 0.0, n)
            self.assertGreaterEqual(s["soc_min"], limits["soc_min"], n)
            self.assertLessEqual(s["soc_max"], limits["soc_max"], n)
            # the EMS asks within the live limits of the step it commands
            self.assertEqual(s["em_clamped_s"], 0.0, n)
            self.assertEqual(s["battery_limited_s"], 0.0, n)

    def test_hybrid_corrected_fuel_below_the_baseline_at_each_ambient(self):
        by = {(sc, a): s for _, sc, a, s in self.each()}
        for ambient in mr.SUITE_AMBIENTS_C:
            base, hyb = by[("baseline_urban", ambient)], by[("hybrid_urban", ambient)]
            self.assertLess(hyb["fuel_soc_corrected_kg"], base["fuel_kg"], ambient)

    def test_hvac_heats_in_the_cold_and_cools_in_the_heat(self):
        hv = config("hvac.yaml")
        eta = hv["aux_heater"]["efficiency"]
        set_h = hv["controller"]["heating_setpoint_K"] - 273.15
        set_c = hv["controller"]["cooling_setpoint_K"] - 273.15
        band = hv["diagnostics"]["band_K"]  # cabin_discomfort's band
        for n, _, ambient, s in self.each():
            self.assertAlmostEqual(s["fuel_kg"], s["engine_fuel_kg"] + s["heater_fuel_kg"], delta=1e-12, msg=n)
            self.assertAlmostEqual(s["heater_fuel_kg"] * DIESEL_LHV_J_KG * eta / 3.6e6, s["heater_kwh"],
                                   delta=1e-9 * max(1.0, s["heater_kwh"]), msg=n)
            self.assertAlmostEqual(sum(s["fuel_by_state_kg"].values()), s["fuel_kg"], delta=1e-12, msg=n)
            for k in ("initial", "final", "mean", "min", "max"):
                T = s["cabin_temperature_c_" + k]
                self.assertTrue(min(ambient, set_h) - 1.0 <= T <= max(ambient, set_c) + 1.0, (n, k, T))
            self.assertGreater(s["hvac_kwh"], 0.0, n)
            if s["architecture"] == "conventional":  # the hybrid's 24 V load goes to the DC/DC
                self.assertGreater(s["energy_kwh"]["aux_hvac"], 0.0, n)
            if ambient <= 0:
                self.assertGreater(s["heater_fuel_kg"], 0.0, n)
                self.assertEqual(s["ac_cooling_kwh"], 0.0, n)
                # heated, within the discomfort band of the heating set point (the convectors'
                # capacity G_h (T_coolant - T_cabin) limits it below the set point at 0 degC)
                self.assertGreater(s["cabin_temperature_c_final"], set_h - band, n)
                self.assertGreater(s["cabin_temperature_c_mean"], ambient + 10.0, n)
            else:
                self.assertEqual(s["heater_fuel_kg"], 0.0, n)
                self.assertGreater(s["ac_cooling_kwh"], 0.0, n)
                self.assertLess(s["cabin_temperature_c_final"], set_c + band, n)  # (hybrid: engine off at a stop)

    def test_summaries_equal_the_stored_ones(self):
        for n, scenario, ambient, s in self.each():
            diff = mr.differences(mr.read_reference(scenario, ambient), s)
            self.assertEqual(diff, [], "%s differs from %s (scripts/twin references --update regenerates "
                                       "it on purpose): %s" % (n, mr.reference_path(scenario, ambient), diff))


if __name__ == "__main__":
    unittest.main()
