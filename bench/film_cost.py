#!/usr/bin/env python3
"""What a pixel costs in memory: the peak RSS of one-sample renders of a
scene at two resolutions (the film, its first-hit layers and the writing
of the EXR and PNG), the difference divided by the difference in pixels.
The scene's own memory (meshes, Embree, textures) is the same at both
sizes and drops out.

    bench/film_cost.py --binary build/caustica --scene scenes/cornell-box.xml --small 512 --large 2048
"""

import argparse
import re
import subprocess
import tempfile
from pathlib import Path


def peak_kib(binary, scene, res, out, extra):
    result = subprocess.run(["/usr/bin/time", "-f", "peak %M", binary, "render", scene, "-D", f"res={res}", "--spp",
                             "1", "-q", "-o", str(out)] + extra, capture_output=True, text=True, check=True)
    return int(re.search(r"peak (\d+)", result.stderr).group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default="build/caustica")
    parser.add_argument("--scene", default="scenes/cornell-box.xml")
    parser.add_argument("--small", type=int, default=512)
    parser.add_argument("--large", type=int, default=2048)
    parser.add_argument("--raw-sums", action="store_true", help="write the raw sums too (float EXR)")
    args = parser.parse_args()
    extra = ["--raw-sums"] if args.raw_sums else []
    with tempfile.TemporaryDirectory() as tmp:
        small = peak_kib(args.binary, args.scene, args.small, Path(tmp) / "small.exr", extra)
        large = peak_kib(args.binary, args.scene, args.large, Path(tmp) / "large.exr", extra)
    pixels = args.large ** 2 - args.small ** 2
    print(f"{args.scene}, {args.large}^2 against {args.small}^2 pixels at 1 spp{' with raw sums' if extra else ''}: "
          f"{(large - small) * 1024 / pixels:.1f} bytes per pixel at the peak")


if __name__ == "__main__":
    main()
