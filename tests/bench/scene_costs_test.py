"""bench/scene_costs.py's sorting of perf's report into kinds of work, on a
report written here (perf itself is not among the test machine's packages)."""

import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
from scene_costs import categorise  # noqa: E402

REPORT = """
# Samples: 9K of event 'cpu-clock'
#
    15.94%  ld-linux-x86-64.so.2          [.] do_lookup_x
    14.64%  [kernel.kallsyms]             [k] pvm_irq_enable
     5.31%  libc.so.6                     [.] _int_malloc
     4.80%  caustica                      [.] caustica::light_importance
     3.65%  caustica                      [.] caustica::TriangleMesh::interaction
     3.21%  caustica                      [.] caustica::(anonymous namespace)::beckmann_visible_slope
     2.56%  libm.so.6                     [.] __erf
     2.00%  libembree3.so.3               [.] embree::avx2::BVHNIntersector1<8, 1, true>::intersect
     1.43%  libz.so.1.2.13                [.] 0x0000000000004a26
     1.42%  caustica                      [.] caustica::(anonymous namespace)::LowDiscrepancySampler::next_2d
     1.00%  caustica                      [.] caustica::Transform::vector
            |
            --0.95%--0x36ee0006c1880000
"""


class Categorise(unittest.TestCase):
    def test_sums_each_kind_of_work(self):
        shares = categorise(REPORT)
        self.assertAlmostEqual(shares["start-up (dynamic linking)"], 15.94)
        self.assertAlmostEqual(shares["kernel (page faults, allocation)"], 14.64)
        self.assertAlmostEqual(shares["malloc and memset"], 5.31)
        self.assertAlmostEqual(shares["light choice"], 4.80)
        self.assertAlmostEqual(shares["hit to interaction"], 3.65)
        # erf is the Beckmann distribution's, not the maths library's.
        self.assertAlmostEqual(shares["BSDFs"], 3.21 + 2.56)
        self.assertAlmostEqual(shares["Embree traversal"], 2.00)
        self.assertAlmostEqual(shares["file reading and writing"], 1.43)
        self.assertAlmostEqual(shares["sampler"], 1.42)
        self.assertAlmostEqual(shares["other"], 1.00)
        self.assertAlmostEqual(sum(shares.values()), 15.94 + 14.64 + 5.31 + 4.80 + 3.65 + 3.21 + 2.56 + 2.00 + 1.43
                               + 1.42 + 1.00)


if __name__ == "__main__":
    unittest.main()
