"""The cost-ratio benchmark's arithmetic: a pass is the difference of two
render loops over the passes between them, and runs are summarised by
their median and range."""

import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))

import cost_ratios  # noqa: E402


class CostRatios(unittest.TestCase):
    def test_pass_leaves_out_the_first_pass(self):
        # A first pass of 0.5 s (its setup included), then 0.1 s each.
        self.assertAlmostEqual(cost_ratios.pass_seconds(0.5, 0.5 + 15 * 0.1, 15), 0.1, places=12)

    def test_spread_is_median_least_largest(self):
        self.assertEqual(cost_ratios.spread([4.1, 3.5, 3.9, 5.2, 3.7]), (3.9, 3.5, 5.2))
        self.assertEqual(cost_ratios.spread([2.0, 4.0]), (3.0, 2.0, 4.0))


if __name__ == "__main__":
    unittest.main()
