#!/usr/bin/python3
"""The rviz live view, rendered headless (Xvfb, Mesa software OpenGL) and checked from its pixels:
  - control: rviz with config/twin.rviz but no viz_node shows no gauge colour (the check fails);
  - live: baseline_urban with rviz:=true: the bus, the speed, engine and temperature gauges are
    drawn, and nothing of the hybrid (no e-machine purple, no battery yellow);
  - replay: a short hybrid_urban bag through `scripts/twin replay BAG --start S --rate R`: the
    bus, the stops and every gauge colour, the hybrid's included;
  - `twin replay` rejects a bad --rate / --start / bag with exit status 2 and a message naming it.
Colours are told apart by hue (twin_tools.viz.layout's palette; rviz shades faces but keeps
hues); the screen's unsaturated background, grid and text never count.
Skipped (with a message) only when rviz or Xvfb is not installed (scripts/twin setup --viz)."""
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

import numpy as np

from twin_tools.launch import ports, run_util
from twin_tools.report import postprocess

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

SCREEN = (1400, 900)
# hue ranges (PIL HSV, 0..255) of the palette in twin_tools.viz.layout
HUES = {"red": [(0, 8), (248, 255)], "orange": [(14, 30)], "yellow": [(32, 44)], "green": [(80, 100)],
        "cyan": [(118, 136)], "blue": [(144, 164)], "purple": [(186, 210)]}
MIN_PX = 300            # a gauge colour is present with at least this many pixels
BUS_PX = (1500, 30000)  # the blue of the bus (12 m x 3 m at ~14 px/m, + the route-strip icon)

VIEW = (0, 70, SCREEN[0], SCREEN[1] - 40)   # rviz's 3D view: the window without menu, tool and status bars


def grab(display):
    """The 3D view of the rviz window (at the top left of the bare X screen: no window manager)."""
    from PIL import ImageGrab
    return ImageGrab.grab(bbox=VIEW, xdisplay=display)


def colour_counts(img):
    """{colour: pixels} over saturated, lit pixels (background, grid and text are grey)."""
    hsv = np.asarray(img.convert("RGB").convert("HSV")).reshape(-1, 3).astype(int)
    h, s, v = hsv.T
    sat = (s > 110) & (v > 90)
    return {name: int(sum(np.sum(sat & (h >= lo) & (h <= hi)) for lo, hi in ranges))
            for name, ranges in HUES.items()}


