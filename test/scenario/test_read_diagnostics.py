#!/usr/bin/env python3
"""The report's diagnostics reader (twin_tools.report.diagnostics.read_diagnostics) on
diagnostics bags written here with known statuses: the tail read taken when the run's
participants are known gives what the whole bag gives, and an aborted node (no final status, its
last status before the tail) sends it back to the whole bag. No ROS master needed (rosbag and
the message classes only)."""
import os
import shutil
import sys
import tempfile
import unittest
from unittest import mock

import genpy
import rosbag
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from twin_tools.report import diagnostics  # noqa: E402

END_S = 30.0  # [s] simulated end of the synthetic runs


def status(name, t, final, extra=()):
    values = [KeyValue("final", "true" if final else "false"), KeyValue("t", "%.1f" % t)]
    values += [KeyValue(k, v) for k, v in extra]
    return DiagnosticStatus(level=0, name=name, message="", hardware_id="", values=values)


def write_bag(path, nodes_until):
    """diagnostics.bag: every node of nodes_until {name: last second or None} publishes at every
    simulated second up to its last second; nodes with None run to END_S and publish a final
    status there (with a warning key, as the participants do)."""
    with rosbag.Bag(path, "w") as bag:
        for k in range(0, int(END_S) + 1):
            t = float(k)
            for name, last in sorted(nodes_until.items()):
                if last is not None and t > last:
                    continue
                msg = DiagnosticArray()
                msg.header.stamp = genpy.Time.from_sec(t)
                msg.status = [status(name, t, False)]
                bag.write(diagnostics.DIAGNOSTICS_TOPIC, msg, msg.header.stamp)
        for name, last in sorted(nodes_until.items()):
            if last is None:
                msg = DiagnosticArray()
                msg.header.stamp = genpy.Time.from_sec(END_S + 0.4)
                msg.status = [status(name, END_S + 0.4, True,
                                     [("warning/w/first_time_s", "12.0"), ("warning/w/raised", "1")])]
                bag.write(diagnostics.DIAGNOSTICS_TOPIC, msg, msg.header.stamp)


class ReadDiagnostics(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="hbt_diag_")
        self.run_bag = os.path.join(self.tmp, "run.bag")  # only its folder is used

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def read(self, participants):
        """(nodes, start times of every read_messages call: None = the whole bag)."""
        starts = []
        original = rosbag.Bag.read_messages

        def spy(bag, *args, **kwargs):
            st = kwargs.get("start_time")
            starts.append(None if st is None else st.to_sec())
            return original(bag, *args, **kwargs)
        with mock.patch.object(rosbag.Bag, "read_messages", spy):
            return diagnostics.read_diagnostics(self.run_bag, participants=participants), starts

    def test_a_normal_end_reads_the_tail_only_and_gives_what_the_whole_bag_gives(self):
        write_bag(os.path.join(self.tmp, diagnostics.DIAGNOSTICS_BAG), {"a": None, "b": None})
        whole, starts_whole = self.read(None)
        tail, starts_tail = self.read(["a", "b"])
        self.assertEqual(starts_whole, [None])
        self.assertEqual(len(starts_tail), 1)
        self.assertAlmostEqual(starts_tail[0], END_S + 0.4 - diagnostics.TAIL_S, places=6)
        self.assertEqual(tail, whole)
        for name in ("a", "b"):
            self.assertTrue(tail[name]["final"])
            self.assertAlmostEqual(tail[name]["t"], END_S + 0.4)
            self.assertEqual(tail[name]["values"]["warning/w/first_time_s"], "12.0")

    def test_a_node_that_stopped_early_sends_it_to_the_whole_bag(self):
        write_bag(os.path.join(self.tmp, diagnostics.DIAGNOSTICS_BAG), {"a": None, "b": None, "c": 7.0})
        nodes, starts = self.read(["a", "b", "c"])
        self.assertEqual(len(starts), 2)
        self.assertAlmostEqual(starts[0], END_S + 0.4 - diagnostics.TAIL_S, places=6)
        self.assertIsNone(starts[1])
        self.assertFalse(nodes["c"]["final"])
        self.assertEqual(nodes["c"]["t"], 7.0)  # its last periodic status
        self.assertTrue(nodes["a"]["final"] and nodes["b"]["final"])

    def test_no_final_status_in_the_tail_sends_it_to_the_whole_bag(self):
        # an interrupted run: everyone publishes to the end, nobody a final status
        write_bag(os.path.join(self.tmp, diagnostics.DIAGNOSTICS_BAG), {"a": END_S, "b": END_S})
        nodes, starts = self.read(["a", "b"])
        self.assertEqual(len(starts), 2)
        self.assertAlmostEqual(starts[0], END_S - diagnostics.TAIL_S, places=6)
        self.assertIsNone(starts[1])
        self.assertEqual({n: (st["final"], st["t"]) for n, st in nodes.items()},
                         {"a": (False, END_S), "b": (False, END_S)})

    def test_an_empty_diagnostics_bag_gives_no_node(self):
        rosbag.Bag(os.path.join(self.tmp, diagnostics.DIAGNOSTICS_BAG), "w").close()
        self.assertEqual(self.read(["a"])[0], {})
        self.assertEqual(self.read(None)[0], {})

    def test_no_diagnostics_bag_is_none(self):
        self.assertIsNone(diagnostics.read_diagnostics(self.run_bag, participants=["a"]))


if __name__ == "__main__":
    unittest.main()
