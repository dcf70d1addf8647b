"""scripts/twin replay BAG [--rate R] [--start S] [--no-rviz]: a run's bag played back under
simulated time with the live view (launch/include/replay.launch: rosbag play publishing /clock,
scripts/viz_node, rviz with config/twin.rviz) on its own ROS master on a free port.

Everything comes from the bag alone, checked before anything starts:
  - /vehicle/state (required): the road is rebuilt from it (altitude = integral of
    grade_percent over distance_m, one point every >= 5 m; the stretch the bus drove);
  - /twin/run_info (written by scripts/twin run): the stops (its stops_csv) and the title
    (scenario, engine, ambient); without it, stops.csv next to the bag (an interrupted run).
--rate: playback speed, a positive number (1 = real time); --start: seconds into the bag,
0 <= S < the bag's duration. With rviz the replay lasts until the window is closed (the view
stays on the last state); with --no-rviz (markers only, e.g. for another rviz) it ends with the bag.
Exit status 2 on bad input, with a message naming the argument or the bag's missing topic."""
import argparse
import json
import math
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile

from twin_tools.paths import REPO
from twin_tools.report.postprocess import RUN_INFO_TOPIC
from twin_tools import wiring

# topics (twin_tools.wiring: the participants' topics.yaml)
VEHICLE_STATE = wiring.topic("vehicle", "state")

ROAD_STEP_M = 5.0


def fail(msg):
    print("twin: replay: %s" % msg, file=sys.stderr)
    sys.exit(2)


def positive_number(name, text):
    try:
        v = float(text)
    except ValueError:
        fail("%s '%s' is not a number" % (name, text))
    if not math.isfinite(v) or v <= 0.0:
        fail("%s must be a positive number (got %s)" % (name, text))
    return v


def read_bag(path):
    """(duration [s], road rows [(distance_m, altitude_m)], run_info dict or None)."""
    from twin_tools.bags.reader import BagError, open_bag
    try:
        bag = open_bag(path)
    except BagError as e:
        fail(str(e))
    with bag:
        topics = bag.get_type_and_topic_info().topics
        if VEHICLE_STATE not in topics:
            fail("%s has no /vehicle/state (topics: %s)" % (path, ", ".join(sorted(topics)) or "none"))
        duration = bag.get_end_time() - bag.get_start_time()
        road, alt, last_s, last_row = [], 0.0, None, None
        for _, m, _ in bag.read_messages(topics=[VEHICLE_STATE]):
            s = m.distance_m
            if last_s is not None:
                alt += (s - last_s) * m.grade_percent / 100.0
            last_s = s
            last_row = (s, alt)
            if not road or s >= road[-1][0] + ROAD_STEP_M:
                road.append(last_row)
        if last_row is not None and road[-1] != last_row:
            road.append(last_row)
        info = None
        for _, m, _ in bag.read_messages(topics=[RUN_INFO_TOPIC]):
            info = json.loads(m.data)
    return duration, road, info


def title_of(info, bag):
    if not info:
        return "replay of %s" % bag
    a = info.get("args", {})
    return "%s, %s engine, %s degC (replay)" % (info.get("scenario", "?"), a.get("engine", "map"),
                                                a.get("ambient", "25"))


def main():
    ap = argparse.ArgumentParser(prog="twin replay", description=__doc__.split("\n")[0])
    ap.add_argument("bag")
    ap.add_argument("--rate", default="1", help="playback speed (positive; 1 = real time)")
    ap.add_argument("--start", default="0", help="start this many seconds into the bag")
    ap.add_argument("--no-rviz", action="store_true", help="markers only, no rviz window")
    a = ap.parse_args()
    rate = positive_number("--rate", a.rate)
    try:
        start = float(a.start)
    except ValueError:
        fail("--start '%s' is not a number" % a.start)
    if not os.path.isfile(a.bag):
        fail("no such bag: %s" % a.bag)
    bag = os.path.abspath(a.bag)
    duration, road, info = read_bag(bag)
    if not math.isfinite(start) or start < 0.0 or start >= duration:
        fail("--start %s is outside the bag %s: 0 <= start < %.1f s" % (a.start, a.bag, duration))
    if info is not None:
        stops_text = info.get("stops_csv", "")
    else:
        beside = os.path.join(os.path.dirname(bag), "stops.csv")
        if not os.path.exists(beside):
            fail("%s has no %s (not written by scripts/twin run, or the run did not end) and there is "
                 "no stops.csv next to it: the stops are unknown" % (a.bag, RUN_INFO_TOPIC))
        stops_text = open(beside).read()
    if not stops_text.strip():
        fail("%s: %s has no stops_csv" % (a.bag, RUN_INFO_TOPIC))

    tmp = tempfile.mkdtemp(prefix="twin_replay_")
    try:
        with open(os.path.join(tmp, "road.csv"), "w") as f:
            f.write("# road of %s: altitude = integral of grade over distance\ndistance_m,altitude_m\n" % bag)
            f.writelines("%.3f,%.4f\n" % r for r in road)
        with open(os.path.join(tmp, "stops.csv"), "w") as f:
            f.write(stops_text)
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            port = s.getsockname()[1]
        env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % port)
        cmd = ["roslaunch", "--no-summary", "-p", str(port),
               os.path.join(REPO, "launch", "include", "replay.launch"), "bag:=" + bag,
               "rate:=%r" % rate, "start:=%r" % start, "rviz:=%s" % ("false" if a.no_rviz else "true"),
               "profile_csv:=" + os.path.join(tmp, "road.csv"), "stops_csv:=" + os.path.join(tmp, "stops.csv"),
               "title:=" + title_of(info, a.bag)]
        print("twin: replaying %s from %.1f s of %.1f s at %gx%s" % (
            a.bag, start, duration, rate, "" if a.no_rviz else " (close the rviz window to end)"), flush=True)
        proc = subprocess.Popen(cmd, env=env)
        # Ctrl-C reaches roslaunch too (same process group): let it stop its nodes and master
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        return proc.wait()
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
