#!/usr/bin/python3
"""The round trip of the FMU export: the battery and the e-machine exported as FMUs
(<build>/fmus/battery.fmu, emachine.fmu, as `twin fmu export` gives them) and imported in place of
the native participants of hybrid_urban (`battery_fmu:= emachine_fmu:=`, no mapping files), 600 s
of the mission, against the native run:

- summary.json: every key equal but wall_time_s (wall clock);
- the bag: every topic the same number of messages, each message byte for byte the same
  (serialised, stamps included), but /twin/run_info (one message: the launch arguments, which
  name the FMUs, and the wall-clock and CPU times of the run).

Bit-identical, no tolerance: the FMUs step the same model libraries with the same parameters, the
same inputs (the FMU participant passes values whose unit is the field's own unchanged) and the
same step; the conversion messages <-> model is the one the native nodes use (battery_io.hpp,
emachine_io.hpp). The FMU run must have used the FMUs (their resolved mappings, their
extraction), so the test cannot pass on two native runs."""
import json
import os
import shutil
import subprocess
import tempfile
import threading
import unittest

import rosbag

from twin_tools.launch import run_util
from twin_tools.paths import REPO

UNTIL_S = 600.0


def run_together(target, arg_tuples):
    """target(*args) for every tuple of arg_tuples, each in its own thread, all at once; returns when all are done."""
    threads = [threading.Thread(target=target, args=a) for a in arg_tuples]
    for t in threads:
        t.start()
    for t in threads:
        t.join()


def fmu_dir():
    """<build>/fmus (src/fmi/export/CMakeLists.txt), next to the devel space in use."""
    for p in os.environ.get("CMAKE_PREFIX_PATH", "").split(":"):
        d = os.path.join(os.path.dirname(p), "fmus")
        if p.endswith("devel") and os.path.isdir(d):
            return d
    return os.path.join(REPO, "build", "fmus")


def flatten(d, prefix=""):
    out = {}
    if isinstance(d, dict):
        for k, v in d.items():
            out.update(flatten(v, prefix + "/" + k))
    elif isinstance(d, list):
        for i, v in enumerate(d):
            out.update(flatten(v, "%s/%d" % (prefix, i)))
    else:
        out[prefix] = d
    return out


def read_json(path):
    with open(path) as f:
        return json.load(f)


def messages(bag_path):
    """topic -> [(stamp ns, serialised bytes)] in the bag's order."""
    out = {}
    with rosbag.Bag(bag_path) as b:
        for topic, msg, t in b.read_messages(raw=True):
            out.setdefault(topic, []).append((t.to_nsec(), bytes(msg[1])))
    return out


class FmuRoundTrip(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_fmu_round_trip_")
        fmus = fmu_dir()
        cls.fmus = {m: os.path.join(fmus, m + ".fmu") for m in ("battery", "emachine")}
        for f in cls.fmus.values():
            if not os.path.isfile(f):
                raise unittest.SkipTest("no %s (the build makes it)" % f)
        runs = {"native": [], "fmu": ["%s_fmu:=%s" % (m, f) for m, f in sorted(cls.fmus.items())]}
        cls.out, cls.rc = {}, {}

        def run(name, args):
            out = os.path.join(cls.tmp, name)
            r = subprocess.run([os.path.join(REPO, "scripts", "twin"), "run", "hybrid_urban", "--out", out,
                                "until:=%g" % UNTIL_S] + args, env=dict(os.environ, HBT_SETUP_DONE="1"),
                               capture_output=True, text=True)
            cls.out[name], cls.rc[name] = out, (r.returncode, r.stdout[-2000:] + r.stderr[-2000:])

        run_together(run, list(runs.items()))  # both at once

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_runs_completed_and_the_fmu_run_used_the_fmus(self):
        for name in ("native", "fmu"):
            self.assertEqual(self.rc[name][0], 0, self.rc[name][1])
            self.assertEqual(run_util.read_status(self.out[name])["status"], "ok")
        for m in self.fmus:
            self.assertTrue(os.path.isfile(os.path.join(self.out["fmu"], "resolved_config", m + "_fmu.csv")))
            self.assertTrue(os.path.isdir(os.path.join(self.out["fmu"], "fmu", m, "resources")))
            self.assertFalse(os.path.exists(os.path.join(self.out["native"], "fmu", m)))

    def test_summary_equal_but_the_wall_time(self):
        a, b = (flatten(read_json(os.path.join(self.out[n], "summary.json"))) for n in ("native", "fmu"))
        self.assertEqual(set(a), set(b))
        differ = sorted(k for k in a if a[k] != b[k])
        print("\n  summary.json: %d keys, differing: %s" % (len(a), differ))
        self.assertLessEqual(set(differ), {"/wall_time_s"})
        self.assertEqual(a["/sim_time_s"], UNTIL_S)

    def test_bag_byte_identical_but_run_info(self):
        a = messages(os.path.join(self.out["native"], "run.bag"))
        b = messages(os.path.join(self.out["fmu"], "run.bag"))
        self.assertEqual(sorted(a), sorted(b))
        self.assertIn("/battery/state", a)
        self.assertIn("/emachine/state", a)
        n = 0
        for topic in sorted(a):
            if topic == "/twin/run_info":  # launch arguments (the FMUs), wall-clock and CPU times
                continue
            self.assertEqual(len(a[topic]), len(b[topic]), topic)
            for i, (x, y) in enumerate(zip(a[topic], b[topic])):
                self.assertEqual(x, y, "%s message %d (stamp %d ns) differs" % (topic, i, x[0]))
            n += len(a[topic])
        self.assertGreaterEqual(len(a["/battery/state"]), int(UNTIL_S / 0.1))  # the recorder's period 0.1 s
        print("\n  run.bag: %d messages on %d topics byte-identical (/twin/run_info excepted)" % (n, len(a) - 1))


if __name__ == "__main__":
    run_util.unittest_main(verbosity=2)
