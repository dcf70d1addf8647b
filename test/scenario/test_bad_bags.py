#!/usr/bin/python3
"""The bag tools never crash on a bad file (twin_tools.bags.reader): `twin report`, `twin plot` and
`twin replay` answer a missing path, a folder, an empty file, a file that is not a bag, a bag cut
short (unindexed) and a bag without the twin's run metadata with exit status != 0 and one
message naming the file -- no traceback. The cut bag is a real bag written here and truncated;
after `rosbag reindex` it is readable again and `twin plot` plots what it holds."""
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
