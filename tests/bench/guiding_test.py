"""bench/guiding.py end to end at a toy scale: it writes its table, CSV and
plot with a row per integrator. Asserts what it writes, never how fast."""

import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))
sys.path.insert(0, str(ROOT / "bench"))

import convergence  # noqa: E402


class ClockStub:
    """Stands in for the renderer: each render of an integrator takes the next of its given seconds."""

    def __init__(self, seconds, samples=64):
        self.seconds = {name: list(times) for name, times in seconds.items()}
        self.samples = samples
        self.calls = []

    def render(self, scene, output, *, integrator, spp, seed, res):
        self.calls.append((integrator, spp, seed))
        return {"seconds": self.seconds[integrator].pop(0), "samples": self.samples}


class GuidingBench(unittest.TestCase):
    def test_writes_the_equal_time_table(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            result = subprocess.run(
                ["/usr/bin/python3", str(ROOT / "bench" / "guiding.py"), "--out", str(out), "--caustica", BINARY,
                 "--scenes", "cornell-box-baffle", "--res", "8", "--max-spp", "4", "--reference-spp", "16",
                 "--repeat", "2"],
                capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            table = (out / "guiding.md").read_text()
            for integrator in ("path", "guided_path", "bdpt"):
                self.assertIn(f"| cornell-box-baffle | {integrator} | 4 |", table)
            self.assertIn("guiding:", table)
            self.assertIn("one thread, the least of 2 runs taking turns", table)
            self.assertTrue((out / "plots" / "guiding.png").exists())
            self.assertEqual(len((out / "guiding.csv").read_text().splitlines()) - 9, 3 * 3)

    def test_refuses_fewer_than_one_run(self):
        result = subprocess.run(
            ["/usr/bin/python3", str(ROOT / "bench" / "guiding.py"), "--out", "unused", "--caustica", BINARY,
             "--repeat", "0"], capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("--repeat must be at least 1, not 0", result.stderr)


class RetimeLongest(unittest.TestCase):
    def rows(self):
        return [{"scene": "box", "integrator": name, "spp": spp, "seconds": 5.0, "samples": 64}
                for name in ("path", "guided_path") for spp in (1, 2)]

    def test_keeps_the_least_seconds_of_the_longest_runs(self):
        rows = self.rows()
        stub = ClockStub({"path": [4.0, 6.0], "guided_path": [7.0, 3.5]})
        convergence.retime_longest(stub, "box", "box.xml", rows, [1, 2], 8, Path("unused"), 3)
        # The stub's clock readings, not a measurement: which of them each row keeps.
        kept_readings = {(r["integrator"], r["spp"]): r["seconds"] for r in rows}
        self.assertEqual(kept_readings, {("path", 1): 5.0, ("path", 2): 4.0, ("guided_path", 1): 5.0,
                                         ("guided_path", 2): 3.5})
        # Taking turns, each with the longest run's own seed.
        seed = convergence.ladder_seed(1)
        self.assertEqual(stub.calls, [("path", 2, seed), ("guided_path", 2, seed)] * 2)

    def test_a_repeat_that_took_other_samples_is_an_error(self):
        with self.assertRaisesRegex(RuntimeError, "box / path: a repeated run took 32 samples, the first 64"):
            convergence.retime_longest(ClockStub({"path": [1.0]}, samples=32), "box", "box.xml",
                                   self.rows()[:2], [1, 2], 8, Path("unused"), 2)


if __name__ == "__main__":
    unittest.main()
