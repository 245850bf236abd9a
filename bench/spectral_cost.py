"""What spectral transport costs, and how error falls with time where it is needed.

1. Per integrator, CPU-seconds of one thread for the classic Cornell box (no spectral content) rendered with
   --spectral off and on, and their ratio.
2. On the prism scene (scenes/prism.xml, rendered spectrally as its dispersion asks), each integrator's relMSE
   against a long bdpt reference (light tracing leaves the glass, seen through delta lobes, black), at growing
   sample counts, with its CPU-seconds.

    /usr/bin/python3 bench/spectral_cost.py [--res 64] [--out bench-results/spectral]
"""

import argparse
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from caustica_cli import Caustica  # noqa: E402
from render_rate import cpu_seconds  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
COST_INTEGRATORS = ["path", "ptracer", "bdpt", "photon", "sppm"]
PRISM_INTEGRATORS = ["bdpt", "photon", "sppm"]


def timed(caustica, scene, out, integrator, spp, res, options=()):
    before = cpu_seconds()
    caustica.render(scene, out, integrator=integrator, spp=spp, seed=1, res=res, options=options)
    return cpu_seconds() - before


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--caustica", type=Path, default=ROOT / "build" / "caustica")
    parser.add_argument("--res", type=int, default=64)
    parser.add_argument("--spp", type=int, default=32)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    caustica = Caustica(args.caustica, threads=1)
    box = ROOT / "scenes" / "cornell-box.xml"
    prism = ROOT / "scenes" / "prism.xml"
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "render.exr"
        print(f"Cornell box, {args.res}x{args.res}, {args.spp} spp, 1 thread: CPU-seconds (best of {args.repeat})")
        print("integrator  rgb  spectral  ratio")
        for integrator in COST_INTEGRATORS:
            rgb, spectral = (min(timed(caustica, box, out, integrator, args.spp, args.res, ("--spectral", mode))
                                 for _ in range(args.repeat)) for mode in ("off", "on"))
            print(f"{integrator:10s} {rgb:6.2f} {spectral:6.2f}  {spectral / rgb:5.2f}")

        reference = Path(tmp) / "reference.exr"
        caustica.render(prism, reference, integrator="bdpt", spp=2048, seed=99, res=args.res)
        print(f"\nprism, {args.res}x{args.res}, 1 thread: relMSE against bdpt at 2048 spp")
        print("integrator  spp  cpu_s  relMSE")
        for integrator in PRISM_INTEGRATORS:
            for spp in (4, 16, 64):
                seconds = timed(caustica, prism, out, integrator, spp, args.res)
                error = caustica.compare(out, reference)["rel_mse"]
                print(f"{integrator:10s} {spp:4d} {seconds:6.2f}  {error:.5f}")


if __name__ == "__main__":
    main()
