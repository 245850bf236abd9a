"""bench/bidirectional.py end to end at a toy scale: it writes its table, CSV
and plot with a row per integrator and scene. Asserts what it writes, never
how fast."""

import os
import subprocess
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))


class BidirectionalBench(unittest.TestCase):
    def test_writes_the_equal_time_table(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            result = subprocess.run(
                ["/usr/bin/python3", str(ROOT / "bench" / "bidirectional.py"), "--out", str(out), "--caustica",
                 BINARY, "--scenes", "cornell-box-glass,door-nearly-shut", "--res", "8", "--max-spp", "2",
                 "--reference-spp", "8", "--bootstrap", "200"],
                capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            table = (out / "bidirectional.md").read_text()
            for scene in ("cornell-box-glass", "door-nearly-shut"):
                for integrator in ("path", "bdpt", "sppm", "vcm", "vcm:merge_at=after_specular", "mlt"):
                    self.assertIn(f"| {scene} | {integrator} | 2 |", table)
            self.assertIn('value="2"', (out / "scenes" / "door-nearly-shut.xml").read_text())
            self.assertTrue((out / "plots" / "convergence.png").exists())


if __name__ == "__main__":
    unittest.main()
