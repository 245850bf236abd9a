"""The benchmark suite end to end at its tiny scale (a 16x16 Cornell box, a
few samples), and the resumable reference. Needs CAUSTICA_BINARY, which
ctest sets; asserts what the suite writes, never how fast it ran."""

import csv
import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))

from caustica_cli import Caustica, read_metadata  # noqa: E402
from reference import make_reference  # noqa: E402

BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))


class TinySuite(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out = Path(cls.tmp.name)
        cls.result = subprocess.run(
            ["/usr/bin/python3", str(ROOT / "bench" / "suite.py"), "--scale", "tiny", "--out", str(cls.out),
             "--caustica", BINARY, "--threads", "2", "--integrators", "path,direct,ptracer,no-such-integrator",
             "--samplers", "independent,ldsampler"],
            capture_output=True, text=True)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_runs_and_skips_an_unknown_integrator(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr)
        self.assertIn("skipping integrator 'no-such-integrator'", self.result.stdout)

    def test_convergence_csv(self):
        with open(self.out / "convergence.csv") as f:
            lines = f.readlines()
        self.assertTrue(any("E[(x - ref)^2] = E[(x - truth)^2] + Var[ref]" in line for line in lines))
        rows = list(csv.DictReader(line for line in lines if not line.startswith("#")))
        self.assertEqual([(r["integrator"], int(r["spp"])) for r in rows],
                         [(i, s) for i in ("path", "path@ldsampler", "direct", "direct@ldsampler", "ptracer",
                                           "ptracer@ldsampler") for s in (1, 2, 4, 8, 16)])
        for r in rows:
            self.assertEqual(r["scene"], "cornell-box")
            self.assertEqual(int(r["samples"]), 16 * 16 * int(r["spp"]))
            self.assertGreater(int(r["rays"]), 0)
            self.assertGreater(float(r["mse"]), 0)
            self.assertAlmostEqual(float(r["mse_corrected"]), float(r["mse"]) - float(r["reference_estimated_mse"]),
                                   delta=1e-6 * float(r["mse"]))

    def test_reference_carries_its_error(self):
        metadata = read_metadata(self.out / "references" / "cornell-box.exr")
        self.assertEqual(metadata["spp"], "256")
        self.assertEqual(metadata["seeds"], "1000000,1000001")
        self.assertGreater(float(metadata["estimated_rel_mse"]), 0)

    def test_plots_variance_and_summary(self):
        for name in ["cornell-box.png", "cornell-box.svg", "convergence.png", "convergence.svg", "variance.png"]:
            self.assertGreater((self.out / "plots" / name).stat().st_size, 1000, name)
        with open(self.out / "variance.csv") as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([r["integrator"] for r in rows],
                         ["path", "path@ldsampler", "direct", "direct@ldsampler", "ptracer", "ptracer@ldsampler"])
        for r in rows:
            self.assertGreater(float(r["mean_variance"]), 0)
            self.assertAlmostEqual(float(r["variance_per_sample"]), float(r["mean_variance"]) * 16, places=6)
        # ptracer splats and writes no variance layers, and ldsampler's layers would overstate its variance: an
        # independent twin render stands in.
        self.assertTrue((self.out / "renders" / "cornell-box" / "ptracer-000016spp-twin.exr").exists())
        self.assertTrue((self.out / "renders" / "cornell-box" / "path@ldsampler-000016spp-twin.exr").exists())
        self.assertFalse((self.out / "renders" / "cornell-box" / "path-000016spp-twin.exr").exists())
        summary = (self.out / "summary.md").read_text()
        self.assertIn("| cornell-box | path | 16 |", summary)
        self.assertIn("| cornell-box | direct | 16 |", summary)
        self.assertIn("| cornell-box | ptracer | 16 |", summary)
        self.assertIn("Skipped: no-such-integrator", summary)


class SceneWithMedia(unittest.TestCase):
    """On the fog box, an integrator that does not render media is skipped
    for that scene alone, and the others run."""

    def test_refusing_integrator_is_skipped_per_scene(self):
        with tempfile.TemporaryDirectory() as tmp:
            result = subprocess.run(
                ["/usr/bin/python3", str(ROOT / "bench" / "suite.py"), "--scale", "tiny", "--out", tmp, "--caustica",
                 BINARY, "--threads", "2", "--integrators", "path,direct", "--samplers", "independent", "--scenes",
                 "cornell-box-fog"],
                capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("skipping integrator 'direct' on cornell-box-fog", result.stdout)
            with open(Path(tmp) / "convergence.csv") as f:
                rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
            self.assertEqual({(r["scene"], r["integrator"]) for r in rows}, {("cornell-box-fog", "path")})


class ResumableReference(unittest.TestCase):
    def test_only_missing_chunks_are_rendered(self):
        with tempfile.TemporaryDirectory() as tmp:
            caustica = Caustica(BINARY, 2)
            reference = Path(tmp) / "ref.exr"
            scene = ROOT / "scenes" / "cornell-box.xml"
            logged = []
            make = lambda: make_reference(caustica, scene, reference, spp=10, chunk_spp=4, res=8,  # noqa: E731
                                          log=logged.append)
            metadata = make()
            self.assertEqual(sum("chunk" in line for line in logged), 3)  # 4 + 4 + 2 samples
            self.assertEqual(metadata["spp"], "10")
            logged.clear()
            (reference.with_suffix(".chunks") / "chunk-0001.exr").unlink()
            make()
            self.assertEqual([line for line in logged if "chunk" in line], ["  reference ref.exr: chunk 2 of 3, 4 spp"])


if __name__ == "__main__":
    unittest.main()
