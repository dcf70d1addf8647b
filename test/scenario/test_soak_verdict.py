#!/usr/bin/python3
"""The soak's memory verdict on constructed runs with known answers (no ROS): the fitted rise is
exact on a line; a heap that stays level (with noise) is flat; one that grows by 1 MiB per mission,
or within one mission by more than the allowance beyond its bag queue's high-water mark, is not; a
step within a mission up to that high-water mark (the bounded writer queue) is flat."""
import random
import unittest

from twin_tools.bench import soak


def runs(late, early=None, scenario="baseline_urban", queue=None):
    early = early or late
    queue = queue or [None] * len(late)
    return [{"scenario": scenario, "anon_early_mib": e, "anon_late_mib": l, "bag_queue_high_water_mib": q}
            for e, l, q in zip(early, late, queue)]


class SoakVerdict(unittest.TestCase):
    def test_fitted_rise_exact_on_a_line(self):
        self.assertAlmostEqual(soak.fitted_rise([30.0 + 0.5 * i for i in range(10)]), 4.5, places=12)
        self.assertEqual(soak.fitted_rise([7.0] * 5), 0.0)
        self.assertIsNone(soak.fitted_rise([1.0]))

    def test_level_heap_with_noise_is_flat(self):
        rng = random.Random(3)
        late = [30.0 + rng.uniform(-0.5, 0.5) for _ in range(10)]
        lines, flat = soak.memory_verdict(runs(late) + runs(late, scenario="hybrid_urban"))
        self.assertTrue(flat, lines)
        self.assertEqual(len(lines), 2)

    def test_growth_from_mission_to_mission_is_found(self):
        late = [30.0 + 1.0 * i for i in range(10)]  # +9 MiB over the soak: ~26 % of the mean
        lines, flat = soak.memory_verdict(runs(late))
        self.assertFalse(flat)
        self.assertIn("GROWS", lines[0])

    def test_growth_within_a_mission_is_found(self):
        late = [30.0] * 10
        early = [30.0] * 9 + [27.0]  # the last mission grew 3 MiB (10 %) while it ran
        lines, flat = soak.memory_verdict(runs(late, early))
        self.assertFalse(flat)

    def test_step_up_to_the_bag_queue_high_water_is_flat(self):
        late = [30.0] * 10
        early = [30.0] * 9 + [26.0]  # the last mission's heap stepped up 4 MiB (13 %) ...
        queue = [0.5] * 9 + [4.0]    # ... while its bag queue held 4 MiB at once
        lines, flat = soak.memory_verdict(runs(late, early, queue=queue))
        self.assertTrue(flat, lines)
        queue[-1] = 1.0              # a queue of 1 MiB leaves 3 MiB (10 %) unexplained
        lines, flat = soak.memory_verdict(runs(late, early, queue=queue))
        self.assertFalse(flat, lines)
        self.assertIn("GROWS", lines[0])

    def test_early_and_late_come_from_the_managers_life(self):
        # the manager lives from 10 s to 50 s of a 200 s `twin run` (then the report is written)
        samples = [(10.0 + i, 30.0 + i, 10.0 + i) for i in range(41)]
        steady = soak.steady_samples(samples)
        self.assertEqual(steady[0], (38.0, 18.0))   # first sample at >= 10 + 0.2 * 40 = 18 s
        self.assertEqual(steady[-1], (70.0, 50.0))  # last sample
        self.assertEqual(soak.steady_samples([]), [])


if __name__ == "__main__":
    unittest.main()
