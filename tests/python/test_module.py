"""The Python module against the command line: the same render, bit for
bit, as arrays; the layers and metadata the EXR holds; errors as Python
exceptions with the command line's messages."""

import os
import signal
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np
import OpenImageIO as oiio
import pytest

import caustica

ROOT = Path(__file__).resolve().parents[2]
BOX = ROOT / "scenes" / "cornell-box.xml"


def read_exr(path):
    image = oiio.ImageBuf(str(path))
    names = list(image.spec().channelnames)
    return names, image.get_pixels(oiio.FLOAT)


def test_render_equals_the_command_line_bit_for_bit():
    scene = caustica.load(BOX, defines={"res": "12"})
    result = caustica.render(scene, spp=3, seed=5, threads=2)
    assert result.beauty.shape == (12, 12, 3) and result.beauty.dtype == np.float32
    with tempfile.TemporaryDirectory() as tmp:
        exr = Path(tmp) / "box.exr"
        subprocess.run([os.environ["CAUSTICA_BINARY"], "render", str(BOX), "-o", str(exr), "--spp", "3",
                        "--seed", "5", "--threads", "1", "--exr-format", "float", "-D", "res=12", "--quiet"],
                       check=True)
        names, pixels = read_exr(exr)
    rgb = [names.index(c) for c in ("R", "G", "B")]
    assert np.array_equal(pixels[:, :, rgb], result.beauty)
    variance = [names.index("variance." + c) for c in ("R", "G", "B")]
    assert np.array_equal(pixels[:, :, variance], result.layers["variance"])
    assert result.beauty.mean() > 0


def test_metadata_and_integrator_choice():
    # Files the text names resolve beside `name`.
    scene = caustica.load_string(BOX.read_text(), defines={"res": "8"}, name=str(ROOT / "scenes" / "text.xml"))
    result = caustica.render(scene, integrator="bdpt:max_depth=3", spp=2, first_sample=4, seed=1)
    assert result.metadata["caustica:integrator"].startswith("bdpt max_depth=3")
    assert result.metadata["caustica:first_sample"] == "4"
    assert result.metadata["caustica:spp"] == "2"
    assert "caustica:plan" in result.metadata


def test_errors_carry_the_command_lines_messages():
    bad = "<scene version='3.0.0'>\n<shape type='sphere'><float name='radius' value='-1'/></shape>\n</scene>"
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bad.xml"
        path.write_text(bad)
        cli = subprocess.run([os.environ["CAUSTICA_BINARY"], "info", str(path)], capture_output=True, text=True)
        assert cli.returncode != 0
        with pytest.raises(caustica.SceneError) as raised:
            caustica.load(path)
        assert str(raised.value) == f"{path}:2: parameter 'radius' of shape 'sphere': must be positive"
        assert (raised.value.file, raised.value.line) == (str(path), 2)
        assert str(raised.value) in cli.stderr
        with pytest.raises(caustica.SceneError, match="bad.xml:2: parameter 'radius'"):
            caustica.load_string(bad, name="bad.xml")
    with pytest.raises(caustica.SceneError, match="cannot open scene file"):
        caustica.load(ROOT / "no-such-scene.xml")
    with pytest.raises(ValueError, match="spectral must be 'on', 'off' or 'auto'"):
        caustica.render(caustica.load(BOX, defines={"res": "4"}), spp=1, spectral="sometimes")
    with pytest.raises(TypeError):
        caustica.render("not a scene", spp=1)


@pytest.mark.parametrize("option, kwargs", [
    (["--integrator", "path:no_such=1"], {"integrator": "path:no_such=1"}),
    (["--integrator", "nosuch"], {"integrator": "nosuch"}),
    (["--threads", "5000"], {"threads": 5000}),
    (["--first-sample", "4611686018427387905"], {"first_sample": 4611686018427387905}),
])
def test_bad_render_options_raise_the_command_lines_message(option, kwargs):
    cli = subprocess.run([os.environ["CAUSTICA_BINARY"], "render", str(BOX), "-o", "/dev/null/x.exr", "--spp", "1",
                          "-D", "res=4", "--quiet", *option], capture_output=True, text=True)
    assert cli.returncode != 0
    with pytest.raises(ValueError) as raised:
        caustica.render(caustica.load(BOX, defines={"res": "4"}), spp=1, **kwargs)
    # The command line names its option with dashes and a capital V is CLI11's.
    message = str(raised.value)
    message = message.replace("threads:", "--threads:").replace("first_sample:", "--first-sample:")
    assert message in cli.stderr, (message, cli.stderr)


def test_light_selection_matches_the_command_line(tmp_path):
    hall = ROOT / "scenes" / "many-lights.xml"
    scene = caustica.load(hall, defines={"res": "8"})
    for selection in ("power", "tree"):
        exr = tmp_path / f"{selection}.exr"
        subprocess.run([os.environ["CAUSTICA_BINARY"], "render", str(hall), "-o", str(exr), "--spp", "2", "--seed", "1",
                        "--exr-format", "float", "-D", "res=8", "--quiet", "--light-selection", selection], check=True)
        result = caustica.render(scene, spp=2, seed=1, light_selection=selection)
        assert caustica.compare(result, str(exr))["mse"] == 0
    with pytest.raises(ValueError, match="light_selection must be 'tree', 'power' or 'auto', not 'nearest'"):
        caustica.render(scene, spp=1, light_selection="nearest")


