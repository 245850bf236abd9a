#!/usr/bin/python3
"""Light selection at equal time: the light tree against the choice by power on a scene of many lights.

On the hall of 124 lamps (scenes/many-lights.xml): a reference by path with the choice by power (which
shares no code with the tree), then `path` at 1, 2, 4, ... samples per pixel on one thread with each
selection (--light-selection power and tree), each run's relative MSE against the reference and its
render-loop seconds. Written to OUT:

    many_lights.csv        one row per run: selection, spp, seconds, relMSE
    many_lights.md         per selection: relMSE x seconds of the longest run and its ratio to power's;
                           the command that made it
    plots/many_lights.png  relMSE against seconds

    bench/many_lights.py --out /tmp/many-lights [--res 64] [--max-spp 256] [--reference-spp 8192]
"""

import argparse
import csv
import os
import sys
from pathlib import Path

import convergence
from caustica_inprocess import runner
from reference import make_reference
from suite_config import spp_ladder

ROOT = Path(__file__).resolve().parent.parent
SCENE = "many-lights"
SELECTIONS = ["power", "tree"]
FIELDS = ["selection", "spp", "seconds", "rel_mse"]


def run_selection(caustica, scene_path, reference, selection, ladder, res, renders_dir):
    rows = []
    renders_dir.mkdir(parents=True, exist_ok=True)
    for i, spp in enumerate(ladder):
        image = renders_dir / f"path-{selection}-{spp:06d}spp.exr"
        metadata = caustica.render(scene_path, image, integrator="path", spp=spp, seed=convergence.ladder_seed(i),
                                   res=res, options=["--light-selection", selection])
        metrics = caustica.compare(image, reference)
        rows.append({"selection": selection, "spp": spp, "seconds": float(metadata["seconds"]),
                     "rel_mse": float(metrics["rel_mse"])})
    last = rows[-1]
    print(f"  {selection}: {last['spp']} spp in {last['seconds']:.2f} s, relMSE {last['rel_mse']:.3g}")
    return rows


def write_markdown(path, rows, command):
    longest = {}
    for row in rows:
        if row["selection"] not in longest or row["spp"] > longest[row["selection"]]["spp"]:
            longest[row["selection"]] = row
    base = longest["power"]["rel_mse"] * longest["power"]["seconds"]
    lines = ["# Light selection at equal time", "",
             f"`path` on {SCENE} (124 lamps), one thread: relMSE x seconds of each selection's longest run "
             "(lower is better) and its ratio to the choice by power.", "",
             "| selection | spp | seconds | relMSE | relMSE x s | / power |", "| --- | --- | --- | --- | --- | --- |"]
    for name in SELECTIONS:
        r = longest[name]
        cost = r["rel_mse"] * r["seconds"]
        lines.append(f"| {name} | {int(r['spp'])} | {r['seconds']:.3g} | {r['rel_mse']:.3g} | {cost:.3g} | "
                     f"{cost / base:.2f} |")
    lines += ["", f"Command: `{command}`", ""]
    path.write_text("\n".join(lines))


def plot(rows, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(4.6, 3.4), layout="constrained")
    for name in SELECTIONS:
        runs = [r for r in rows if r["selection"] == name and r["rel_mse"] > 0]
        ax.loglog([r["seconds"] for r in runs], [r["rel_mse"] for r in runs], marker="o", markersize=3,
                  label=f"path, {name}")
    ax.set_title(f"{SCENE}: light selection", fontsize=10)
    ax.set_xlabel("seconds (one thread)")
    ax.set_ylabel("relative MSE")
    ax.grid(True, linewidth=0.3)
    ax.legend(fontsize=7)
    out_dir.mkdir(parents=True, exist_ok=True)
    fig.savefig(out_dir / "many_lights.png", dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--caustica", default=str(ROOT / "build" / "caustica"))
    parser.add_argument("--res", type=int, default=64)
    parser.add_argument("--max-spp", type=int, default=256)
    parser.add_argument("--reference-spp", type=int, default=8192)
    args = parser.parse_args()
    out = args.out
    scene_path = ROOT / "scenes" / f"{SCENE}.xml"
    reference = out / "references" / f"{SCENE}-path-power.exr"
    make_reference(runner(args.caustica, os.cpu_count() or 1), scene_path, reference, spp=args.reference_spp,
                   chunk_spp=max(1, args.reference_spp // 4), res=args.res, integrator="path",
                   options=["--light-selection", "power"])
    caustica = runner(args.caustica, 1)
    rows = []
    for selection in SELECTIONS:
        rows += run_selection(caustica, scene_path, reference, selection, spp_ladder(args.max_spp), args.res,
                              out / "renders")
    with open(out / "many_lights.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    write_markdown(out / "many_lights.md", rows, " ".join([Path(sys.argv[0]).name] + sys.argv[1:]))
    plot(rows, out / "plots")
    print((out / "many_lights.md").read_text())


if __name__ == "__main__":
    main()
