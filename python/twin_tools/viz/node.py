"""Live view of the twin in rviz (launch argument rviz:=true of a run, and scripts/twin replay):
not a participant of the lock-step protocol, it only listens. Publishes /twin/markers
(visualization_msgs/MarkerArray, frame 'bus'; drawn by twin_tools.viz.layout, layout
config/twin.rviz) at a wall-clock rate, whatever the simulated speed.

It subscribes to the twin's state topics as they appear on the master (checked once a wall
second): a run without battery or thermal nodes gets no gauges for them.
Parameters:
  ~profile_csv  road profile: a CSV with columns distance_m, altitude_m ('#' lines skipped),
                e.g. the run's <out>/profile.csv (read once it exists: the vehicle writes it at start)
  ~stops_csv    the mission's stops: a CSV with column distance_m (<out>/stops.csv)
  ~title        first line of the view (scenario, engine, ambient)
  ~rate_hz      wall-clock publish rate [Hz] (default 10)
"""
import csv
import os
import threading
import time

import rospy
from visualization_msgs.msg import MarkerArray

from twin_tools import wiring
from twin_tools.viz import layout as viz_layout
from twin_tools.viz import markers as viz_markers

# what the view draws: (participant, key) of the wiring; the layout finds each message under its
# participant's name (twin_tools.viz.layout)
DRAWN = (("vehicle", "state"), ("engine", "state"), ("cooling", "state"), ("aftertreatment", "state"),
         ("battery", "state"), ("emachine", "state"), ("ems", "command"), ("hvac", "state"))


def drawn_topics():
    """{topic: (participant, message class)} of DRAWN, from the participants' topics.yaml."""
    return {wiring.topic(p, k): (p, wiring.message_class(p, k)) for p, k in DRAWN}


def read_columns(path, columns, every_m=0.0):
    """Rows of the named float columns of a CSV ('#' comment lines skipped); with every_m > 0
    only rows at least every_m further along the first column."""
    rows, last = [], -1e300
    with open(path) as f:
        reader = csv.DictReader(line for line in f if not line.startswith("#"))
        missing = [c for c in columns if c not in (reader.fieldnames or [])]
        if missing:
            raise ValueError("%s: no column %s" % (path, ", ".join(missing)))
        for row in reader:
            vals = [float(row[c]) for c in columns]
            if vals[0] >= last + every_m:
                rows.append(vals)
                last = vals[0]
    return rows


class Viz:
    def __init__(self):
        self.profile_csv = rospy.get_param("~profile_csv", "")
        self.stops_csv = rospy.get_param("~stops_csv", "")
        self.title = rospy.get_param("~title", "")
        self.road = viz_layout.Road()
        self.road_loaded = self.stops_loaded = False
        self.latest = {}
        self.prev_vehicle = None      # the vehicle message before the latest: wheel/brake power
        self.lock = threading.Lock()
        self.subs = {}
        self.topics = drawn_topics()
        self.drawn = {}
        self.pub = rospy.Publisher("/twin/markers", MarkerArray, queue_size=1)

    def subscribe_new_topics(self):
        have = dict(rospy.get_published_topics())
        for topic, (key, cls) in self.topics.items():
            if topic not in self.subs and have.get(topic) == cls._type:
                self.subs[topic] = rospy.Subscriber(topic, cls, self.on_msg, key, queue_size=1)

    def on_msg(self, msg, key):
        with self.lock:
            if key == "vehicle":
                self.prev_vehicle = self.latest.get("vehicle")
            self.latest[key] = msg

    def load_files(self):
        """The road and the stops, once their files exist (the vehicle writes them at start)."""
        if not self.road_loaded and self.profile_csv and os.path.exists(self.profile_csv):
            rows = read_columns(self.profile_csv, ["distance_m", "altitude_m"], every_m=5.0)
            self.road.s, self.road.alt = [r[0] for r in rows], [r[1] for r in rows]
            self.road_loaded = True
        if not self.stops_loaded and self.stops_csv and os.path.exists(self.stops_csv):
            self.road.stops = sorted(r[0] for r in read_columns(self.stops_csv, ["distance_m"]))
            self.stops_loaded = True

    def powers(self):
        """Wheel-hub and friction-brake power [W] between the two last vehicle messages."""
        v0, v1 = self.prev_vehicle, self.latest.get("vehicle")
        if v0 is None or v1 is None:
            return 0.0, 0.0
        dt = (v1.header.stamp - v0.header.stamp).to_sec()
        if dt <= 0.0:
            return 0.0, 0.0
        return ((v1.wheel_work_j - v0.wheel_work_j) / dt,
                (v1.friction_brake_loss_j - v0.friction_brake_loss_j) / dt)

    def publish(self):
        with self.lock:
            if "vehicle" not in self.latest:
                return
            st = dict(self.latest)
            p_wheel, p_brake = self.powers()
        self.load_files()
        sc = viz_markers.Scene()
        viz_layout.draw(sc, st, self.road, self.title, p_wheel, p_brake)
        self.pub.publish(sc.finish(self.drawn))


def draw_loop(viz, period_s):
    next_check = 0.0
    while not rospy.is_shutdown():
        try:
            now = time.monotonic()
            if now >= next_check and len(viz.subs) < len(viz.topics):
                viz.subscribe_new_topics()
                next_check = now + 1.0
            viz.publish()
        except Exception:  # the master or the publisher gone while shutting down: end quietly
            if rospy.is_shutdown():
                return
            raise
        time.sleep(period_s)


def main():
    rospy.init_node("viz")
    viz = Viz()
    # drawing on a wall-clock thread; the main thread only spins, so the SIGINT handler (which
    # shuts rospy down) never runs while the drawing thread's lock is held
    threading.Thread(target=draw_loop, args=(viz, 1.0 / rospy.get_param("~rate_hz", 10.0)),
                     daemon=True).start()
    rospy.spin()


if __name__ == "__main__":
    main()