def problems(counts, present, absent=()):
    """What is wrong with a frame: missing colours, a bus of implausible size, colours that
    must not be there. Empty = the frame shows the view."""
    out = ["%s missing (%d px)" % (c, counts[c]) for c in present if counts[c] < MIN_PX]
    if not BUS_PX[0] <= counts["blue"] <= BUS_PX[1]:
        out.append("bus blue %d px outside %s" % (counts["blue"], BUS_PX))
    out += ["%s drawn (%d px) but absent from the run" % (c, counts[c]) for c in absent if counts[c] >= MIN_PX // 3]
    return out


def watch(proc, display, present, absent=(), timeout_s=60.0):
    """Grabs the screen every 0.5 s while proc runs; returns (first frame without problems or
    None, the last problems seen)."""
    last = ["no frame grabbed"]
    t_end = time.time() + timeout_s
    while time.time() < t_end and proc.poll() is None:
        time.sleep(0.5)
        img = grab(display)
        last = problems(colour_counts(img), present, absent)
        if not last:
            return img, []
    return None, last


class LiveView(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        missing = [x for x in ("rviz", "Xvfb") if shutil.which(x) is None]
        if missing:
            raise unittest.SkipTest("%s not installed (scripts/twin setup --viz installs them)" % ", ".join(missing))
        cls.tmp = tempfile.mkdtemp(prefix="hbt_viz_")
        r, w = os.pipe()
        cls.xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(w), "-screen", "0", "%dx%dx24" % SCREEN,
                                     "-nolisten", "tcp"], pass_fds=(w,), stdout=subprocess.DEVNULL,
                                    stderr=subprocess.DEVNULL, start_new_session=True)
        os.close(w)
        with os.fdopen(r) as f:
            cls.display = ":" + f.readline().strip()
        os.environ["DISPLAY"] = cls.display
        os.environ["LIBGL_ALWAYS_SOFTWARE"] = "1"   # Mesa llvmpipe: no GPU on CI machines

    @classmethod
    def tearDownClass(cls):
        cls.xvfb.terminate()
        cls.xvfb.wait(timeout=10)
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_1_control_without_viz_node(self):
        """rviz alone: the check must fail (no bus, no gauge colours)."""
        port, lock = ports.reserve_port(os.getpid() % (ports.PORT_HI - ports.PORT_LO))
        self.addCleanup(os.close, lock)
        env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % port, ROS_HOME=self.tmp)
        master = subprocess.Popen(["rosmaster", "--core", "-p", str(port)], env=env, start_new_session=True,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        rviz = subprocess.Popen(["rviz", "-d", os.path.join(REPO, "config", "twin.rviz")], env=env,
                                start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            t_end, shown = time.time() + 90.0, False
            while time.time() < t_end and not shown:  # until rviz draws its view (dark background)
                time.sleep(0.5)
                a = np.asarray(grab(self.display).convert("RGB")).reshape(-1, 3).astype(int)
                shown = np.mean(np.all(np.abs(a - (30, 32, 36)) <= 3, axis=1)) > 0.3
            self.assertTrue(shown, "rviz did not show its view within 90 s")
            time.sleep(2.0)
            counts = colour_counts(grab(self.display))
            self.assertEqual(len(problems(counts, HUES)), len(HUES) + 1, counts)  # every colour missing
            self.assertLess(max(counts.values()), MIN_PX // 3, counts)
        finally:
            for p in (rviz, master):
                os.killpg(p.pid, signal.SIGINT)
                p.wait(timeout=20)

    def test_2_live_run_baseline(self):
        """baseline_urban rviz:=true: conventional gauges drawn, no e-machine or battery. The
        run is the whole mission (rviz starts slowly on a loaded machine, where a map-engine
        mission can end first) and is stopped as soon as a frame shows the view."""
        out = os.path.join(self.tmp, "baseline")
        proc = run_util.start_launch(os.path.join(REPO, "launch", "baseline_urban.launch"), out,
                                     rviz="true", timeout=10.0)
        try:
            img, why = watch(proc, self.display, ("blue", "green", "orange", "red", "cyan"),
                             absent=("purple", "yellow"), timeout_s=120.0)
            ended = proc.poll() is not None
        finally:
            run_util.stop(proc)
        self.assertIsNotNone(img, "no frame of the live run showed the view: %s%s" % (
            why, " (the run ended first: %s/roslaunch.log)" % out if ended else ""))

    def test_3_replay_hybrid(self):
        """twin replay of a hybrid bag: every gauge colour, the hybrid's included."""
        out = os.path.join(self.tmp, "hybrid")
        st = run_util.run_launch(os.path.join(REPO, "launch", "hybrid_urban.launch"), out, until=60,
                                 timeout=10.0)
        self.assertEqual(st["status"], "ok", st)
        bag = os.path.join(out, "run.bag")
        with open(os.path.join(out, "stops.csv")) as f:  # the metadata `twin run` stores in the bag
            postprocess.store_run_info(bag, {"scenario": "hybrid_urban", "args": {"until": "60"},
                                             "status": st, "stops_csv": f.read()})
        # bus approaching the stop at 167 m (profile t 51.5 s): the stop in the view
        proc = subprocess.Popen([os.path.join(REPO, "scripts", "twin"), "replay", bag, "--start", "40",
                                 "--rate", "0.5"], start_new_session=True, stdout=subprocess.DEVNULL,
                                stderr=subprocess.STDOUT)
        try:
            img, why = watch(proc, self.display, ("blue", "green", "orange", "red", "cyan", "purple", "yellow"),
                             timeout_s=120.0)
        finally:
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGINT)
            proc.wait(timeout=30)
        self.assertIsNotNone(img, "no frame of the replay showed the view: %s" % why)

    def test_4_replay_rejects_bad_input(self):
        bag = os.path.join(self.tmp, "hybrid", "run.bag")
        if not os.path.exists(bag):
            self.skipTest("needs the bag of test_3")
        twin = os.path.join(REPO, "scripts", "twin")
        text = os.path.join(self.tmp, "not_a_bag.bag")
        with open(text, "w") as f:
            f.write("hello\n")
        for args, expect in ((["--rate", "0"], "--rate must be a positive number"),
                             (["--rate", "fast"], "--rate 'fast' is not a number"),
                             (["--start", "-1"], "--start -1 is outside the bag"),
                             (["--start", "1e6"], "0 <= start < 60.0 s"),
                             (["--start", "nan"], "--start nan is outside the bag")):
            r = subprocess.run([twin, "replay", bag] + args, capture_output=True, text=True, timeout=60)
            self.assertEqual(r.returncode, 2, (args, r.stderr))
            self.assertIn(expect, r.stderr, args)
        r = subprocess.run([twin, "replay", text, "--no-rviz"], capture_output=True, text=True, timeout=60)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("%s: not a ROS bag" % text, r.stderr)


if __name__ == "__main__":
    run_util.unittest_main(verbosity=2)  # all skipped (tools missing): exit 77, ctest "Not Run"
