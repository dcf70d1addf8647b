#!/usr/bin/python3
"""The example participant of docs/adding_a_participant.md, run as a user would add one: the trip
computer (test/example_participant: its folder, one hbt_add_participant call, one launch include,
its YAML, its plugin entry) joins baseline_urban for 240 s, as a nodelet and as a node.

- Its display equals, at every stamp, the definitions (trip_computer.hpp) applied to the engine's
  and the vehicle's states it read (stamped one of its macro steps earlier: the Jacobi rule), with
  the diesel density of src/common/units.hpp.
- It only listens: every other topic of run.bag is bit-identical to the run without it.
- Its warning threshold comes from the diagnostics: section of its YAML (long_idle at 5 s).
- Its wiring is checked before the first step: a topics.yaml declaring another message type stops
  the run naming that file and the key."""
import os
import shutil
import tempfile
import unittest

from twin_tools import units as twin_units
from twin_tools.launch import run_util
from twin_tools.paths import REPO
from twin_tools.report.diagnostics import read_diagnostics

EXAMPLE = os.path.join(REPO, "test", "example_participant")
LAUNCH = os.path.join(EXAMPLE, "trip_computer.launch")
BASELINE = os.path.join(REPO, "launch", "baseline_urban.launch")
UNTIL = 240.0
P_NS = 100_000_000  # the trip computer's macro step (trip_computer.yaml cosim/macro_step_s 0.1 s)
IDLE_S = 5.0


def messages(bag_path, topics):
    import rosbag
    out = {t: {} for t in topics}
    with rosbag.Bag(bag_path) as b:
        for topic, m, _ in b.read_messages(topics=topics):
            out[topic][m.header.stamp.to_nsec()] = m
    return out


class ExampleParticipant(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_example_")
        # its YAML with the idle warning at 5 s (the shipped 120 s is longer than any Urban stop)
        cls.yaml = os.path.join(cls.tmp, "trip_computer.yaml")
        with open(os.path.join(EXAMPLE, "trip_computer.yaml")) as f:
            text = f.read()
        assert "idle_s: 120.0" in text
        with open(cls.yaml, "w") as f:
            f.write(text.replace("idle_s: 120.0", "idle_s: %.1f" % IDLE_S))
        cls.runs = {}
        for mode in ("nodelets", "nodes"):
            out = os.path.join(cls.tmp, mode)
            cls.runs[mode] = (out, run_util.run_launch(LAUNCH, out, mode=mode, until=UNTIL, record_period=0,
                                                       timeout=10.0, trip_computer_config=cls.yaml))
        cls.without = os.path.join(cls.tmp, "without")
        cls.without_status = run_util.run_launch(BASELINE, cls.without, until=UNTIL, record_period=0, timeout=10.0)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_runs_complete_with_the_participant(self):
        for mode, (out, st) in self.runs.items():
            self.assertEqual(st["status"], "ok", (mode, st))
            self.assertIn("trip_computer", st["compute_time_s"], mode)
        self.assertEqual(self.without_status["status"], "ok", self.without_status)

    def test_display_follows_its_definitions_from_what_it_read(self):
        rho_kg_l = twin_units.DIESEL_DENSITY_KG_L
        for mode, (out, _) in self.runs.items():
            m = messages(os.path.join(out, "run.bag"), ["/trip_computer/display", "/engine/state", "/vehicle/state"])
            display = m["/trip_computer/display"]
            self.assertEqual(len(display), int(UNTIL * 1e9) // P_NS + 1, mode)  # t = 0 and every 0.1 s
            shown = 0
            for t, d in display.items():
                if t == 0:
                    continue
                e, v = m["/engine/state"][t - P_NS], m["/vehicle/state"][t - P_NS]
                fuel_l, dist_km, l_100km, on, _ = d.values
                self.assertEqual(fuel_l, e.fuel_mass_kg / rho_kg_l, (mode, t))
                self.assertEqual(dist_km, v.distance_m / 1000.0, (mode, t))
                self.assertEqual(on, 1.0 if v.distance_m >= 1000.0 else 0.0, (mode, t))
                if on:
                    shown += 1
                    self.assertAlmostEqual(l_100km, fuel_l / (v.distance_m / 1e5), delta=1e-12 * l_100km)
                else:
                    self.assertEqual(l_100km, 0.0)
            self.assertGreater(shown, 0, "the bus passed 1 km within %.0f s" % UNTIL)

    def test_a_listener_changes_nothing_else(self):
        without = [x for x in run_util.bag_messages(os.path.join(self.without, "run.bag")) if x[0] != "/twin/run_info"]
        for mode, (out, _) in self.runs.items():
            with_it = [x for x in run_util.bag_messages(os.path.join(out, "run.bag"))
                       if x[0] not in ("/twin/run_info", "/trip_computer/display")]
            self.assertEqual(len(with_it), len(without), mode)
            self.assertTrue(with_it == without, "%s: another topic changed" % mode)

    def test_its_warning_threshold_comes_from_its_yaml(self):
        for mode, (out, _) in self.runs.items():
            final = read_diagnostics(os.path.join(out, "run.bag"))["trip_computer"]["values"]
            self.assertIsNotNone(final, mode)
            self.assertIn("warning/long_idle/first_time_s", final, (mode, sorted(final)))
            # raised when the standstill idling it displays had lasted 5 s without a break
            display = messages(os.path.join(out, "run.bag"), ["/trip_computer/display"])["/trip_computer/display"]
            start, first = None, None
            for t in sorted(display):
                if display[t].values[4] > 0.0:
                    start = t if start is None else start
                    if t - start >= int(IDLE_S * 1e9):
                        first = start + int(IDLE_S * 1e9)
                        break
                else:
                    start = None
            self.assertIsNotNone(first, "no standstill of 5 s in %.0f s of Urban" % UNTIL)
            self.assertAlmostEqual(float(final["warning/long_idle/first_time_s"]), first / 1e9, places=9)

    def test_a_wrongly_declared_topic_stops_the_run_naming_file_and_key(self):
        topics = os.path.join(self.tmp, "topics.yaml")
        with open(os.path.join(EXAMPLE, "node", "topics.yaml")) as f:
            text = f.read()
        with open(topics, "w") as f:
            f.write(text.replace("display: hybrid_bus_twin/ProbeSignal", "display: hybrid_bus_twin/EngineState"))
        out = os.path.join(self.tmp, "bad_wiring")
        st = run_util.run_launch(LAUNCH, out, until=5.0, timeout=10.0, trip_computer_topics=topics)
        self.assertEqual(st["status"], "error", st)
        self.assertEqual(st["steps"], 0, "rejected before the first step")
        self.assertIn(topics, st["message"])
        self.assertIn("publishes/display", st["message"])
        self.assertIn("hybrid_bus_twin/ProbeSignal", st["message"])


if __name__ == "__main__":
    run_util.unittest_main()
