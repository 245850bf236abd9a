#!/usr/bin/python3
"""Where a real scene's time goes: seconds per sample and perf's share of each part of the work.

For each scene: `caustica info` timed (the load: parsing, meshes, Embree's build, the analysis), then one render
on one thread under `perf record` (software clock, 999 Hz), its render-loop seconds per sample from the EXR's
metadata, and perf's samples of the whole process summed by what the functions do (the table below), so
that loading and writing the files count as a user waits for them. Written to OUT:

    scene_costs.md   one row per scene; the command that made it

    bench/scene_costs.py --out /tmp/scene-costs [--spp 16] SCENE[:-D name=value,...] ...

Without scenes it profiles the repository's hard cases (many lights, hair, textures, the glass box) and the
real scenes in ../shared/external-scenes where that folder exists.
"""

import argparse
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

from caustica_cli import read_metadata

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_SCENES = ["scenes/many-lights.xml:res=128", "scenes/fur-ball.xml:res=128",
                  "scenes/cornell-box-textured.xml:res=128", "scenes/cornell-box-glass.xml:res=128"]
EXTERNAL = ROOT.parent / "shared" / "external-scenes"

# What a function does, by its name (first match wins); the rest is "other".
CATEGORIES = [
    ("start-up (dynamic linking)", r"^ld-linux"),
    ("kernel (page faults, allocation)", r"^\[k\]"),
    ("malloc and memset", r"^libc\.so"),
    ("Embree traversal", r"embree|rtc|avx2::|sse42::|BVH"),
    ("hit to interaction", r"::interaction|::intersect\b|EmbreeScene|first_shown|spawn|offset_ray"),
    ("light choice", r"LightTree|light_importance|LightSelection|DiscreteDistribution"),
    ("light sampling", r"sample_Li|pdf_Li|sample_seen_from|pdf_seen_from|direct_light|Emitter"),
    ("BSDFs", r"Bsdf|bsdf|beckmann|ggx|Microfacet|fresnel|Fresnel|Conductor|Dielectric|Plastic|Diffuse|erf"),
    ("textures", r"Texture|texture|Bitmap|bitmap|Mipmap|mipmap|Checkerboard"),
    ("sampler", r"Sampler|sampler|sobol|Sobol|owen|Owen|pcg|Pcg|stratif"),
    ("film and filter", r"Film|Filter|filter|film"),
    ("file reading and writing", r"libz|OpenEXR|Imf|OIIO|png|Ply|ply|Obj|obj_|read_|write_|tinyexr|Imath"),
    ("maths library", r"libm\.|__exp|__log|__sin|__cos|atan|acos|sqrt|pow"),
]


def categorise(report):
    """perf report's lines (--sort dso,sym --stdio) summed by CATEGORIES, in percent."""
    shares = {name: 0.0 for name, _ in CATEGORIES}
    shares["other"] = 0.0
    for line in report.splitlines():
        m = re.match(r"\s*([\d.]+)%\s+(\S+)\s+(.*)$", line)
        if not m:
            continue
        share, dso, symbol = float(m.group(1)), m.group(2), m.group(3)
        text = symbol if symbol.startswith("[k]") else f"{dso} {symbol}"
        for name, pattern in CATEGORIES:
            if re.search(pattern, text):
                shares[name] += share
                break
        else:
            shares["other"] += share
    return shares


def parse_scene(spec):
    path, _, defines = spec.partition(":")
    pairs = [d for d in defines.split(",") if d]
    return Path(path), pairs


def profile(binary, scene, defines, spp, out):
    flags = [arg for d in defines for arg in ("-D", d)]
    started = time.perf_counter()
    subprocess.run([binary, "info", str(scene), *flags], check=True, capture_output=True)
    load = time.perf_counter() - started
    exr = out / (scene.stem + ".exr")
    data = out / (scene.stem + ".perf")
    subprocess.run(["perf", "record", "-e", "cpu-clock", "-F", "999", "-o", str(data), "--", binary, "render",
                    str(scene), *flags, "--spp", str(spp), "--threads", "1", "-o", str(exr), "-q"],
                   check=True, capture_output=True)
    report = subprocess.run(["perf", "report", "-i", str(data), "--no-children", "--sort", "dso,sym", "--stdio"],
                            check=True, capture_output=True, text=True).stdout
    shares = categorise(report)
    metadata = read_metadata(exr)
    per_sample = float(metadata["seconds"]) / max(1, int(metadata["samples"]))
    return load, per_sample, shares, metadata.get("integrator", "").split(" ")[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenes", nargs="*")
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--caustica", default=str(ROOT / "build" / "caustica"))
    parser.add_argument("--spp", type=int, default=16)
    args = parser.parse_args()
    if not shutil.which("perf"):
        sys.exit("scene_costs.py: perf not found; install it with: apt install linux-perf")
    scenes = args.scenes or DEFAULT_SCENES + sorted(str(p) for p in EXTERNAL.glob("*/scene.xml"))
    args.out.mkdir(parents=True, exist_ok=True)
    names = [name for name, _ in CATEGORIES] + ["other"]
    lines = ["# Where real scenes' time goes", "",
             f"One thread, {args.spp} spp; load is `caustica info`'s wall time, us/sample the render loop's "
             "seconds per camera sample, and the rest perf's share of the whole render process (percent).", "",
             "| scene | integrator | load s | us/sample | " + " | ".join(names) + " |",
             "| --- | --- | ---: | ---: | " + " | ".join("---:" for _ in names) + " |"]
    for spec in scenes:
        scene, defines = parse_scene(spec)
        if not scene.is_absolute():
            scene = ROOT / scene
        load, per_sample, shares, integrator = profile(args.caustica, scene, defines, args.spp, args.out)
        label = scene.parent.name if scene.name == "scene.xml" else scene.stem
        lines.append(f"| {label} | {integrator} | {load:.2f} | {per_sample * 1e6:.2f} | " +
                     " | ".join(f"{shares[n]:.1f}" for n in names) + " |")
        print(lines[-1], flush=True)
    lines += ["", f"Command: `{' '.join([Path(sys.argv[0]).name] + sys.argv[1:])}`", ""]
    (args.out / "scene_costs.md").write_text("\n".join(lines))
    print((args.out / "scene_costs.md").read_text())


if __name__ == "__main__":
    main()
