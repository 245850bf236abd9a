#!/usr/bin/python3
"""Two of the costs the speed targets are stated in, measured in runs that
take turns, so that a shared machine's drift slows both sides alike:

- bdpt's render loop per sample against path's: the same scene, size and
  samples, one thread, the independent sampler; one ratio per pair of runs;
- an sppm pass of --photons photons: the render loop of 1 + --passes
  passes less that of one pass (which also builds what later passes
  reuse), divided by --passes.

The render loop is the EXR's caustica:seconds (loading and writing aside).
The third, the path tracer's ray rate against raw Embree's, is
`build/bench/ray_throughput_benchmark --benchmark_filter=PathTracer`'s
of_embree.

    bench/cost_ratios.py --binary build/caustica --repeat 6
"""

import argparse
import statistics
import tempfile
from pathlib import Path

from caustica_cli import Caustica


def spread(values):
    """Median, least and largest of a list of measurements."""
    return statistics.median(values), min(values), max(values)


def render_seconds(caustica, scene, res, out, integrator, spp):
    """The render loop's seconds and the samples it took."""
    metadata = caustica.render(scene, out, integrator=integrator, spp=spp, seed=1, res=res)
    return float(metadata["seconds"]), int(metadata["samples"])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default="build/caustica")
    parser.add_argument("--scene", default="scenes/cornell-box.xml")
    parser.add_argument("--res", type=int, default=64)
    parser.add_argument("--spp", type=int, default=64, help="samples per pixel of the bdpt and path runs")
    parser.add_argument("--photons", type=int, default=100000)
    parser.add_argument("--passes", type=int, default=15)
    parser.add_argument("--sppm-res", type=int, default=128)
    parser.add_argument("--repeat", type=int, default=6)
    args = parser.parse_args()
    caustica = Caustica(args.binary, 1)
    ratios, passes = [], []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "out.exr"
        sppm = f"sppm:photons={args.photons}"
        for _ in range(args.repeat):
            path_seconds, path_samples = render_seconds(caustica, args.scene, args.res, out, "path", args.spp)
            bdpt_seconds, bdpt_samples = render_seconds(caustica, args.scene, args.res, out, "bdpt", args.spp)
            ratios.append((bdpt_seconds / bdpt_samples) / (path_seconds / path_samples))
            one, _ = render_seconds(caustica, args.scene, args.sppm_res, out, sppm, 1)
            more, _ = render_seconds(caustica, args.scene, args.sppm_res, out, sppm, 1 + args.passes)
            passes.append((more - one) / args.passes)
    print(f"{args.scene}, one thread, independent sampler, {args.repeat} runs each, taking turns")
    print(f"bdpt / path per sample ({args.res}x{args.res}, {args.spp} spp): "
          "median {:.2f}, {:.2f} to {:.2f}".format(*spread(ratios)))
    print(f"sppm pass of {args.photons} photons ({args.sppm_res}x{args.sppm_res}): "
          "median {:.3f} s, {:.3f} to {:.3f} s".format(*spread(passes)))


if __name__ == "__main__":
    main()
