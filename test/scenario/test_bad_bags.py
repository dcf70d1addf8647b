#!/usr/bin/python3
"""The bag tools never crash on a bad file (twin_tools.bags.reader): `twin report`, `twin plot` and
`twin replay` answer a missing path, a folder, an empty file, a file that is not a bag, a bag cut
short (unindexed) and a bag without the twin's run metadata with exit status != 0 and one
message naming the file -- no traceback. A bag that holds less than its run (topics filtered out,
states ending early) is reported for what it holds and says so; a --baseline that is not the
conventional bus's summary under the same conditions is refused naming the difference; a plot of
a topic of another scenario names the topic. The cut bag is a real bag written here and truncated;
after `rosbag reindex` it is readable again and `twin plot` plots what it holds."""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
TWIN = os.path.join(REPO, "scripts", "twin")


def twin(*args):
    r = subprocess.run([TWIN] + list(args), capture_output=True, text=True, timeout=120)
    return r.returncode, r.stdout + r.stderr


class BadBags(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import rosbag
        import rospy
        from hybrid_bus_twin.msg import VehicleState
        cls.tmp = tempfile.mkdtemp(prefix="hbt_bad_bags_")
        t = cls.tmp
        cls.files = {"missing": os.path.join(t, "missing.bag"), "folder": os.path.join(t, "folder.bag"),
                     "empty": os.path.join(t, "empty.bag"), "text": os.path.join(t, "text.bag"),
                     "cut": os.path.join(t, "cut.bag"), "no_run_info": os.path.join(t, "plain.bag")}
        os.makedirs(cls.files["folder"])
        open(cls.files["empty"], "w").close()
        with open(cls.files["text"], "w") as f:
            f.write("speed,fuel\n1,2\n")
        with rosbag.Bag(cls.files["no_run_info"], "w", chunk_threshold=4096) as bag:  # small chunks: a cut keeps some
            for k in range(2000):
                m = VehicleState()
                m.header.stamp = rospy.Time.from_sec(0.1 * k)
                m.speed_m_s = 0.01 * k
                bag.write("/vehicle/state", m, m.header.stamp)
        size = os.path.getsize(cls.files["no_run_info"])
        with open(cls.files["no_run_info"], "rb") as f, open(cls.files["cut"], "wb") as g:
            g.write(f.read(size // 2))  # cut short: the index at the end is lost

        # a run's bag that holds less than its run: the vehicle's states of 0-199.9 s only of a
        # 300 s baseline run (the engine's topics filtered out), with the run's metadata
        from twin_tools.report.postprocess import store_run_info
        cls.runs = {"partial": os.path.join(t, "partial.bag"), "hybrid": os.path.join(t, "hybrid.bag")}
        shutil.copy(cls.files["no_run_info"], cls.runs["partial"])
        stops = "distance_m,t_profile_s,stop_time_s\n0,0,12.5\n150,40,20\n"
        cls.status = {"status": "ok", "message": "end of mission", "sim_time_s": 300.0, "wall_time_s": 1.0,
                      "steps": 30000, "macro_step_s": 0.01, "compute_time_s": {"vehicle": 0.5, "engine": 0.5}}
        store_run_info(cls.runs["partial"], {"scenario": "baseline_urban", "args": {}, "status": cls.status,
                                             "stops_csv": stops, "stop_service": None})
        # the same as the hybrid's (the report reads the architecture from the scenario)
        shutil.copy(cls.files["no_run_info"], cls.runs["hybrid"])
        store_run_info(cls.runs["hybrid"], {"scenario": "hybrid_urban", "args": {"ambient": "25"},
                                            "status": cls.status, "stops_csv": stops, "stop_service": None})

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def refused(self, rc, text, path, *words):
        self.assertNotEqual(rc, 0, text)
        self.assertNotIn("Traceback", text)
        self.assertIn(path, text)
        for w in words:
            self.assertIn(w, text)

    def test_report(self):
        words = {"missing": "no such file", "folder": "a folder", "empty": "empty", "text": "not a ROS bag",
                 "cut": "rosbag reindex", "no_run_info": "/twin/run_info"}
        for kind, path in self.files.items():
            rc, text = twin("report", path, "--out", os.path.join(self.tmp, "r_" + kind))
            self.refused(rc, text, path, words[kind])

    def test_report_of_a_bag_that_holds_less_than_its_run(self):
        # reported for what it holds, saying which topics are missing and where its states end
        out = os.path.join(self.tmp, "r_partial")
        rc, text = twin("report", self.runs["partial"], "--out", out)
        self.assertEqual(rc, 0, text)
        self.assertNotIn("Traceback", text)
        self.assertIn("/engine/state", text)
        self.assertIn("states end at t = 199.9 s of the 300.0 s", text)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        self.assertEqual(s["missing_topics"], ["/engine/state"])  # of the two that ran, the engine's
        self.assertTrue(s["partial"])
        self.assertAlmostEqual(s["data_until_s"], 199.9, places=6)
        with open(os.path.join(out, "report.md")) as f:
            self.assertIn("**Incomplete bag**", f.read())

    def test_report_baseline_of_another_scenario_or_conditions(self):
        def summary(name, **kv):
            path = os.path.join(self.tmp, name)
            with open(path, "w") as f:
                json.dump(dict({"scenario": "baseline_urban", "architecture": "conventional", "engine_model": "map",
                                "ambient_c": 25.0, "fuel_kg": 10.0}, **kv), f)
            return path
        hyb = self.runs["hybrid"]
        cases = [
            (hyb, summary("hybrid_as_base.json", scenario="hybrid_urban", architecture="p1_48v"),
             "a run of hybrid_urban (architecture p1_48v): --baseline takes the conventional bus's"),
            (hyb, summary("cold_base.json", ambient_c=0.0), "ambient_c 0.0 (baseline) vs 25.0 (this run)"),
            (hyb, summary("other_mission.json", sim_time_s=8115.4), "sim_time_s 8115.4 (baseline) vs 300.0 (this run)"),
            (self.runs["partial"], summary("base.json"), "this run (baseline_urban) is the conventional bus"),
            (hyb, self.tmp, "a folder, not a summary.json"),
            (hyb, self.files["text"], "not JSON"),
            (hyb, self.files["empty"], "not JSON"),
        ]
        with open(os.path.join(self.tmp, "not_summary.json"), "w") as f:
            json.dump([1, 2], f)
        cases.append((hyb, os.path.join(self.tmp, "not_summary.json"), "not a run's summary.json"))
        for bag, base, words in cases:
            with self.subTest(base=os.path.basename(base)):
                rc, text = twin("report", bag, "--baseline", base, "--out", os.path.join(self.tmp, "r_base"))
                self.refused(rc, text, "", words)
        rc, text = twin("report", hyb, "--baseline", summary("good.json", sim_time_s=300.0),
                        "--out", os.path.join(self.tmp, "r_good"))
        self.assertEqual(rc, 0, text)

    def test_plot_a_topic_of_another_scenario(self):
        # the conventional bus's bag has no battery: the plot names the topic and what the bag holds
        rc, text = twin("plot", self.runs["partial"], "/battery/state/soc", "-o", os.path.join(self.tmp, "b.png"))
        self.refused(rc, text, self.runs["partial"], "/battery/state not in", "/vehicle/state")

    def test_replay_a_bag_that_holds_less_than_its_run(self):
        # without the engine's topics the live view replays what there is
        rc, text = twin("replay", self.runs["partial"], "--no-rviz", "--rate", "1000")
        self.assertEqual(rc, 0, text)
        self.assertNotIn("Traceback", text)

    def test_plot_and_replay(self):
        for kind in ("missing", "folder", "empty", "text", "cut"):
            path = self.files[kind]
            rc, text = twin("plot", path, "/vehicle/state/speed_m_s", "-o", os.path.join(self.tmp, "p.png"))
            self.refused(rc, text, path)
            rc, text = twin("replay", path, "--no-rviz")
            self.refused(rc, text, path)

    def test_a_reindexed_cut_bag_plots_what_it_holds(self):
        path = os.path.join(self.tmp, "cut_again.bag")
        shutil.copy(self.files["cut"], path)
        r = subprocess.run(["rosbag", "reindex", path], capture_output=True, text=True, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        png = os.path.join(self.tmp, "cut.png")
        rc, text = twin("plot", path, "/vehicle/state/speed_m_s", "-o", png)
        self.assertEqual(rc, 0, text)
        self.assertGreater(os.path.getsize(png), 1000)


if __name__ == "__main__":
    unittest.main()
