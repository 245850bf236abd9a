"""The example convergence script runs end to end at a tiny size with the
module of this build, and reports an error for each integrator."""

import os
import re
import subprocess
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))
MODULES = Path(BINARY).resolve().parent / "python"


class ExampleConvergence(unittest.TestCase):
    def test_plots_path_and_bdpt(self):
        if not any(MODULES.glob("caustica*.so")):
            self.skipTest("this build has no Python module")
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp) / "convergence.png"
            result = subprocess.run(
                ["/usr/bin/python3", str(ROOT / "bench" / "example_convergence.py"), "--scene",
                 str(ROOT / "scenes" / "cornell-box.xml"), "--res", "8", "--reference-spp", "256", "--max-spp", "16",
                 "--out", str(out)],
                capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=str(MODULES)))
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertTrue(out.stat().st_size > 0)
        for integrator in ("path", "bdpt"):
            match = re.search(rf"^{integrator}: relMSE (\S+) in (\S+) s$", result.stdout, re.M)
            self.assertIsNotNone(match, result.stdout)
            self.assertGreater(float(match.group(1)), 0)


if __name__ == "__main__":
    unittest.main()
