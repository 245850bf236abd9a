"""bench/radiosity.py end to end at a toy scale: it writes its table, CSV and
plot with a row per radiosity variant and patch size. Asserts what it
writes, never how fast."""

import os
import subprocess
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))


class RadiosityBench(unittest.TestCase):
    def test_writes_the_error_against_time_table(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            result = subprocess.run(
                ["/usr/bin/python3", str(ROOT / "bench" / "radiosity.py"), "--out", str(out), "--caustica", BINARY,
                 "--scenes", "cornell-box", "--res", "8", "--max-spp", "4", "--reference-spp", "16",
                 "--patches", "0.4,0.3"],
                capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            table = (out / "radiosity.md").read_text()
            for variant in ("radiosity", "radiosity adaptive"):
                for patch in ("0.4", "0.3"):
                    self.assertIn(f"| cornell-box | {variant} | {patch} |", table)
            csv = (out / "radiosity.csv").read_text()
            self.assertIn("cornell-box,path,4,", csv)
            self.assertTrue((out / "plots" / "convergence.png").exists())


if __name__ == "__main__":
    unittest.main()
