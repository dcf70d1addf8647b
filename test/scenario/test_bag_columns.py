#!/usr/bin/python3
"""twin_tools.bags.columns (the report's bag reader) against rosbag's own reader: for every message
type of the package, filled with values that cover each field's range (bools, negative and large
integers, floats down to the smallest normal, strings and arrays), the columns equal what a loop
over rosbag.Bag.read_messages() gives (postprocess.read_run_rosbag), array for array and bit for
bit, over several chunks; topics whose layout varies (a header frame_id of changing length) are
read message by message with the same result. A compressed or cut bag is not this reader's
(Unsupported) and read_run still gives rosbag's result. twin_tools.bags.append (the run's metadata appended after a
run) leaves a bag rosbag reads as the one its own append gives: the same messages, times and
topics."""
import os
import random
import shutil
import tempfile
import unittest

import numpy as np

INT_RANGES = {"int8": (-128, 127), "byte": (-128, 127), "uint8": (0, 255), "char": (0, 255),
              "int16": (-2**15, 2**15 - 1), "uint16": (0, 2**16 - 1), "int32": (-2**31, 2**31 - 1),
              "uint32": (0, 2**32 - 1), "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1)}
FLOATS = [0.0, -0.0, 1.5, -2.25e-308, 1e300, -3.75, 123456.789, 2.2250738585072014e-308]


def fill(msg, rng, k, vary_frame):
    """Every field of msg from rng; k: the message's index (its stamp)."""
    import rospy
    for name, typ in zip(msg.__slots__, msg._slot_types):
        base, arr, n = typ, typ.endswith("]"), None
        if arr:
            base, _, n = typ[:-1].partition("[")
            n = int(n) if n else rng.randint(0, 3)
        def one():
            if base == "bool":
                return rng.random() < 0.5
            if base in INT_RANGES:
                lo, hi = INT_RANGES[base]
                return rng.choice([lo, hi, 0, rng.randint(lo, hi)])
            if base in ("float32", "float64"):
                v = rng.choice(FLOATS + [rng.uniform(-1e6, 1e6)])
                return float(np.float32(v)) if base == "float32" else v
            if base == "string":
                return "s" * rng.randint(0, 5)
            if base in ("time", "duration"):
                return rospy.Time(rng.randint(0, 1000), rng.randint(0, 999999999)) if base == "time" \
                    else rospy.Duration(rng.randint(0, 1000), 0)
            return None
        if base == "std_msgs/Header" or name == "header":
            msg.header.stamp = rospy.Time(k // 10, (k % 10) * 100000000 + rng.randint(0, 99))
            msg.header.frame_id = "f" * (k % 3) if vary_frame else "base"
            msg.header.seq = k
            continue
        if arr and base in ("uint8", "char"):
            setattr(msg, name, bytes(rng.randint(0, 255) for _ in range(n)))
        elif arr:
            vals = [one() for _ in range(n)]
            if vals and vals[0] is None:
                continue  # arrays of messages: left empty
            setattr(msg, name, vals)
        else:
            v = one()
            if v is None:  # a nested message
                fill(getattr(msg, name), rng, k, vary_frame)
            else:
                setattr(msg, name, v)


class BagColumns(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import rosbag
        import rospy
        import hybrid_bus_twin.msg as hm
        from std_msgs.msg import String
        cls.tmp = tempfile.mkdtemp(prefix="hbt_bag_columns_")
        cls.bag = os.path.join(cls.tmp, "all.bag")
        rng = random.Random(7)
        cls.types = [getattr(hm, n) for n in dir(hm) if not n.startswith("_") and hasattr(getattr(hm, n), "_type")
                     and "header" in getattr(hm, n).__slots__]
        assert len(cls.types) >= 12, cls.types
        with rosbag.Bag(cls.bag, "w", chunk_threshold=64 * 1024) as bag:
            for k in range(600):
                for i, typ in enumerate(cls.types):
                    m = typ()
                    fill(m, rng, k, vary_frame=(i == 0))
                    bag.write("/t%d/%s" % (i, typ._type.split("/")[1]), m, m.header.stamp)
            bag.write("/twin/run_info", String(data='{"scenario": "x"}'), rospy.Time(60))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def assertSameData(self, a, b):
        self.assertEqual(sorted(a), sorted(b))
        for topic in b:
            self.assertEqual(list(a[topic]), list(b[topic]), topic)
            for f in b[topic]:
                x, y = a[topic][f], b[topic][f]
                self.assertEqual(x.dtype, y.dtype, (topic, f))
                self.assertTrue(np.array_equal(x.view(np.uint64), y.view(np.uint64)), (topic, f))  # bit for bit

    def test_columns_equal_rosbags_messages(self):
        from twin_tools.bags.columns import read_columns
        from twin_tools.report.postprocess import read_run_rosbag
        cols, msgs = read_columns(self.bag, messages_of=("/twin/run_info",))
        info, data = read_run_rosbag(self.bag)
        self.assertEqual(len(data), len(self.types))
        self.assertTrue(all(len(d["t"]) == 600 for d in data.values()))
        self.assertSameData(cols, data)
        self.assertEqual(msgs["/twin/run_info"][0].data, '{"scenario": "x"}')
        self.assertEqual(info, {"scenario": "x"})
        # the fields kept: every numeric primitive, bools among them
        vs = [d for t, d in data.items() if t.endswith("/VehicleState")][0]
        self.assertIn("speed_m_s", vs)

    def test_compressed_and_cut_bags_go_through_rosbag(self):
        import rosbag
        from twin_tools.bags.columns import Unsupported, read_columns
        from twin_tools.report.postprocess import read_run, read_run_rosbag
        packed = os.path.join(self.tmp, "packed.bag")
        with rosbag.Bag(self.bag) as src, rosbag.Bag(packed, "w", compression="bz2") as dst:
            for topic, raw, t in src.read_messages(raw=True):
                dst.write(topic, raw, t, raw=True)
        with self.assertRaises(Unsupported):
            read_columns(packed)
        info, data = read_run(packed)
        self.assertSameData(data, read_run_rosbag(self.bag)[1])
        cut = os.path.join(self.tmp, "cut.bag")
        with open(self.bag, "rb") as f, open(cut, "wb") as g:
            g.write(f.read(os.path.getsize(self.bag) // 2))
        with self.assertRaises(Unsupported):
            read_columns(cut)

    def test_append_reads_as_rosbags_append(self):
        import rosbag
        import rospy
        from std_msgs.msg import String
        from twin_tools.bags.append import append_at_end
        from twin_tools.bags.columns import read_columns
        for topic in ("/twin/run_info", "/t1/" + self.types[1]._type.split("/")[1]):  # a new topic, a known one
            if topic != "/twin/run_info":
                msg = self.types[1]()
                fill(msg, random.Random(3), 5, False)
            else:
                msg = String(data='{"run": "info"}')
            ours, theirs = os.path.join(self.tmp, "ours.bag"), os.path.join(self.tmp, "theirs.bag")
            shutil.copy(self.bag, ours)
            shutil.copy(self.bag, theirs)
            append_at_end(ours, topic, msg)
            append_at_end(ours, topic, msg)  # twice: an appended bag appends again
            for _ in range(2):
                with rosbag.Bag(theirs, "a") as bag:
                    bag.write(topic, msg, rospy.Time.from_sec(bag.get_end_time()))
            with rosbag.Bag(ours) as a, rosbag.Bag(theirs) as b:
                ra, rb = {}, {}  # per topic, in order (at equal times the order across topics is rosbag's choice)
                for bag, out in ((a, ra), (b, rb)):
                    for tp, raw, t in bag.read_messages(raw=True):
                        out.setdefault(tp, []).append((raw[1], t))
                self.assertEqual(sorted(ra), sorted(rb))
                self.assertTrue(ra == rb, topic)
                self.assertEqual(a.get_end_time(), b.get_end_time())
                # (rosbag's append opens a connection per append, ours reuses the topic's)
                ta, tb = a.get_type_and_topic_info().topics, b.get_type_and_topic_info().topics
                self.assertEqual({k: (v.msg_type, v.message_count) for k, v in ta.items()},
                                 {k: (v.msg_type, v.message_count) for k, v in tb.items()})
            cols, msgs = read_columns(ours, messages_of=("/twin/run_info",))
            if topic == "/twin/run_info":
                self.assertEqual([m.data for m in msgs[topic]], ['{"scenario": "x"}'] + 2 * ['{"run": "info"}'])
            else:
                self.assertEqual(len(cols[topic]["t"]), 602)


if __name__ == "__main__":
    unittest.main()
