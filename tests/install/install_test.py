"""The installed caustica, as another project meets it: `cmake --install`
into a fresh prefix, moved elsewhere afterwards (nothing may point back at
the build tree); a consumer project built against it with
find_package(caustica) renders the Cornell box bit for bit as the build
tree's command line does; the installed executable and Python module find
their data in the prefix."""

import os
import shutil
import subprocess
import tempfile
import unittest
from pathlib import Path

import OpenImageIO as oiio
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ["CAUSTICA_BUILD_DIR"])
BOX = ROOT / "scenes" / "cornell-box.xml"


def run(args, **kwargs):
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        raise AssertionError(f"{' '.join(map(str, args))} failed:\n{result.stdout}\n{result.stderr}")
    return result


def beauty(path):
    image = oiio.ImageBuf(str(path))
    names = list(image.spec().channelnames)
    pixels = image.get_pixels(oiio.FLOAT)
    return pixels[:, :, [names.index(c) for c in ("R", "G", "B")]]


class InstalledTree(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        tmp = Path(cls.tmp.name)
        run(["cmake", "--install", BUILD, "--prefix", tmp / "staged"])
        cls.prefix = tmp / "moved"
        shutil.move(tmp / "staged", cls.prefix)
        cls.work = tmp

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_only_the_public_header_is_installed(self):
        headers = sorted(p.relative_to(self.prefix / "include") for p in (self.prefix / "include").rglob("*")
                         if p.is_file())
        self.assertEqual(headers, [Path("caustica/caustica.h")])

    def test_a_consumer_project_renders_as_the_command_line_does(self):
        source, build = ROOT / "tests" / "install" / "consumer", self.work / "consumer"
        run(["cmake", "-S", source, "-B", build, f"-DCMAKE_PREFIX_PATH={self.prefix}", "-DCMAKE_BUILD_TYPE=Release"])
        run(["cmake", "--build", build])
        ours, theirs = self.work / "consumer.exr", self.work / "cli.exr"
        out = run([build / "render_box", BOX, ours, 3, 7]).stdout
        run([BUILD / "caustica", "render", BOX, "-o", theirs, "--spp", 3, "--seed", 7, "-D", "res=8",
             "--threads", 1, "--exr-format", "float", "--quiet"])
        self.assertTrue(np.array_equal(beauty(ours), beauty(theirs)))
        self.assertGreater(float(beauty(ours).mean()), 0)
        lines = out.splitlines()
        self.assertEqual(lines[0], "caustica 0.1.0")
        # Nine significant digits name a float exactly.
        self.assertEqual(np.float32(lines[1].split()[-1]), beauty(theirs)[4, 4, 0])
        self.assertTrue(lines[2].startswith("path "))
        self.assertEqual(lines[3], "refused: the render has no channel 'no such channel'")
        self.assertTrue(lines[4].startswith("refused: broken.xml:1:"), lines[4])

    def test_the_installed_executable_finds_its_data_in_the_prefix(self):
        out = run([self.prefix / "bin" / "caustica", "--version"]).stdout
        self.assertIn(f"RGB-to-spectrum table: {self.prefix}/share/caustica/rgb_spectrum_table.bin", out)
        self.assertIn(f"OCIO config: {self.prefix}/share/caustica/config.ocio", out)
        exr = self.work / "spectral.exr"
        run([self.prefix / "bin" / "caustica", "render", BOX, "-o", exr, "--spp", 1, "-D", "res=4", "--spectral",
             "on", "--quiet"])
        self.assertTrue(exr.exists())

    def test_the_installed_python_module_renders(self):
        modules = list(self.prefix.glob("lib/python3/dist-packages/caustica*.so"))
        if not modules:
            self.skipTest("this build has no Python module (pybind11 not installed)")
        script = ("import caustica\n"
                  f"scene = caustica.load({str(BOX)!r}, defines={{'res': '4'}})\n"
                  "print(caustica.__file__)\n"
                  "print(caustica.render(scene, spp=1, spectral='on').beauty.shape)\n")
        env = dict(os.environ, PYTHONPATH=str(self.prefix / "lib" / "python3" / "dist-packages"))
        out = run(["/usr/bin/python3", "-c", script], env=env).stdout.splitlines()
        self.assertTrue(out[0].startswith(str(self.prefix)), out[0])
        self.assertEqual(out[1], "(4, 4, 3)")


if __name__ == "__main__":
    unittest.main()
