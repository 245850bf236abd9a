#!/usr/bin/python3
"""Path guiding at equal time: path, guided_path and bdpt on the scenes guiding is for.

For each scene (the Cornell box, the box whose light hides behind a baffle,
the room lit through a door ajar): a reference by bdpt (which shares no
code with the guiding), then every integrator at 1, 2, 4, ... samples per
pixel on one thread, each run's relative MSE against the reference and its
render-loop seconds (CPU-seconds of one thread). Written to OUT:

    guiding.csv          one row per run (the convergence suite's columns, and the run's caustica:run)
    guiding.md           per scene and integrator: relMSE x seconds of the longest run and its ratio to path's,
                         with the guiding trees' memory; the command that made it. With --repeat N each
                         longest run is rendered N times, the integrators taking turns, and its seconds are
                         the least of them: the same seed gives the same image, so only the clock differs,
                         and the least is the run this shared machine slowed least
    plots/guiding.png    relMSE against seconds per scene; guided_path's runs that end within its training
                         passes drawn hollow

    bench/guiding.py --out /tmp/guiding [--res 64] [--max-spp 256] [--reference-spp 8192] [--repeat 1]
"""

import argparse
import os
import sys
from pathlib import Path

import convergence
from caustica_cli import read_metadata
from caustica_inprocess import runner
from reference import make_reference
from suite_config import spp_ladder

ROOT = Path(__file__).resolve().parent.parent
SCENES = ["cornell-box", "cornell-box-baffle", "door-ajar"]
INTEGRATORS = ["path", "guided_path", "bdpt"]
REFERENCE_INTEGRATOR = "bdpt"
# Its default: passes 0 to 5 learn, 63 samples per pixel in all.
TRAINING_SPP = 63


def efficiency_table(rows):
    """Per scene: (integrator, spp, seconds, relMSE, relMSE x seconds, ratio to path's), longest runs."""
    table = {}
    for row in rows:
        last = table.setdefault(row["scene"], {}).get(row["integrator"])
        if last is None or row["spp"] > last["spp"]:
            table[row["scene"]][row["integrator"]] = row
    out = {}
    for scene, runs in table.items():
        path_cost = runs["path"]["rel_mse"] * runs["path"]["seconds"] if "path" in runs else None
        out[scene] = [(name, r["spp"], r["seconds"], r["rel_mse"], r["rel_mse"] * r["seconds"],
                       r["rel_mse"] * r["seconds"] / path_cost if path_cost else float("nan"))
                      for name, r in runs.items()]
    return out


def write_markdown(path, table, guiding_runs, command, repeat=1):
    timing = "one thread" if repeat == 1 else f"one thread, the least of {repeat} runs taking turns"
    lines = ["# Path guiding at equal time", "",
             f"relMSE x seconds of each integrator's longest run (lower is better; {timing}), and its ratio to "
             "path's.", "", "| scene | integrator | spp | seconds | relMSE | relMSE x s | / path |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for scene, runs in table.items():
        for name, spp, seconds, rel, cost, ratio in runs:
            lines.append(f"| {scene} | {name} | {int(spp)} | {seconds:.3g} | {rel:.3g} | {cost:.3g} | {ratio:.2f} |")
    lines += ["", "guided_path's runs (caustica:run):", ""]
    lines += [f"- {scene}, {spp} spp: {run}" for scene, spp, run in guiding_runs]
    lines += ["", f"Command: `{command}`", ""]
    path.write_text("\n".join(lines))


def plot(rows, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.2 * len(scenes), 3.4), layout="constrained", squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for integrator in INTEGRATORS:
            runs = [r for r in rows if r["scene"] == scene and r["integrator"] == integrator and r["rel_mse"] > 0]
            if not runs:
                continue
            line, = ax.loglog([r["seconds"] for r in runs], [r["rel_mse"] for r in runs], marker="o", markersize=3,
                              label=integrator)
            training = [r for r in runs if integrator == "guided_path" and r["spp"] <= TRAINING_SPP]
            if training:
                ax.loglog([r["seconds"] for r in training], [r["rel_mse"] for r in training], linestyle="none",
                          marker="o", markersize=6, markerfacecolor="white", color=line.get_color(),
                          label="guided_path, within training")
        ax.set_title(scene, fontsize=10)
        ax.set_xlabel("seconds (one thread)")
        ax.set_ylabel("relative MSE")
        ax.grid(True, linewidth=0.3)
        ax.legend(fontsize=7)
    out_dir.mkdir(parents=True, exist_ok=True)
    fig.savefig(out_dir / "guiding.png", dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--caustica", default=str(ROOT / "build" / "caustica"))
    parser.add_argument("--res", type=int, default=64)
    parser.add_argument("--max-spp", type=int, default=256)
    parser.add_argument("--reference-spp", type=int, default=8192)
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--repeat", type=int, default=1,
                        help="renders of each longest run whose least seconds the table gives")
    args = parser.parse_args()
    if args.repeat < 1:
        parser.error(f"--repeat must be at least 1, not {args.repeat}")
    out = args.out
    caustica = runner(args.caustica, 1)
    reference_runner = runner(args.caustica, os.cpu_count() or 1)
    rows, guiding_runs = [], []
    for scene in args.scenes.split(","):
        scene_path = ROOT / "scenes" / f"{scene}.xml"
        reference = out / "references" / f"{scene}.exr"
        make_reference(reference_runner, scene_path, reference, spp=args.reference_spp,
                       chunk_spp=max(1, args.reference_spp // 4), res=args.res, integrator=REFERENCE_INTEGRATOR)
        renders = out / "renders" / scene
        scene_rows = convergence.run_scene(caustica, scene, scene_path, reference, INTEGRATORS,
                                           spp_ladder(args.max_spp), args.res, renders, {})
        convergence.retime_longest(caustica, scene, scene_path, scene_rows, spp_ladder(args.max_spp), args.res,
                                   renders, args.repeat)
        rows += scene_rows
        longest = convergence.render_path(renders, "guided_path", spp_ladder(args.max_spp)[-1])
        if longest.exists():
            guiding_runs.append((scene, spp_ladder(args.max_spp)[-1], read_metadata(longest).get("run", "")))
    convergence.write_csv(out / "guiding.csv", rows)
    rows = convergence.read_csv(out / "guiding.csv")
    write_markdown(out / "guiding.md", efficiency_table(rows), guiding_runs,
                   " ".join([Path(sys.argv[0]).name] + sys.argv[1:]), args.repeat)
    plot(rows, out / "plots")
    print((out / "guiding.md").read_text())


if __name__ == "__main__":
    main()
