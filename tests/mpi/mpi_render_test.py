"""Renders under mpirun against the single-process render: equal bit for bit
for any number of ranks, time budgets agreed, and a lost rank reported
with a valid partial image. Run by ctest where Open MPI is installed (the
install script installs it); on loopback, with --oversubscribe."""

import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest
from pathlib import Path

import numpy as np
import OpenImageIO as oiio

BINARY = os.environ.get("CAUSTICA_BINARY", "build/caustica")
SOURCE = Path(__file__).resolve().parents[2]
GLASS = str(SOURCE / "scenes" / "cornell-box-glass.xml")
BOX = str(SOURCE / "scenes" / "cornell-box.xml")
# Open MPI refuses root unless told (CI and this machine run as root), and
# its shared-memory single copy needs ptrace rights containers often lack.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")


def mpirun(n, *args):
    return ["mpirun", "-n", str(n), "--oversubscribe", BINARY, *args]


def read(path):
    image = oiio.ImageInput.open(str(path))
    spec = image.spec()
    pixels = image.read_image(0, 0, 0, spec.nchannels, "float")
    image.close()
    metadata = {a.name: a.value for a in spec.extra_attribs if a.name.startswith("caustica:")}
    return list(spec.channelnames), pixels, metadata


def remainder_part(channel):
    """Part of a raw sum's remainder: where bdpt's splats span more than 2^52
    the order of the terms may show there, never in an image value."""
    return channel.startswith("raw.") and channel[-2:] in (".3", ".4", ".5")


def moment_part(channel):
    """Part of a sum behind the variance layers: plain doubles, which the
    ranks' films reproduce to rounding only."""
    return channel.startswith(("raw.weight2.", "raw.w2x"))


