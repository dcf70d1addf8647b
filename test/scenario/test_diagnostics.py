#!/usr/bin/python3
"""Scenario test of the participants' /diagnostics (docs/diagnostics.md): baseline_urban at
0 degC for 60 s, in nodelets and in nodes mode, with config/aftertreatment.yaml's light-off grace
(its diagnostics: section) cut to 30 s so that the cold SCR raises ats_below_light_off. Every participant's statuses are in
diagnostics.bag (one at every simulated second and a final one) with its host, step counts and
compute times; /diagnostics is not in run.bag, which stays bit-identical between the two modes; the
warning's first time in summary.json is the one the recorded /aftertreatment/state implies; the
report rebuilt from the bags is identical, and without diagnostics.bag it says so; a typo in
a participant's diagnostics: section (config/vehicle.yaml) stops the run before the first step naming the file and the key."""
import json
import os
import shutil
import socket
import subprocess
import tempfile
import unittest

from twin_tools.launch import run_util

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

LAUNCH = os.path.join(REPO, "launch", "baseline_urban.launch")
POSTPROCESS = ["-m", "twin_tools.report.postprocess"]
UNTIL = 60.0
GRACE_S = 30.0
NS = 10**9
BASE_STEP_S = 0.01  # the stepper's base step [s] (launch/include/urban.launch arg step); a participant without cosim/macro_step_s steps at it
# the participants that publish the baseline's topics (conventional, thermal, hvac:=on)
BASELINE_PARTICIPANTS = sorted({t.split("/")[1] for t in run_util.BASELINE_TOPICS})
CONFIG_FILE = {"engine": "engine_map.yaml"}  # participant -> its config file where it is not <name>.yaml


def macro_step_s(name):
    """The participant's macro step [s] from its shipped config (cosim/macro_step_s)."""
    import yaml
    with open(os.path.join(REPO, "config", CONFIG_FILE.get(name, name + ".yaml"))) as f:
        doc = yaml.safe_load(f) or {}
    return float((doc.get("cosim") or {}).get("macro_step_s", BASE_STEP_S))


# participant -> its macro step [s]; the recorder steps at the base step (record_period 0)
PARTICIPANTS = dict({n: macro_step_s(n) for n in BASELINE_PARTICIPANTS}, recorder=BASE_STEP_S)


def read_statuses(bag):
    """[(stamp_ns, DiagnosticStatus)] of every /diagnostics message, and the set of topics."""
    import rosbag
    out, topics = [], set()
    with rosbag.Bag(bag) as b:
        for topic, msg, _ in b.read_messages():
            topics.add(topic)
            for s in msg.status:
                out.append((msg.header.stamp.to_nsec(), s))
    return out, topics


