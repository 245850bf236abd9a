"""The convergence figures on synthetic runs whose answers are known."""

import math
import random
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))

import fit  # noqa: E402
import summary  # noqa: E402
from suite_config import spp_ladder  # noqa: E402


class FitSlope(unittest.TestCase):
    def test_exact_power_law(self):
        times = [0.1 * 2**k for k in range(8)]
        slope, intercept = fit.fit_slope(times, [3e-2 * t**-1 for t in times])
        self.assertAlmostEqual(slope, -1, places=12)
        self.assertAlmostEqual(intercept, math.log10(3e-2), places=12)

    def test_noisy_monte_carlo_runs(self):
        # Error ~ 1/t with 20% multiplicative noise: the slope stays near -1.
        rng = random.Random(7)
        times = [0.01 * 2**k for k in range(12)]
        errors = [0.5 / t * math.exp(rng.gauss(0, 0.2)) for t in times]
        slope, _ = fit.fit_slope(times, errors)
        self.assertAlmostEqual(slope, -1, delta=0.05)

    def test_half_slope(self):
        times = [1, 10, 100]
        self.assertAlmostEqual(fit.fit_slope(times, [1, 10**-0.5, 0.1])[0], -0.5, places=12)

    def test_unusable_points_are_left_out(self):
        # A corrected error at or below zero has no logarithm.
        self.assertAlmostEqual(fit.fit_slope([1, 10, 100, 1000], [1, 0.1, 0.01, -1e-4])[0], -1, places=12)
        self.assertIsNone(fit.fit_slope([1, 10], [1, 0]))
        self.assertIsNone(fit.fit_slope([5, 5], [1, 2]))


class TimeToReach(unittest.TestCase):
    def test_interpolates_between_runs_in_log_log(self):
        # Error 1/t: reaches 0.05 at t = 20, between the runs at 10 and 40.
        seconds, extrapolated = fit.time_to_reach([10, 40, 160], [0.1, 0.025, 0.00625], 0.05)
        self.assertAlmostEqual(seconds, 20, places=9)
        self.assertFalse(extrapolated)

    def test_the_first_run_may_already_be_there(self):
        self.assertEqual(fit.time_to_reach([2, 4], [0.01, 0.005], 0.1), (2, False))

    def test_extrapolates_a_falling_tail(self):
        seconds, extrapolated = fit.time_to_reach([1, 2, 4, 8], [1, 0.5, 0.25, 0.125], 0.01)
        self.assertAlmostEqual(seconds, 100, places=6)
        self.assertTrue(extrapolated)

    def test_a_stalled_error_never_gets_there(self):
        # Bias: the error falls, then stops at 0.1.
        self.assertIsNone(fit.time_to_reach([1, 2, 4, 8, 16], [1, 0.3, 0.11, 0.1, 0.1], 0.01))


class Efficiency(unittest.TestCase):
    def test_inverse_of_error_times_time(self):
        self.assertAlmostEqual(fit.efficiency(0.01, 4), 25)
        self.assertTrue(math.isnan(fit.efficiency(0, 4)))


class Summary(unittest.TestCase):
    def rows(self, integrator, errors):
        return [{"scene": "box", "integrator": integrator, "spp": 2**k, "seconds": 0.5 * 2**k, "rays": 1e6 * 2**k,
                 summary.METRIC: e} for k, e in enumerate(errors)]

    def test_table_per_scene_and_integrator(self):
        rows = self.rows("path", [0.8, 0.4, 0.2, 0.1]) + self.rows("direct", [0.5, 0.3, 0.3, 0.3])
        table = summary.summarize(rows, target=0.1)
        self.assertEqual([(t["scene"], t["integrator"]) for t in table], [("box", "path"), ("box", "direct")])
        path, direct = table
        self.assertAlmostEqual(path["slope"], -1)
        self.assertAlmostEqual(path["efficiency"], 1 / (0.1 * 4))
        self.assertEqual(path["time_to_target"], (4, False))
        self.assertAlmostEqual(path["mrays_per_second"], 2)
        self.assertIsNone(direct["time_to_target"])
        text = summary.markdown(table, 0.1)
        self.assertIn("| box | path | 8 | 4 | 0.1 | -1.00 | 2.5 | 4 | 2 |", text)
        self.assertIn("| box | direct | 8 | 4 | 0.3 |", text)
        self.assertIn("not reached", text)


class Ladder(unittest.TestCase):
    def test_powers_of_two(self):
        self.assertEqual(spp_ladder(16), [1, 2, 4, 8, 16])
        self.assertEqual(spp_ladder(12), [1, 2, 4, 8])
        self.assertEqual(spp_ladder(1), [1])


if __name__ == "__main__":
    unittest.main()