@unittest.skipUnless(shutil.which("mpirun"), "Open MPI's mpirun is not installed")
class MpiRender(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.out = Path(self.dir.name)

    def tearDown(self):
        self.dir.cleanup()

    def render(self, command, name, check=True):
        path = self.out / name
        result = subprocess.run(command + ["-o", str(path), "--exr-format", "float"], env=ENV, capture_output=True,
                                text=True, timeout=300)
        if check:
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        return path, result

    def assert_same_image(self, a, b, what):
        channels, x, _ = read(a)
        other, y, _ = read(b)
        self.assertEqual(channels, other, what)
        for c, name in enumerate(channels):
            if name.startswith("variance."):
                np.testing.assert_allclose(x[..., c], y[..., c], rtol=1e-6, atol=0, err_msg=f"{what}: {name}")
            elif not remainder_part(name) and not moment_part(name):
                self.assertTrue(np.array_equal(x[..., c].view(np.uint32), y[..., c].view(np.uint32)),
                                f"{what}: channel {name} differs")

    def test_any_number_of_ranks_renders_the_single_process_image(self):
        for integrator in ["path", "bdpt", "ptracer", "guided_path"]:
            args = ["render", GLASS, "-D", "res=16", "--spp", "23", "--seed", "5", "--integrator", integrator,
                    "--raw-sums", "-q"]
            single, _ = self.render([BINARY] + args, f"{integrator}.exr")
            for n in [1, 2, 3, 4]:
                ranks, _ = self.render(mpirun(n, *args), f"{integrator}-{n}.exr")
                self.assert_same_image(ranks, single, f"{integrator} on {n} ranks")
                metadata = read(ranks)[2]
                self.assertEqual(metadata["caustica:spp"], "23")
                self.assertEqual(metadata.get("caustica:ranks", "1"), str(n))

    # The ranks stop at the sample count rank 0 decides: the image is the
    # single-process render of that many samples.
    def test_a_time_budget_stops_every_rank_at_one_sample_count(self):
        args = ["render", BOX, "-D", "res=32", "--seed", "2", "-q"]
        ranks, _ = self.render(mpirun(2, *args, "--time", "1.5"), "timed.exr")
        spp = read(ranks)[2]["caustica:spp"]
        self.assertGreater(int(spp), 0)
        single, _ = self.render([BINARY] + args + ["--spp", spp], "single.exr")
        self.assert_same_image(ranks, single, f"--time 1.5 on 2 ranks ({spp} spp)")

    def test_sppm_renders_on_rank_0_alone(self):
        args = ["render", BOX, "-D", "res=16", "--spp", "3", "--seed", "2", "--integrator", "sppm:photons=2000"]
        ranks, result = self.render(mpirun(2, *args), "sppm-2.exr")
        self.assertIn("sppm keeps per-pixel state across iterations: it renders on rank 0 alone", result.stdout)
        single, _ = self.render([BINARY] + args + ["-q"], "sppm.exr")
        self.assert_same_image(ranks, single, "sppm on 2 ranks")

    def test_a_rank_that_fails_to_load_ends_the_job_with_its_message(self):
        scene = self.out / "scene.xml"
        scene.write_text("<scene version='3.0.0'><shape type='ply'><string name='filename' value='none.ply'/>"
                         "</shape></scene>")
        _, result = self.render(mpirun(2, "render", str(scene), "-q"), "none.exr", check=False)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("rank 0: error:", result.stderr)
        self.assertIn("none.ply", result.stderr)

    def killed_part_way(self, recovery, kill_mpirun=False, ranks=2, res=16):
        """Kills rank 1 (or sends mpirun a Ctrl-C) three seconds into a long
        render; its exit status, error output and partial image."""
        args = ["render", BOX, "-D", f"res={res}", "--spp", "1000000", "--seed", "4", "--raw-sums", "-q",
                "--rank-timeout", "2", "-o", str(self.out / "partial.exr"), "--exr-format", "float"]
        command = ["mpirun", "-n", str(ranks), "--oversubscribe"] + (["--enable-recovery"] if recovery else [])
        job = subprocess.Popen(command + [BINARY] + args, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True)
        rank1 = None
        deadline = time.time() + 60
        while rank1 is None and time.time() < deadline:
            for pid in os.listdir("/proc"):
                try:
                    environ = Path(f"/proc/{pid}/environ").read_bytes().split(b"\0")
                    cmdline = Path(f"/proc/{pid}/cmdline").read_bytes()
                except (OSError, ValueError):
                    continue
                if b"OMPI_COMM_WORLD_RANK=1" in environ and str(self.out).encode() in cmdline:
                    rank1 = int(pid)
            time.sleep(0.1)
        self.assertIsNotNone(rank1, "rank 1 never started")
        time.sleep(3)
        if kill_mpirun:
            job.send_signal(signal.SIGINT)
        else:
            os.kill(rank1, signal.SIGKILL)
        stdout, stderr = job.communicate(timeout=120)
        return job.returncode, stderr, self.out / "partial.exr"

    # Under --enable-recovery rank 0 notices the silence, collects the live
    # ranks' films, writes them, names the rank it lost and exits with 4
    # (which mpirun in that mode does not pass on: it returns 0); the image
    # holds its true samples, and merges with a later range.
    def test_a_lost_rank_is_named_and_the_rest_written(self):
        for ranks in [2, 3]:
            _, stderr, partial = self.killed_part_way(recovery=True, ranks=ranks)
            self.assertIn("caustica: error: lost rank 1 (no answer within --rank-timeout 2 s)", stderr)
            self.check_partial(partial)

    # Without it mpirun ends every rank at once, names the rank that died and
    # exits non-zero; rank 0 writes what it had collected within the second
    # mpirun allows.
    def test_mpirun_ending_the_job_still_leaves_the_collected_image(self):
        code, stderr, partial = self.killed_part_way(recovery=False)
        self.assertNotEqual(code, 0)
        self.assertIn("caustica: stopped by a signal while the ranks rendered", stderr)
        self.assertIn("rank 1", stderr)
        self.check_partial(partial)

    # Ctrl-C reaches the ranks as mpirun's SIGTERM, at this size mostly while
    # rank 0 renders its own share on its second thread.
    def test_ctrl_c_to_mpirun_leaves_the_collected_image(self):
        _, stderr, partial = self.killed_part_way(recovery=False, kill_mpirun=True, res=64)
        self.assertIn("caustica: stopped by a signal while the ranks rendered", stderr)
        self.assertNotIn("Segmentation fault", stderr)
        self.check_partial(partial)

    def check_partial(self, partial):
        channels, pixels, metadata = read(partial)
        spp = int(metadata["caustica:spp"])
        self.assertGreater(spp, 0)
        # The film holds as many samples as the metadata counts.
        self.assertTrue(np.all(pixels[..., channels.index("samples.Y")] == spp))
        self.assertLess(spp, 1000000)
        self.assertEqual(metadata["caustica:interrupted"], "true")
        held = metadata.get("caustica:ranges", f"0-{spp - 1}")
        counted = sum(int(b) - int(a) + 1 for a, b in (r.split("-") for r in held.split(",")))
        self.assertEqual(counted, spp)
        self.assertTrue(np.all(np.isfinite(pixels)))
        last = max(int(r.split("-")[1]) for r in held.split(","))
        more, _ = self.render([BINARY, "render", BOX, "-D", f"res={pixels.shape[1]}", "--spp", "4", "--seed", "4",
                               "--raw-sums", "-q",
                               "--first-sample", str(last + 1)], "more.exr")
        merged = self.out / "merged.exr"
        result = subprocess.run([BINARY, "merge", str(partial), str(more), "-o", str(merged)], capture_output=True,
                                text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(read(merged)[2]["caustica:spp"], str(spp + 4))


if __name__ == "__main__":
    unittest.main()
