#!/usr/bin/python3
"""Step-protocol tests on the two-mass oscillator scenario (test/cosim/oscillator.launch):
lock-step results against the exact solution, convergence of the coupling error with the
macro step, bit-identical repeated runs, a killed node stopping the run within 2 s with a
message naming it and a readable bag, a bad parameter rejected with its key named; multi-rate
(mass_b at twice the base step) with ordered groups end to end, and bad macro step / order keys
rejected before step 0 naming the file or parameter and the key."""
import math
import os
import signal
import tempfile
import time
import unittest

from twin_tools.launch import run_util

LAUNCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "oscillator.launch")
W1, W2 = math.sqrt(100.0), math.sqrt(140.0)  # k = 100 N/m, k_c = 20 N/m, m = 1 kg


def max_error(bag):
    import rosbag
    err, n = 0.0, 0
    with rosbag.Bag(bag) as b:
        for _, msg, _ in b.read_messages(topics=["/mass_a/state"]):
            t = msg.header.stamp.to_sec()
            err = max(err, abs(msg.values[0] - 0.5 * (math.cos(W1 * t) + math.cos(W2 * t))))
            n += 1
    return err, n


class Protocol(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="hbt_protocol_")

    def test_lockstep_matches_exact_solution_and_converges(self):
        errs = []
        for dt in (0.002, 0.001):
            out = os.path.join(self.tmp, "dt%g" % dt)
            st = run_util.run_launch(LAUNCH, out, step=dt, until=1.0)
            self.assertEqual(st["status"], "ok", st)
            err, n = max_error(os.path.join(out, "run.bag"))
            self.assertEqual(n, round(1.0 / dt) + 1, "every stamp from t=0 to t_end recorded")
            errs.append(err)
        self.assertLess(errs[1], 0.02)
        # Jacobi coupling is first order: halving the macro step halves the error.
        self.assertAlmostEqual(errs[0] / errs[1], 2.0, delta=0.3)

    def test_two_runs_are_bit_identical(self):
        runs = []
        for i in range(2):
            out = os.path.join(self.tmp, "run%d" % i)
            st = run_util.run_launch(LAUNCH, out, step=0.001, until=0.5)
            self.assertEqual(st["status"], "ok", st)
            runs.append(run_util.bag_messages(os.path.join(out, "run.bag")))
        self.assertEqual(len(runs[0]), 2 * 501)
        self.assertEqual(runs[0], runs[1])

    def test_killed_node_stops_run_within_2s(self):
        out = os.path.join(self.tmp, "kill")
        proc = run_util.start_launch(LAUNCH, out, step=0.001, until=1000.0, timeout=1.0)
        self.addCleanup(run_util.stop, proc)
        pid = run_util.pid_of_node(proc, "mass_b")
        time.sleep(3.0)  # well into the run
        self.assertIsNone(proc.poll(), "run still going before the kill")
        t_kill = time.time()
        os.kill(pid, signal.SIGKILL)
        # the stepper must stop the run by itself; roslaunch then exits
        run_util.wait(proc, 30)
        st = run_util.read_status(out)
        stop_delay = os.path.getmtime(os.path.join(out, "status.json")) - t_kill
        self.assertEqual(st["status"], "error")
        self.assertIn("mass_b", st["message"])
        self.assertLess(stop_delay, 2.0, "run stopped %.2f s after the kill" % stop_delay)
        msgs = run_util.bag_messages(os.path.join(out, "run.bag"))  # readable, indexed bag
        self.assertGreater(len(msgs), 100)

    def test_bad_parameter_names_key(self):
        out = os.path.join(self.tmp, "bad")
        proc = run_util.start_launch(LAUNCH, out, step=0.001, until=1.0, mass_a_kg=-1.0)
        run_util.wait(proc, 60)
        st = run_util.read_status(out)
        self.assertEqual(st["status"], "error")
        self.assertIn("mass_a", st["message"])
        self.assertIn("mass_kg", st["message"])
        self.assertEqual(st["steps"], 0, "no step may run with a bad parameter")

    def test_multirate_ordered_groups(self):
        """mass_b steps every 2 ms (base 1 ms) after mass_a (Gauss-Seidel); the recorder, every
        1 ms, writes each topic's held value: mass_b's state stamped floor(t / 2 ms) * 2 ms."""
        out = os.path.join(self.tmp, "multirate")
        st = run_util.run_launch(LAUNCH, out, step=0.001, until=0.5, b_macro_step=0.002,
                                 order="[[mass_a], [mass_b]]", record_period=0)
        self.assertEqual(st["status"], "ok", st)
        self.assertEqual(st["steps"], 500)
        import rosbag
        with rosbag.Bag(os.path.join(out, "run.bag")) as b:
            rows = [(topic, t.to_nsec(), m.header.stamp.to_nsec())
                    for topic, m, t in b.read_messages()]
        ms = 1000000
        for topic, period in (("/mass_a/state", ms), ("/mass_b/state", 2 * ms)):
            got = [(t, stamp) for tp, t, stamp in rows if tp == topic]
            want = [(max(1, i * ms), i * ms // period * period) for i in range(501)]  # t=0 at 1 ns
            self.assertEqual(got, want, topic)
        err, n = max_error(os.path.join(out, "run.bag"))
        self.assertEqual(n, 501)
        self.assertLess(err, 0.03)

    def test_bad_macro_step_and_order_name_key(self):
        out = os.path.join(self.tmp, "bad_rate")
        st = run_util.run_launch(LAUNCH, out, timeout_s=60, step=0.001, until=1.0,
                                 b_macro_step=0.0015)
        self.assertEqual(st["status"], "error")
        self.assertIn("mass_b", st["message"])
        self.assertIn("cosim/macro_step_s", st["message"])
        self.assertIn("not an integer multiple", st["message"])
        self.assertEqual(st["steps"], 0)
        out = os.path.join(self.tmp, "bad_order")
        st = run_util.run_launch(LAUNCH, out, timeout_s=60, step=0.001, until=1.0,
                                 order="[[mass_a], [nobody]]")
        self.assertEqual(st["status"], "error")
        self.assertIn("key 'order'", st["message"])
        self.assertIn("nobody", st["message"])
        self.assertEqual(st["steps"], 0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
