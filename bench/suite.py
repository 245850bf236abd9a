#!/usr/bin/python3
"""The convergence and variance suite: what accuracy costs in time.

For each scene: a reference (bench/reference.py), then every integrator with
each sampler (named INTEGRATOR@SAMPLER but for the first) at 1, 2, 4, ...
samples per pixel, each run's error against the reference
(bench/convergence.py), log-log plots of error against time, per-pixel
variance images, and a summary table. Everything goes to OUT:

    references/SCENE.exr        the references (and their chunks)
    renders/SCENE/*.exr         every run
    convergence.csv             one row per run
    variance.csv                per scene and integrator, from its longest run
    plots/SCENE.png, .svg       error against time per scene; plots/convergence.png, .svg all scenes
    plots/variance.png          the variance images
    summary.md                  the tables, the machine and the command

References are kept between runs of the suite at the same scale, so a
second run renders only the convergence runs.
"""

import argparse
import os
import platform
import shutil
import sys
import time
from pathlib import Path

import convergence
import plots
import summary
import variance
from caustica_inprocess import runner
from reference import make_reference
from suite_config import INTEGRATORS, REFERENCE_INTEGRATOR, SAMPLERS, SCALES, TWIN_SEED_BASE, runs, spp_ladder

ROOT = Path(__file__).resolve().parent.parent


def machine_text(threads):
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}; {threads} render threads"


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scale", choices=sorted(SCALES), default="quick")
    parser.add_argument("--out", type=Path, help="output folder (default: bench-results/SCALE)")
    parser.add_argument("--integrators", default=",".join(INTEGRATORS),
                        help="comma-separated; unknown ones are skipped (default: %(default)s)")
    parser.add_argument("--samplers", default=",".join(SAMPLERS),
                        help="comma-separated; every integrator runs with each (default: %(default)s)")
    parser.add_argument("--scenes", help="comma-separated names under scenes/ (default: the scale's)")
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--caustica", type=Path, default=ROOT / "build" / "caustica")
    parser.add_argument("--publish", type=Path, help="also copy the PNG plots and the summary here (e.g. docs/bench)")
    return parser.parse_args()


def run_scenes(caustica, scenes, integrators, scale, out):
    """References and convergence runs of every scene: (CSV rows, skipped integrators)."""
    rows, skipped = [], {}
    ladder = spp_ladder(scale.max_spp)
    for scene in scenes:
        scene_path = ROOT / "scenes" / f"{scene}.xml"
        if not scene_path.exists():
            sys.exit(f"caustica bench: no scene {scene_path}")
        reference = out / "references" / f"{scene}.exr"
        make_reference(caustica, scene_path, reference, spp=scale.reference_spp, chunk_spp=scale.chunk_spp,
                       res=scale.res)
        rows += convergence.run_scene(caustica, scene, scene_path, reference, integrators, ladder, scale.res,
                                      out / "renders" / scene, skipped)
    return rows, skipped


def measure_variance(caustica, rows, out, res):
    """variance.csv and plots/variance.png from each integrator's longest run; returns the CSV rows.

    Runs without variance layers (integrators that splat), and runs with a stratifying sampler (named
    INTEGRATOR@SAMPLER), whose layers assume independent samples and overstate the variance, get an independent
    twin render to estimate it from.
    """
    measured = []
    for scene, by_integrator in summary.by_scene_and_integrator(rows).items():
        row_images = []
        for integrator, runs in by_integrator.items():
            last = runs[-1]
            exr = convergence.render_path(out / "renders" / scene, integrator, int(last["spp"]))
            twin = None
            if "@" in integrator or not variance.has_variance_layers(exr):
                twin = exr.with_name(exr.stem + "-twin.exr")
                caustica.render(ROOT / "scenes" / f"{scene}.xml", twin, integrator=integrator, spp=int(last["spp"]),
                                seed=TWIN_SEED_BASE + len(runs), res=res)
            row_images.append(variance.measure(scene, integrator, last, exr, twin))
        measured.append((scene, row_images))
    variance_rows = [row for _, row_images in measured for row, _ in row_images]
    variance.write_csv(out / "variance.csv", variance_rows)
    variance.plot(measured, out / "plots" / "variance.png")
    return variance_rows


def summary_text(args, scale, rows, variance_rows, skipped, seconds):
    command = os.environ.get("CAUSTICA_BENCH_COMMAND") or " ".join(["bench/suite.py", *sys.argv[1:]])
    ladder = spp_ladder(scale.max_spp)
    return "\n".join([
        f"# caustica convergence suite, {args.scale} scale",
        "",
        f"Command: `{command}`  ",
        f"Machine: {machine_text(args.threads)}  ",
        f"Scenes at {scale.res}x{scale.res} pixels; references of {scale.reference_spp} spp "
        f"({REFERENCE_INTEGRATOR}); runs at {ladder[0]} to {ladder[-1]} spp; suite wall time {seconds:.0f} s.",
        "",
        summary.markdown(summary.summarize(rows, scale.target_rel_mse), scale.target_rel_mse),
        "Per-pixel variance at the longest run (from the film's per-pixel moments):",
        "",
        variance.markdown(variance_rows),
    ] + [f"Skipped: {name} ({message})\n" for name, message in skipped.items()])


def main():
    args = parse_args()
    started = time.monotonic()
    scale = SCALES[args.scale]
    out = (args.out or ROOT / "bench-results" / args.scale).resolve()
    scenes = args.scenes.split(",") if args.scenes else list(scale.scenes)
    integrators = runs([i for i in args.integrators.split(",") if i], [s for s in args.samplers.split(",") if s])
    print(f"caustica bench, scale {args.scale}: {scenes} x {integrators} at {spp_ladder(scale.max_spp)} spp, "
          f"{scale.res}x{scale.res} pixels -> {out}")

    caustica = runner(args.caustica, args.threads)
    rows, skipped = run_scenes(caustica, scenes, integrators, scale, out)
    if not rows:
        sys.exit("caustica bench: no integrator ran")
    convergence.write_csv(out / "convergence.csv", rows)
    title = f"caustica, {args.scale} scale: {scale.res}x{scale.res} pixels, {args.threads} threads"
    plots.plot_convergence(rows, out / "plots", scale.target_rel_mse, title)
    variance_rows = measure_variance(caustica, rows, out, scale.res)
    text = summary_text(args, scale, rows, variance_rows, skipped, time.monotonic() - started)
    (out / "summary.md").write_text(text)
    print(text)

    if args.publish:
        args.publish.mkdir(parents=True, exist_ok=True)
        for name in ["convergence.png", "variance.png"]:
            shutil.copy(out / "plots" / name, args.publish / name)
        shutil.copy(out / "summary.md", args.publish / "summary.md")


if __name__ == "__main__":
    main()
