#!/usr/bin/python3
"""The soak's memory verdict on constructed runs with known answers (no ROS): the fitted rise is
exact on a line; a heap that stays level (with noise) is flat; one that grows by 1 MiB per mission,
or within one mission by more than the allowance, is not."""
import random
import unittest

from twin_tools.bench import soak


def runs(late, early=None, scenario="baseline_urban"):
    early = early or late
    return [{"scenario": scenario, "anon_early_mib": e, "anon_late_mib": l} for e, l in zip(early, late)]


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


if __name__ == "__main__":
    unittest.main()
