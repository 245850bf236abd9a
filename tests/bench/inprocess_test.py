"""The benchmarks' two runners agree: the module in process and the
executable render the same EXR bit for bit, merge alike, and report the
same errors (the executable prints nine digits)."""

import os
import sys
import tempfile
import unittest
from pathlib import Path

import OpenImageIO as oiio

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))

from caustica_cli import Caustica, UnknownIntegrator  # noqa: E402
from caustica_inprocess import InProcessCaustica, runner  # noqa: E402

BINARY = os.environ.get("CAUSTICA_BINARY", str(ROOT / "build" / "caustica"))
BOX = ROOT / "scenes" / "cornell-box.xml"


def pixels(path):
    return oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)


class Runners(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.out = Path(self.tmp.name)
        self.inprocess = runner(BINARY, 1)
        if not isinstance(self.inprocess, InProcessCaustica):
            self.skipTest("this build has no Python module")
        self.cli = Caustica(BINARY, 1)

    def tearDown(self):
        self.tmp.cleanup()

    def test_same_renders_merges_and_errors(self):
        made = {}
        for name, run in (("inprocess", self.inprocess), ("cli", self.cli)):
            parts = [self.out / f"{name}-{seed}.exr" for seed in (1, 2)]
            for seed, part in zip((1, 2), parts):
                meta = run.render(BOX, part, integrator="path@ldsampler", spp=4, seed=seed, res=8)
                self.assertEqual(meta["spp"], "4")
            merged = self.out / f"{name}-merged.exr"
            run.merge(parts, merged)
            made[name] = (parts, merged, run.compare(parts[0], merged))
        for a, b in zip(made["inprocess"][0] + [made["inprocess"][1]], made["cli"][0] + [made["cli"][1]]):
            self.assertTrue((pixels(a) == pixels(b)).all(), a.name)
        ours, theirs = made["inprocess"][2], made["cli"][2]
        for key, value in theirs.items():
            self.assertAlmostEqual(ours[key], value, delta=abs(value) * 1e-8, msg=key)

    def test_an_unknown_integrator_is_recognised(self):
        with self.assertRaises(UnknownIntegrator):
            self.inprocess.render(BOX, self.out / "x.exr", integrator="no-such", spp=1, seed=1, res=4)


if __name__ == "__main__":
    unittest.main()