class Diagnostics(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="hbt_diag_")
        cfg = os.path.join(cls.tmp, "config")
        shutil.copytree(os.path.join(REPO, "config"), cfg, ignore=shutil.ignore_patterns("data"))
        os.symlink(os.path.join(REPO, "config", "data"), os.path.join(cfg, "data"))
        p = os.path.join(cfg, "aftertreatment.yaml")
        with open(p) as f:
            text = f.read()
        assert "light_off_grace_s: 300.0" in text
        with open(p, "w") as f:
            f.write(text.replace("light_off_grace_s: 300.0", "light_off_grace_s: %.1f" % GRACE_S))
        cls.runs = {}
        for mode in ("nodelets", "nodes"):
            out = os.path.join(cls.tmp, mode)
            st = run_util.run_launch(LAUNCH, out, mode=mode, until=UNTIL, ambient=0, record_period=0,
                                     config=cfg, timeout=10.0)
            cls.runs[mode] = (out, st)

    def test_runs_complete(self):
        for mode, (out, st) in self.runs.items():
            self.assertEqual(st["status"], "ok", (mode, st))
            self.assertAlmostEqual(st["sim_time_s"], UNTIL, places=9)

    def test_every_participant_reports_compute_times(self):
        host = socket.gethostname()
        for mode, (out, _) in self.runs.items():
            statuses, topics = read_statuses(os.path.join(out, "diagnostics.bag"))
            self.assertEqual(topics, {"/diagnostics"})
            by = {}
            for t, s in statuses:
                by.setdefault(s.name, []).append((t, s))
            self.assertEqual(set(by), set(PARTICIPANTS), mode)
            for name, sts in by.items():
                periodic = sorted(t for t, s in sts if {kv.key: kv.value for kv in s.values}["final"] == "false")
                finals = [(t, s) for t, s in sts if {kv.key: kv.value for kv in s.values}["final"] == "true"]
                # one status at every simulated second (config period_s 1) and one final at the end
                self.assertEqual(periodic, [k * NS for k in range(int(UNTIL) + 1)], (mode, name))
                self.assertEqual([t for t, _ in finals], [int(UNTIL) * NS], (mode, name))
                per_s = int(round(1.0 / PARTICIPANTS[name]))
                for t, s in sts:
                    v = {kv.key: kv.value for kv in s.values}
                    self.assertEqual(s.hardware_id, host)
                    self.assertEqual(v["sim_time_s"], "%d.%09d" % (t // NS, t % NS))
                    mean, mx = float(v["step_compute_ms_mean"]), float(v["step_compute_ms_max"])
                    n = int(v["steps_window"])
                    final = v["final"] == "true"
                    # steps whose state is stamped in (t - 1 s, t]; none before t = 0 and in the final
                    self.assertEqual(n, 0 if t == 0 or final else per_s, (mode, name, t))
                    self.assertEqual(int(v["steps_total"]), t // NS * per_s, (mode, name, t))
                    if n:
                        self.assertGreater(mx, 0.0)
                        self.assertLessEqual(mean, mx * (1 + 1e-5))
                        self.assertLess(mx, 10000.0)  # below the 10 s step timeout of the run
                    self.assertLessEqual(float(v["step_compute_ms_mean_run"]),
                                         float(v["step_compute_ms_max_run"]) * (1 + 1e-5))
                # the participants' own sub-step counters
                last = {kv.key: kv.value for kv in finals[0][1].values}
                if name == "aftertreatment":
                    self.assertGreater(int(last["scr_solver_steps_total"]), 0)
                if name == "vehicle":
                    self.assertIn("speed_error_kmh", last)

    def test_run_bag_without_diagnostics_and_bit_identical(self):
        a = run_util.bag_messages(os.path.join(self.runs["nodelets"][0], "run.bag"))
        b = run_util.bag_messages(os.path.join(self.runs["nodes"][0], "run.bag"))
        self.assertNotIn("/diagnostics", {topic for topic, _, _ in a})
        self.assertEqual({topic for topic, _, _ in a}, set(run_util.BASELINE_TOPICS))
        self.assertEqual(len(a), len(run_util.BASELINE_TOPICS) * (int(round(UNTIL / BASE_STEP_S)) + 1))
        self.assertEqual(a, b)

    def warning_first_time_from_states(self, out):
        """First raise of ats_below_light_off implied by the recorded /aftertreatment/state: the
        first stamp at which light_off has been false for GRACE_S without a break."""
        import rosbag
        since = None
        with rosbag.Bag(os.path.join(out, "run.bag")) as bag:
            for _, m, _ in bag.read_messages(topics=["/aftertreatment/state"]):
                t = m.header.stamp.to_nsec()
                if m.light_off:
                    since = None
                    continue
                since = t if since is None else since
                if t - since >= int(GRACE_S * NS):
                    return t
        return None

    def test_warning_in_summary_matches_states(self):
        out = os.path.join(self.tmp, "report")
        shutil.copytree(self.runs["nodelets"][0], out)
        r = subprocess.run(["/usr/bin/python3", *POSTPROCESS, out, "--scenario", "baseline_urban",
                            "ambient:=0", "until:=60"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        w = [x for x in s["warnings"] if x["warning"] == "ats_below_light_off"]
        self.assertEqual(len(w), 1, s["warnings"])
        self.assertEqual(w[0]["node"], "aftertreatment")
        t_states = self.warning_first_time_from_states(out)
        self.assertEqual(t_states, int(GRACE_S * NS))  # cold SCR from t = 0: not lit off at 30 s
        self.assertEqual(w[0]["first_time_s"], t_states / NS)
        self.assertIn("SCR not lit off for 30 s", w[0]["message"])
        self.assertEqual(w[0]["raised"], 1)
        self.assertAlmostEqual(w[0]["active_s"], UNTIL - GRACE_S, places=9)
        self.assertEqual([x["first_time_s"] for x in s["warnings"]],
                         sorted(x["first_time_s"] for x in s["warnings"]))
        with open(os.path.join(out, "report.md")) as f:
            rep = f.read()
        self.assertIn("## Diagnostics", rep)
        self.assertIn("| 30.00 | aftertreatment | ats_below_light_off | 1 | 30.00 |", rep)
        # the same report from the bags alone (scripts/twin report)
        again = os.path.join(self.tmp, "from_bag")
        r = subprocess.run(["/usr/bin/python3", *POSTPROCESS, "--bag", os.path.join(out, "run.bag"), again],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        for f in ("summary.json", "report.md"):
            with open(os.path.join(out, f)) as x, open(os.path.join(again, f)) as y:
                self.assertEqual(x.read(), y.read(), f)
        # a bag copied without diagnostics.bag: no warnings key, and the report says why
        alone = os.path.join(self.tmp, "alone")
        os.makedirs(alone)
        shutil.copy(os.path.join(out, "run.bag"), alone)
        r = subprocess.run(["/usr/bin/python3", *POSTPROCESS, "--bag", os.path.join(alone, "run.bag")],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(alone, "summary.json")) as f:
            self.assertNotIn("warnings", json.load(f))
        with open(os.path.join(alone, "report.md")) as f:
            self.assertIn("No diagnostics.bag beside the bag", f.read())

    def test_bad_diagnostics_config_rejected_before_the_first_step(self):
        cfg = os.path.join(self.tmp, "bad_config")
        shutil.copytree(os.path.join(self.tmp, "config"), cfg, symlinks=True)
        p = os.path.join(cfg, "vehicle.yaml")
        with open(p) as f:
            text = f.read()
        assert "  speed_error_kmh: 3.0" in text
        with open(p, "w") as f:
            f.write(text.replace("  speed_error_kmh: 3.0", "  speed_eror_kmh: 3.0"))
        out = os.path.join(self.tmp, "bad")
        st = run_util.run_launch(LAUNCH, out, until=5.0, config=cfg)
        self.assertEqual(st["status"], "error", st)
        self.assertEqual(st["steps"], 0, "rejected before the first step")
        self.assertIn(p, st["message"])
        self.assertIn("diagnostics/speed_eror_kmh", st["message"])


if __name__ == "__main__":
    unittest.main(verbosity=2)
