#!/usr/bin/python3
"""What accuracy costs in time: radiosity beside path on diffuse scenes.

Radiosity's error falls as its elements shrink and then stops at what the
mesh and its visibility estimate cannot resolve; path's falls as 1/time
without a floor. For each scene: a path reference, path at 1, 2, 4, ...
samples per pixel, and radiosity at each patch size (uniform elements, and
the same with two adaptive levels), rendered at RADIOSITY_SPP samples per
pixel so that pixel edges are resolved alike; every run on one thread, its
relative MSE against the reference and its seconds (the solve included).
Written to OUT:

    radiosity.csv          one row per run (the convergence suite's columns; radiosity's patch sizes in
                           radiosity.md)
    radiosity.md           per scene: each radiosity run's seconds and relMSE, and path's relMSE at the same
                           seconds (interpolated in log-log); the command that made it
    plots/convergence.png  relMSE against seconds, per scene

    bench/radiosity.py --out /tmp/radiosity [--res 64] [--max-spp 1024] [--reference-spp 16384]
                       [--patches 0.3,0.2,0.14,0.1,0.07]
"""

import argparse
import math
import os
import sys
from pathlib import Path

import convergence
from caustica_inprocess import runner
from plots import plot_convergence
from reference import make_reference
from suite_config import spp_ladder

ROOT = Path(__file__).resolve().parent.parent
SCENES = ["cornell-box", "cornell-box-baffle"]
RADIOSITY_SPP = 256
VARIANTS = {"radiosity": "refinements=0", "radiosity adaptive": "refinements=2"}


def radiosity_runs(caustica, scene, scene_path, reference, patches, res, renders_dir):
    """Rows for every variant and patch size, and {id(row): patch size}."""
    rows, patch_of = [], {}
    renders_dir.mkdir(parents=True, exist_ok=True)
    for label, params in VARIANTS.items():
        for i, patch in enumerate(patches):
            image = renders_dir / f"{label.replace(' ', '-')}-{patch:g}.exr"
            metadata = caustica.render(scene_path, image, integrator=f"radiosity:patch_size={patch},{params}",
                                       spp=RADIOSITY_SPP, seed=convergence.ladder_seed(i), res=res)
            metrics = caustica.compare(image, reference)
            row = {"scene": scene, "integrator": label, "spp": RADIOSITY_SPP, "seconds": float(metadata["seconds"]),
                   "samples": int(metadata["samples"]), "rays": int(metadata["rays"]), "threads": caustica.threads}
            row.update({k: metrics[k] for k in convergence.FIELDS if k in metrics})
            rows.append(row)
            patch_of[id(row)] = patch
    return rows, patch_of


def path_error_at(path_rows, seconds):
    """Path's relMSE at `seconds`, interpolated between its runs in log-log; None outside them."""
    points = sorted((r["seconds"], r["rel_mse"]) for r in path_rows if r["seconds"] > 0 and r["rel_mse"] > 0)
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if t0 <= seconds <= t1:
            w = math.log(seconds / t0) / math.log(t1 / t0) if t1 > t0 else 0
            return math.exp(math.log(e0) + w * (math.log(e1) - math.log(e0)))
    return None


def write_markdown(path, scenes, command):
    lines = ["# Radiosity beside path: error against time", "",
             "Each radiosity run's seconds (the solve included, one thread) and relative MSE against the path "
             "reference, and path's relative MSE at the same seconds (interpolated between its runs; '-' outside "
             "them).", "",
             "| scene | variant | patch size | seconds | relMSE | path's relMSE then | radiosity / path |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for scene, (radiosity_rows, patch_of, path_rows) in scenes.items():
        for row in radiosity_rows:
            path_error = path_error_at(path_rows, row["seconds"])
            then = f"{path_error:.3g}" if path_error else "-"
            ratio = f"{row['rel_mse'] / path_error:.2f}" if path_error else "-"
            lines.append(f"| {scene} | {row['integrator']} | {patch_of[id(row)]:g} | {row['seconds']:.3g} | "
                         f"{row['rel_mse']:.3g} | {then} | {ratio} |")
    lines += ["", f"Command: `{command}`", ""]
    path.write_text("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--caustica", default=str(ROOT / "build" / "caustica"))
    parser.add_argument("--res", type=int, default=64)
    parser.add_argument("--max-spp", type=int, default=1024)
    parser.add_argument("--reference-spp", type=int, default=16384)
    parser.add_argument("--patches", default="0.3,0.2,0.14,0.1,0.07")
    parser.add_argument("--scenes", default=",".join(SCENES))
    args = parser.parse_args()
    out = args.out
    patches = [float(p) for p in args.patches.split(",")]
    caustica = runner(args.caustica, 1)
    reference_runner = runner(args.caustica, os.cpu_count() or 1)
    rows, scenes = [], {}
    for scene in args.scenes.split(","):
        scene_path = ROOT / "scenes" / f"{scene}.xml"
        reference = out / "references" / f"{scene}.exr"
        make_reference(reference_runner, scene_path, reference, spp=args.reference_spp,
                       chunk_spp=max(1, args.reference_spp // 4), res=args.res)
        path_rows = convergence.run_integrator(caustica, scene, scene_path, reference, "path",
                                               spp_ladder(args.max_spp), args.res, out / "renders" / scene)
        radiosity_rows, patch_of = radiosity_runs(caustica, scene, scene_path, reference, patches, args.res,
                                                  out / "renders" / scene)
        scenes[scene] = (radiosity_rows, patch_of, path_rows)
        rows += path_rows + radiosity_rows
    convergence.write_csv(out / "radiosity.csv", rows)
    write_markdown(out / "radiosity.md", scenes, " ".join([Path(sys.argv[0]).name] + sys.argv[1:]))
    plot_convergence(rows, out / "plots", 0.01, "radiosity beside path, one thread")
    print((out / "radiosity.md").read_text())


if __name__ == "__main__":
    main()
