"""bench/curves.py end to end at a toy scale: it writes its table with a row for
the curves and one for the triangles. Asserts what it writes, never how fast."""

import os
import subprocess
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))


class CurvesBench(unittest.TestCase):
    def test_writes_the_table(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            result = subprocess.run(
                ["/usr/bin/python3", str(ROOT / "bench" / "curves.py"), "--out", str(out), "--caustica", BINARY,
                 "--res", "8", "--spp", "1", "--sides", "3", "--steps", "1"],
                capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            table = (out / "curves.md").read_text()
            self.assertIn("| bsplinecurve |", table)
            # 1200 hairs of 4 segments, one ring each and one at the tip: 4 x 3 x 2 triangles a hair.
            self.assertIn("| triangles (28800 in all) |", table)


if __name__ == "__main__":
    unittest.main()
