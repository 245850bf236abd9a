"""Renders kept and combined from Python: read and write as the command line
writes its EXRs, and merge as `caustica merge` merges, with its messages."""

import os
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import pytest

import caustica

ROOT = Path(__file__).resolve().parents[2]
BOX = ROOT / "scenes" / "cornell-box.xml"
CLI = os.environ["CAUSTICA_BINARY"]


def box(res=8):
    return caustica.load(BOX, defines={"res": str(res)})


def test_sample_ranges_merge_into_the_render_of_all_samples_bit_for_bit():
    scene = box()
    parts = [caustica.render(scene, spp=3, first_sample=first, seed=4, raw_sums=True) for first in (0, 3)]
    whole = caustica.render(scene, spp=6, seed=4)
    merged = caustica.merge(list(reversed(parts)))
    assert np.array_equal(merged.beauty, whole.beauty)
    assert np.array_equal(merged.layers["variance"], whole.layers["variance"])
    assert merged.metadata["caustica:spp"] == "6"


def test_independent_renders_merge_as_the_command_line_merges_their_files():
    scene = box()
    a, b = (caustica.render(scene, spp=4, seed=seed) for seed in (1, 2))
    merged = caustica.merge([a, b])
    # Equal sample counts in every pixel: the merge is the plain mean.
    mean = (a.beauty.astype(np.float64) + b.beauty.astype(np.float64)) / 2
    assert np.allclose(merged.beauty, mean, rtol=1e-6, atol=0)
    assert float(merged.metadata["caustica:estimated_mse"]) > 0
    with tempfile.TemporaryDirectory() as tmp:
        paths = [Path(tmp) / name for name in ("a.exr", "b.exr", "cli.exr")]
        a.write(paths[0])
        b.write(paths[1])
        subprocess.run([CLI, "merge", str(paths[0]), str(paths[1]), "-o", str(paths[2])], check=True,
                       capture_output=True)
        from_cli = caustica.read(paths[2])
        assert np.array_equal(from_cli.beauty, merged.beauty)
        assert np.array_equal(caustica.merge([str(paths[0]), b]).beauty, merged.beauty)
        assert from_cli.metadata["caustica:seeds"] == merged.metadata["caustica:seeds"]


def test_write_then_read_gives_the_render_back():
    result = caustica.render(box(), spp=2, seed=3, raw_sums=True)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "box.exr"
        result.write(path)
        back = caustica.read(path)
        assert np.array_equal(back.beauty, result.beauty)
        assert back.layers.keys() == result.layers.keys()
        for name, layer in result.layers.items():
            assert np.array_equal(back.layers[name], layer), name
        # The file adds what OpenImageIO writes beside caustica's own.
        assert {k: v for k, v in back.metadata.items() if k.startswith("caustica:")} == result.metadata
        # Half keeps 11 significant bits (and steps of 2^-24 below 2^-14); raw sums stay exact in float.
        result.write(Path(tmp) / "half.exr", exr_format="half")
        half = caustica.read(Path(tmp) / "half.exr")
        assert np.array_equal(half.layers["raw"], result.layers["raw"])
        plain = caustica.render(box(), spp=2, seed=3)
        plain.write(Path(tmp) / "plain-half.exr", exr_format="half")
        assert np.allclose(caustica.read(Path(tmp) / "plain-half.exr").beauty, plain.beauty, rtol=2 ** -11,
                           atol=2 ** -25)
        assert not np.array_equal(caustica.read(Path(tmp) / "plain-half.exr").beauty, plain.beauty)


def test_bad_merges_and_files_raise_the_command_lines_messages():
    scene = box()
    a = caustica.render(scene, spp=2, seed=1)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "a.exr"
        a.write(path)
        cli = subprocess.run([CLI, "merge", str(path), str(path), "-o", str(Path(tmp) / "m.exr")],
                             capture_output=True, text=True)
        assert cli.returncode != 0
        with pytest.raises(ValueError) as raised:
            caustica.merge([path, path])
        assert str(raised.value) in cli.stderr and "seed" in str(raised.value)
        with pytest.raises(ValueError, match="'result 1'.*seed"):
            caustica.merge([a, a])
        other = caustica.render(box(res=4), spp=2, seed=2)
        with pytest.raises(ValueError, match="'result 1'"):
            caustica.merge([a, other])
        with pytest.raises(ValueError, match="output must end in .exr: .*a.png"):
            a.write(Path(tmp) / "a.png")
        with pytest.raises(ValueError, match="exr_format must be 'half' or 'float'"):
            a.write(path, exr_format="double")
        missing = Path(tmp) / "missing.exr"
        with pytest.raises(Exception, match="missing.exr"):
            caustica.read(missing)
    with pytest.raises(ValueError, match="at least one render"):
        caustica.merge([])
    with pytest.raises(TypeError, match="merge takes results or EXR paths, not int"):
        caustica.merge([42])
    with pytest.raises(TypeError, match="compare takes results or EXR paths, not float"):
        caustica.compare(a, 1.5)
