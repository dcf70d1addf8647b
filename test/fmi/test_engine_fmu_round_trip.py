#!/usr/bin/python3
"""The round trip of the engine's FMU export: the map engine exported as an FMU
(<build>/fmus/engine_map.fmu, as `twin fmu export engine_map` gives it) and imported in place of
the native engine participant (`engine_fmu:=`, no mapping file) in both scenarios, against the
native run of each:

- baseline_urban, 300 s from a cold start (cold oil): the FMU's command input
  ems|vehicle.engine_command.* fed by the vehicle;
- hybrid_urban, 150 s from start:=warm (the EMS stops the warm engine at standstill: 23 s off in
  those 150 s, restarts included; from a cold start it stays on for the first 600 s): fed by the
  EMS (the alternative that runs; src/fmi/README.md, naming convention).

Each: summary.json equal but wall_time_s, every bag message byte for byte the same but
/twin/run_info (test_fmu_round_trip.py says why). Bit-identical, no tolerance: the FMU steps the
same model library with the same parameters, inputs and step, through the conversion the node
uses (engine_interface/engine_io.hpp). The FMU runs must have used the FMU (its resolved mapping,
naming the producer that fed the command), so the test cannot pass on two native runs."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_fmu_round_trip import flatten, fmu_dir, messages, read_json, run_together  # noqa: E402

from twin_tools.launch import run_util  # noqa: E402
from twin_tools.paths import REPO  # noqa: E402

# scenario: (until [s], the command's producer, further launch arguments)
RUNS = {"baseline_urban": (300.0, "vehicle", []), "hybrid_urban": (150.0, "ems", ["start:=warm"])}


class EngineFmuRoundTrip(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_engine_fmu_round_trip_")
        cls.fmu = os.path.join(fmu_dir(), "engine_map.fmu")
        if not os.path.isfile(cls.fmu):
            raise unittest.SkipTest("no %s (the build makes it)" % cls.fmu)
        cls.out, cls.rc = {}, {}

        def run(scenario, variant):
            out = os.path.join(cls.tmp, scenario + "_" + variant)
            args = ["engine_fmu:=" + cls.fmu] if variant == "fmu" else []
            r = subprocess.run([os.path.join(REPO, "scripts", "twin"), "run", scenario, "--out", out,
                                "until:=%g" % RUNS[scenario][0]] + RUNS[scenario][2] + args,
                               env=dict(os.environ, HBT_SETUP_DONE="1"),
                               capture_output=True, text=True)
            cls.out[(scenario, variant)] = out
            cls.rc[(scenario, variant)] = (r.returncode, r.stdout[-2000:] + r.stderr[-2000:])

        for scenario in sorted(RUNS):  # native and FMU of one scenario at once
            run_together(run, [(scenario, v) for v in ("native", "fmu")])

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_runs_completed_and_the_command_came_from_the_scenarios_producer(self):
        for scenario, (_, producer, _) in sorted(RUNS.items()):
            for variant in ("native", "fmu"):
                key = (scenario, variant)
                self.assertEqual(self.rc[key][0], 0, self.rc[key][1])
                self.assertEqual(run_util.read_status(self.out[key])["status"], "ok")
            self.assertFalse(os.path.exists(os.path.join(self.out[(scenario, "native")], "fmu", "engine")))
            with open(os.path.join(self.out[(scenario, "fmu")], "resolved_config", "engine_fmu.csv")) as f:
                rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
            inputs = {r[2]: r[1] for r in rows[1:] if r[0] == "input"}  # variable -> field
            self.assertEqual(inputs["ems|vehicle.engine_command.torque_request_nm"],
                             producer + ".engine_command.torque_request_nm", scenario)
            self.assertEqual(inputs["cooling.state.oil_temperature_k"], "cooling.state.oil_temperature_k")

    def test_summary_equal_but_the_wall_time(self):
        for scenario, (until_s, _, _) in sorted(RUNS.items()):
            a, b = (flatten(read_json(os.path.join(self.out[(scenario, v)], "summary.json"))) for v in ("native", "fmu"))
            self.assertEqual(set(a), set(b), scenario)
            differ = sorted(k for k in a if a[k] != b[k])
            print("\n  %s summary.json: %d keys, differing: %s" % (scenario, len(a), differ))
            self.assertLessEqual(set(differ), {"/wall_time_s"}, scenario)
            self.assertEqual(a["/sim_time_s"], until_s)
            if scenario == "hybrid_urban":
                self.assertGreater(a["/engine_off_s"], 0.0)  # stop-start: the engine off and restarted

    def test_bag_byte_identical_but_run_info(self):
        for scenario, (until_s, _, _) in sorted(RUNS.items()):
            a, b = (messages(os.path.join(self.out[(scenario, v)], "run.bag")) for v in ("native", "fmu"))
            self.assertEqual(sorted(a), sorted(b), scenario)
            n = 0
            for topic in sorted(a):
                if topic == "/twin/run_info":  # launch arguments (the FMU), wall-clock and CPU times
                    continue
                self.assertEqual(len(a[topic]), len(b[topic]), topic)
                for i, (x, y) in enumerate(zip(a[topic], b[topic])):
                    self.assertEqual(x, y, "%s %s message %d (stamp %d ns) differs" % (scenario, topic, i, x[0]))
                n += len(a[topic])
            self.assertGreaterEqual(len(a["/engine/state"]), int(until_s / 0.1))  # the recorder's period 0.1 s
            print("\n  %s run.bag: %d messages on %d topics byte-identical (/twin/run_info excepted)"
                  % (scenario, n, len(a) - 1))


if __name__ == "__main__":
    run_util.unittest_main(verbosity=2)