def test_compare_refuses_a_display_image(tmp_path):
    scene = caustica.load(BOX, defines={"res": "4"})
    png = tmp_path / "display.png"
    png.write_bytes(b"not read")
    with pytest.raises(RuntimeError, match="is a display image"):
        caustica.compare(str(png), caustica.render(scene, spp=1))


def test_compare_reports_the_squared_error_of_the_beauty():
    scene = caustica.load(BOX, defines={"res": "8"})
    a = caustica.render(scene, spp=4, seed=1)
    b = caustica.render(scene, spp=4, seed=2)
    assert caustica.compare(a, a)["mse"] == 0
    diff = a.beauty.astype(np.float64) - b.beauty.astype(np.float64)
    errors = caustica.compare(a, b)
    assert errors["mse"] == pytest.approx(np.mean(diff ** 2), rel=1e-9)
    assert errors["mae"] == pytest.approx(np.mean(np.abs(diff)), rel=1e-9)
    rel = diff ** 2 / (b.beauty.astype(np.float64) ** 2 + 1e-2)
    assert errors["rel_mse"] == pytest.approx(np.mean(rel), rel=1e-9)
    # The reference's own estimated error: its mean pixel variance.
    variance = b.layers["variance"].astype(np.float64)
    assert errors["reference_estimated_mse"] == pytest.approx(np.mean(variance), rel=1e-6)
    assert errors["mse_corrected"] == pytest.approx(errors["mse"] - errors["reference_estimated_mse"], rel=1e-9)
    with tempfile.TemporaryDirectory() as tmp:
        exr = Path(tmp) / "b.exr"
        subprocess.run([os.environ["CAUSTICA_BINARY"], "render", str(BOX), "-o", str(exr), "--spp", "4", "--seed", "2",
                        "--exr-format", "float", "-D", "res=8", "--quiet"], check=True)
        assert caustica.compare(a, str(exr))["mse"] == errors["mse"]


def test_develop_equals_the_tonemap_commands_png():
    scene = caustica.load(BOX, defines={"res": "8"})
    result = caustica.render(scene, spp=4, seed=1)
    with tempfile.TemporaryDirectory() as tmp:
        exr = Path(tmp) / "box.exr"
        subprocess.run([os.environ["CAUSTICA_BINARY"], "render", str(BOX), "-o", str(exr), "--spp", "4", "--seed", "1",
                        "--exr-format", "float", "-D", "res=8", "--quiet"], check=True)
        for options, kwargs in (([], {}), (["--tonemap", "reinhard", "--exposure", "1"],
                                           {"tonemap": "reinhard", "exposure": 1.0})):
            # A name of its own each time: OpenImageIO caches what it read by name.
            png = Path(tmp) / f"box{len(options)}.png"
            subprocess.run([os.environ["CAUSTICA_BINARY"], "tonemap", str(exr), "-o", str(png), "--png-bits", "16"]
                           + options, check=True)
            written = oiio.ImageBuf(str(png)).get_pixels(oiio.FLOAT)[:, :, :3]
            developed = caustica.develop(result, **kwargs)
            assert developed.shape == (8, 8, 3)
            # The PNG holds 16-bit steps.
            assert np.max(np.abs(developed - written)) <= 0.5 / 65535 + 1e-7
        from_array = caustica.develop(result.beauty, tonemap="none")
        assert np.array_equal(from_array, caustica.develop(result, tonemap="none"))
    with pytest.raises(ValueError, match="unknown tone operator 'sepia'"):
        caustica.develop(result, tonemap="sepia")
    with pytest.raises(ValueError, match="H x W x 3"):
        caustica.develop(np.zeros((4, 4)))


def test_ctrl_c_stops_a_render_and_raises_keyboard_interrupt():
    script = (f"import caustica, sys\n"
              f"scene = caustica.load({str(BOX)!r}, defines={{'res': '64'}})\n"
              f"print('rendering', flush=True)\n"
              f"caustica.render(scene, spp=1000000, threads=1)\n"
              f"print('finished', flush=True)\n")
    child = subprocess.Popen(["/usr/bin/python3", "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=os.environ)
    try:
        assert child.stdout.readline().strip() == "rendering"
        time.sleep(1)
        child.send_signal(signal.SIGINT)
        # Without the stop the render would run for hours.
        out, err = child.communicate(timeout=60)
    finally:
        child.kill()
    assert "KeyboardInterrupt" in err
    assert "finished" not in out


def test_develop_leaves_the_scenes_tone_operator_as_it_was():
    xml = BOX.read_text().replace("</scene>", "<tonemap type='reinhard'/></scene>")
    scene = caustica.load_string(xml, defines={"res": "8"}, name=str(ROOT / "scenes" / "text.xml"))
    result = caustica.render(scene, spp=2, seed=1)
    before = caustica.develop(result)
    brighter = caustica.develop(result, exposure=2.0)
    assert np.mean(brighter) > np.mean(before)
    assert np.array_equal(caustica.develop(result), before)
