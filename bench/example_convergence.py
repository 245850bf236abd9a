"""Error against render time for path and bdpt on the Cornell box, from
Python alone: the convergence plot of docs/integrators.md for one scene,
as a user would script it with the module (arrays in memory, no files but
the plot).

    PYTHONPATH=build/python python3 bench/example_convergence.py --out convergence.png

The reference is a long path render, merged from independent chunks; each
run is a render of its own seed at 1, 2, 4, ... samples per pixel, judged
by its relative MSE less the reference's own (what `caustica compare`
calls rel_mse_corrected), against the seconds of its render loop.
"""

import argparse

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

import caustica  # noqa: E402


def reference(scene, spp, chunks, threads):
    parts = [caustica.render(scene, integrator="path", spp=spp // chunks, seed=1000 + k, threads=threads)
             for k in range(chunks)]
    return caustica.merge(parts)


def runs(scene, integrator, max_spp, truth, threads):
    """(seconds, relative MSE) of one render per sample count."""
    points, spp = [], 1
    while spp <= max_spp:
        result = caustica.render(scene, integrator=integrator, spp=spp, seed=spp, threads=threads)
        error = caustica.compare(result, truth)["rel_mse_corrected"]
        points.append((float(result.metadata["caustica:seconds"]), error))
        spp *= 2
    return points


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default="scenes/cornell-box.xml")
    parser.add_argument("--res", type=int, default=48)
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--max-spp", type=int, default=256)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--integrators", default="path,bdpt")
    parser.add_argument("--out", default="convergence.png")
    args = parser.parse_args()

    # The independent sampler, as the references and merges assume.
    scene = caustica.load(args.scene, defines={"res": str(args.res), "sampler": "independent"})
    truth = reference(scene, args.reference_spp, 8, args.threads)
    figure, ax = plt.subplots(figsize=(5, 4))
    for integrator in args.integrators.split(","):
        points = [(t, e) for t, e in runs(scene, integrator, args.max_spp, truth, args.threads) if e > 0]
        ax.loglog(*zip(*points), marker="o", markersize=3, label=integrator)
        print(f"{integrator}: relMSE {points[-1][1]:.3g} in {points[-1][0]:.2f} s")
    ax.set_xlabel("render time (s)")
    ax.set_ylabel("relative MSE")
    ax.set_title(args.scene.rsplit("/", 1)[-1], fontsize=10)
    ax.grid(True, which="major", linewidth=0.3)
    ax.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(args.out, dpi=120)
    print(f"-> {args.out}")


if __name__ == "__main__":
    main()
