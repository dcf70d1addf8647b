#!/usr/bin/python3
"""The wiring as the Python tools read it (twin_tools.wiring), against the files it comes from:
every participant of launch/include/urban.launch has its folder src/<name>/ with node/topics.yaml,
its config, and its nodelet plugin; every declared message type exists in msg/; a key not
declared is an error naming the topics.yaml and the key."""
import glob
import os
import unittest

from twin_tools import wiring
from twin_tools.paths import REPO


class Wiring(unittest.TestCase):
    def test_every_participant_has_its_five_places(self):
        names = wiring.participants()
        self.assertEqual(len(names), len(set(names)), names)
        self.assertEqual(set(names), {"vehicle", "engine", "aftertreatment", "cooling", "hvac", "ems", "emachine", "battery"})
        with open(os.path.join(REPO, "nodelet_plugins.xml")) as f:
            plugins = f.read()
        for n in names:
            self.assertTrue(os.path.isfile(os.path.join(REPO, "src", n, "CMakeLists.txt")), n)
            with open(os.path.join(REPO, "src", n, "node", "CMakeLists.txt")) as f:
                self.assertIn("hbt_add_participant(%s\n" % n, f.read())
            self.assertTrue(os.path.isfile(wiring.topics_file(n)), n)
            self.assertIn('name="hybrid_bus_twin/%s"' % n, plugins)
            configs = glob.glob(os.path.join(REPO, "config", n + "*.yaml"))
            self.assertTrue(configs, "no config/%s*.yaml" % n)

    def test_declared_types_exist_and_topics_follow_the_name(self):
        msgs = {os.path.basename(p)[:-4] for p in glob.glob(os.path.join(REPO, "msg", "*.msg"))}
        n_topics = 0
        for n in wiring.participants():
            for key, typ in wiring.declared(n).items():
                pkg, name = typ.split("/")
                self.assertEqual(pkg, "hybrid_bus_twin", (n, key))
                self.assertIn(name, msgs, (n, key))
                self.assertEqual(wiring.topic(n, key), "/%s/%s" % (n, key))
                n_topics += 1
        self.assertEqual(n_topics, 14)

    def test_an_undeclared_key_is_named_with_its_file(self):
        with self.assertRaises(wiring.WiringError) as cm:
            wiring.topic("engine", "exhaust_gas")
        self.assertIn(wiring.topics_file("engine"), str(cm.exception))
        self.assertIn("publishes/exhaust_gas", str(cm.exception))
        with self.assertRaises(wiring.WiringError):
            wiring.declared("no_such_participant")


if __name__ == "__main__":
    unittest.main()
