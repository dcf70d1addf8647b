#!/usr/bin/python3
"""Multi-rate stepping moves the results by less than 0.2 %: baseline_urban
(map engine, nodelets) for the first 300 s with the documented rates (cooling and aftertreatment
nodes every 0.1 s, fed the means of their 10 ms producers from cumulative totals) against
everything at the 10 ms base step (a config copy). Compared: fuel, and the temperature rise above ambient of the HT
coolant, the engine metal and the SCR brick at the end, and the SCR brick's time mean rise.
The full mission: scripts/twin bench rates (docs/bench/rates_<engine>.md)."""
import os
import tempfile
import unittest

from twin_tools.bench.rates_config import all_fast_config
from twin_tools.launch import run_util

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

LAUNCH = os.path.join(REPO, "launch", "baseline_urban.launch")
UNTIL = 300.0
AMBIENT_K = 298.15


def series(bag):
    import rosbag
    out = {"/engine/state": [], "/cooling/state": [], "/aftertreatment/state": []}
    with rosbag.Bag(bag) as b:
        for topic, m, _ in b.read_messages(topics=list(out)):
            out[topic].append(m)
    return out


class Rates(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_rates_")
        cls.runs = {}
        for name, cfg in (("multirate", None), ("all_10ms", all_fast_config(cls.tmp))):
            out = os.path.join(cls.tmp, name)
            args = dict(mode="nodelets", until=UNTIL, timeout=10.0)
            if cfg:
                args["config"] = cfg
            cls.runs[name] = (out, run_util.run_launch(LAUNCH, out, **args))

    def test_rates_move_results_less_than_0p2_percent(self):
        for name, (out, st) in self.runs.items():
            self.assertEqual(st["status"], "ok", (name, st))
        a = series(os.path.join(self.runs["multirate"][0], "run.bag"))
        b = series(os.path.join(self.runs["all_10ms"][0], "run.bag"))
        fa, fb = a["/engine/state"][-1].fuel_mass_kg, b["/engine/state"][-1].fuel_mass_kg
        self.assertLess(abs(fa / fb - 1.0), 0.002, (fa, fb))
        for topic, field in (("/cooling/state", "coolant_ht_temperature_k"), ("/cooling/state", "metal_temperature_k"),
                             ("/aftertreatment/state", "scr_temperature_k")):
            ra = getattr(a[topic][-1], field) - AMBIENT_K
            rb = getattr(b[topic][-1], field) - AMBIENT_K
            self.assertGreater(rb, 5.0, field)  # a real warm-up to compare
            self.assertLess(abs(ra / rb - 1.0), 0.002, (field, ra, rb))
        ma = sum(getattr(m, "scr_temperature_k") - AMBIENT_K for m in a["/aftertreatment/state"]) / len(a["/aftertreatment/state"])
        mb = sum(getattr(m, "scr_temperature_k") - AMBIENT_K for m in b["/aftertreatment/state"]) / len(b["/aftertreatment/state"])
        self.assertLess(abs(ma / mb - 1.0), 0.002, (ma, mb))
        print("rates: fuel %.6f vs %.6f kg (%.3f %%)" % (fa, fb, 100 * (fa / fb - 1)))


if __name__ == "__main__":
    unittest.main()
