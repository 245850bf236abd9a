"""bench/guiding.py end to end at a toy scale: it writes its table, CSV and
plot with a row per integrator. Asserts what it writes, never how fast."""

import os
import subprocess
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))


class GuidingBench(unittest.TestCase):
    def test_writes_the_equal_time_table(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            result = subprocess.run(
                ["/usr/bin/python3", str(ROOT / "bench" / "guiding.py"), "--out", str(out), "--caustica", BINARY,
                 "--scenes", "cornell-box-baffle", "--res", "8", "--max-spp", "4", "--reference-spp", "16"],
                capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            table = (out / "guiding.md").read_text()
            for integrator in ("path", "guided_path", "bdpt"):
                self.assertIn(f"| cornell-box-baffle | {integrator} | 4 |", table)
            self.assertIn("guiding:", table)
            self.assertTrue((out / "plots" / "guiding.png").exists())
            self.assertEqual(len((out / "guiding.csv").read_text().splitlines()) - 9, 3 * 3)


if __name__ == "__main__":
    unittest.main()
