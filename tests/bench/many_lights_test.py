"""bench/many_lights.py end to end at a toy scale: it writes its table, CSV and
plot with a row per light selection. Asserts what it writes, never how fast."""

import os
import subprocess
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))


class ManyLightsBench(unittest.TestCase):
    def test_writes_the_equal_time_table(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            result = subprocess.run(
                ["/usr/bin/python3", str(ROOT / "bench" / "many_lights.py"), "--out", str(out), "--caustica", BINARY,
                 "--res", "8", "--max-spp", "4", "--reference-spp", "16"],
                capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            table = (out / "many_lights.md").read_text()
            self.assertIn("| power | 4 |", table)
            self.assertIn("| tree | 4 |", table)
            self.assertTrue((out / "plots" / "many_lights.png").exists())
            self.assertEqual(len((out / "many_lights.csv").read_text().splitlines()), 1 + 2 * 3)


if __name__ == "__main__":
    unittest.main()
