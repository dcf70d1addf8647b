#!/usr/bin/python3
"""rostest node: watches /mass_a/state, /mass_b/state and /sim/status while the oscillator
scenario runs and checks the lock-step contract: every macro-step stamp appears exactly once per
topic and in order (no step lost or repeated, t = 0 included: each mass reads the other's state
at every step, so every stamp is sent), every participant's DONE reports move forward, and the
state follows the exact two-mass solution."""
import math
import threading
import unittest

import rospy
import rostest
from hybrid_bus_twin.msg import ProbeSignal, StepStatus

DT_NS = 1000000  # 1 ms macro step (protocol.test)
N = 500          # steps observed


class LockStep(unittest.TestCase):
    def test_lockstep(self):
        rospy.init_node("lockstep_check")
        lock = threading.Lock()
        stamps = {"/mass_a/state": [], "/mass_b/state": []}
        xa = {}
        last_done = {}
        errors = []

        def on_state(topic):
            def cb(msg):
                with lock:
                    stamps[topic].append(msg.header.stamp.to_nsec())
                    if topic == "/mass_a/state":
                        xa[msg.header.stamp.to_sec()] = msg.values[0]
            return cb

        def on_status(s):
            if s.status == StepStatus.DONE:
                with lock:
                    prev = last_done.get(s.node)
                    if prev is not None and s.step <= prev:
                        errors.append("%s reported done through step %d after %d" % (s.node, s.step, prev))
                    last_done[s.node] = s.step

        subs = [rospy.Subscriber(t, ProbeSignal, on_state(t), queue_size=10000) for t in stamps]
        subs.append(rospy.Subscriber("/sim/status", StepStatus, on_status, queue_size=10000))
        import time
        t0 = time.time()
        while time.time() - t0 < 50.0:
            with lock:
                if all(len(v) > N for v in stamps.values()):
                    break
            time.sleep(0.05)
        with lock:
            self.assertEqual(errors, [])
            for topic, st in stamps.items():
                self.assertGreater(len(st), N, topic)
                # the test node may have connected after t = 0: from its first stamp on, contiguous
                first = st[0] // DT_NS
                self.assertEqual(st[:N], [(first + i) * DT_NS for i in range(N)], topic)
            w1, w2 = math.sqrt(100.0), math.sqrt(140.0)
            err = max(abs(x - 0.5 * (math.cos(w1 * t) + math.cos(w2 * t))) for t, x in xa.items())
            self.assertLess(err, 0.02)


if __name__ == "__main__":
    rostest.rosrun("hybrid_bus_twin", "lockstep_check", LockStep)
