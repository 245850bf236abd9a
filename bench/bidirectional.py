#!/usr/bin/python3
"""Caustics and narrow openings at equal time: vcm and mlt beside path, bdpt and sppm.

Scenes: the glass box (a caustic, and a caustic seen through the sphere),
the pool box (the floor lit and seen through rippled water, L S D S E),
and the door scene with the door nearly shut (2 degrees: the far room's
light reaches the camera's room through a gap of a few centimetres). Every
render and the references stop at MAX_DEPTH segments, since mlt needs a
finite depth. For each scene: a reference by bdpt, then every integrator at
1, 2, 4, ... samples per pixel (passes, for the iterative ones) on one
thread, each run's relative MSE against the reference and its seconds
(CPU-seconds of one thread). Written to OUT:

    bidirectional.csv    one row per run (the convergence suite's columns)
    bidirectional.md     per scene and integrator: relMSE x seconds of the longest run, and its ratio to the
                         better of bdpt's and sppm's; the command that made it
    plots/convergence.png  relMSE against seconds, per scene

    bench/bidirectional.py --out /tmp/bidir [--res 64] [--max-spp 256] [--reference-spp 8192] [--bootstrap 100000]
"""

import argparse
import os
import sys
from pathlib import Path

import convergence
from caustica_inprocess import runner
from plots import plot_convergence
from reference import make_reference
from suite_config import spp_ladder

ROOT = Path(__file__).resolve().parent.parent
MAX_DEPTH = 8
SCENES = ["cornell-box-glass", "cornell-box-pool", "door-nearly-shut"]
INTEGRATORS = ["path", "bdpt", "sppm", "vcm", "vcm:merge_at=after_specular", "mlt"]
BASELINES = ("bdpt", "sppm")


def with_depth(integrator, bootstrap=100000):
    extra = f",bootstrap={bootstrap}" if integrator == "mlt" else ""
    return f"{integrator}{',' if ':' in integrator else ':'}max_depth={MAX_DEPTH}{extra}"


def label(integrator):
    """The integrator and the options it was chosen with, without the ones every run shares."""
    name, _, options = integrator.partition(":")
    chosen = [o for o in options.split(",") if o and not o.startswith(("max_depth=", "bootstrap="))]
    return name + (":" + ",".join(chosen) if chosen else "")


def scene_file(name, out):
    """The scene's file; the nearly shut door is the door scene with its angle's default changed."""
    if name != "door-nearly-shut":
        return ROOT / "scenes" / f"{name}.xml"
    text = (ROOT / "scenes" / "door-ajar.xml").read_text()
    default = '<default name="door_angle" value="12"/>'
    if default not in text:
        raise SystemExit(f"scenes/door-ajar.xml no longer declares {default}")
    path = out / "scenes" / "door-nearly-shut.xml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text.replace(default, '<default name="door_angle" value="2"/>'))
    return path


def efficiency_table(rows):
    """Per scene: (integrator, spp, seconds, relMSE, relMSE x seconds, ratio to the better baseline), longest runs."""
    longest = {}
    for row in rows:
        name = label(row["integrator"])
        last = longest.setdefault(row["scene"], {}).get(name)
        if last is None or row["spp"] > last["spp"]:
            longest[row["scene"]][name] = row
    table = {}
    for scene, runs in longest.items():
        costs = {name: r["rel_mse"] * r["seconds"] for name, r in runs.items()}
        best = min((costs[b] for b in BASELINES if b in costs), default=None)
        table[scene] = [(name, r["spp"], r["seconds"], r["rel_mse"], costs[name],
                         costs[name] / best if best else float("nan")) for name, r in runs.items()]
    return table


def write_markdown(path, table, command):
    lines = ["# Caustics and narrow openings at equal time", "",
             f"relMSE x seconds of each integrator's longest run (lower is better; one thread; paths of at most "
             f"{MAX_DEPTH} segments), and its ratio to the better of bdpt's and sppm's.", "",
             "| scene | integrator | spp | seconds | relMSE | relMSE x s | / best of bdpt, sppm |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for scene, runs in table.items():
        for name, spp, seconds, rel, cost, ratio in runs:
            lines.append(f"| {scene} | {name} | {int(spp)} | {seconds:.3g} | {rel:.3g} | {cost:.3g} | {ratio:.2f} |")
    lines += ["", f"Command: `{command}`", ""]
    path.write_text("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--caustica", default=str(ROOT / "build" / "caustica"))
    parser.add_argument("--res", type=int, default=64)
    parser.add_argument("--max-spp", type=int, default=256)
    parser.add_argument("--reference-spp", type=int, default=8192)
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--bootstrap", type=int, default=100000, help="mlt's bootstrap states per path length")
    args = parser.parse_args()
    out = args.out
    caustica = runner(args.caustica, 1)
    reference_runner = runner(args.caustica, os.cpu_count() or 1)
    rows = []
    for scene in args.scenes.split(","):
        scene_path = scene_file(scene, out)
        reference = out / "references" / f"{scene}.exr"
        make_reference(reference_runner, scene_path, reference, spp=args.reference_spp,
                       chunk_spp=max(1, args.reference_spp // 4), res=args.res, integrator=with_depth("bdpt"))
        rows += convergence.run_scene(caustica, scene, scene_path, reference, [with_depth(i, args.bootstrap) for i in INTEGRATORS],
                                      spp_ladder(args.max_spp), args.res, out / "renders" / scene, {})
    convergence.write_csv(out / "bidirectional.csv", rows)
    rows = convergence.read_csv(out / "bidirectional.csv")
    write_markdown(out / "bidirectional.md", efficiency_table(rows), " ".join([Path(sys.argv[0]).name] + sys.argv[1:]))
    plot_convergence(rows, out / "plots", 0.01, "caustics and narrow openings, one thread")
    print((out / "bidirectional.md").read_text())


if __name__ == "__main__":
    main()
