#!/usr/bin/env python3
"""What a triangle costs to load and to keep: a generated sphere mesh of
`--triangles` triangles (binary PLY without normals, so smooth ones are
computed, as for most scanned meshes) against one of `--small` triangles,
the difference divided by the difference in triangles:

  resident   memory held while rendering, once loading is over
             (the render's RSS, read once it has stopped changing);
  peak       the highest RSS of `caustica info` (reading, normals,
             Embree's build and its temporary arrays);
  load       CPU-seconds (user + system, all threads) of `caustica info`,
             the least of `--repeat` runs.

    bench/mesh_cost.py --binary build/caustica --triangles 2000000
"""

import argparse
import re
import subprocess
import tempfile
import time
from pathlib import Path

from instancing_memory import scene, write_sphere_ply


def info_cost(binary, path, repeat):
    """Peak RSS (KiB) and the least CPU-seconds of `caustica info`."""
    peak, cpu = 0, float("inf")
    for _ in range(repeat):
        result = subprocess.run(["/usr/bin/time", "-f", "cost %M %U %S", binary, "info", str(path)],
                                capture_output=True, text=True, check=True)
        kib, user, system = re.search(r"cost (\d+) ([\d.]+) ([\d.]+)", result.stderr).groups()
        peak, cpu = max(peak, int(kib)), min(cpu, float(user) + float(system))
    return peak, cpu


def rss_kib(pid):
    status = Path(f"/proc/{pid}/status").read_text()
    return int(re.search(r"VmRSS:\s+(\d+)", status).group(1))


def resident_kib(binary, path, out):
    """The RSS of a long render once it has stayed within 0.5 % for a second."""
    render = subprocess.Popen([binary, "render", str(path), "--spp", "1000000", "--threads", "1", "-q", "-o", str(out)],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        history = []
        while render.poll() is None:
            history.append(rss_kib(render.pid))
            recent = history[-10:]
            if len(recent) == 10 and max(recent) - min(recent) <= 0.005 * max(recent):
                return max(recent)
            time.sleep(0.1)
        raise RuntimeError(f"the render of {path} ended before its memory settled")
    finally:
        render.kill()
        render.wait()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default="build/caustica")
    parser.add_argument("--triangles", type=int, default=2000000)
    parser.add_argument("--small", type=int, default=2000)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        costs = {}
        for n in (args.small, args.triangles):
            count = write_sphere_ply(tmp / f"mesh{n}.ply", n)
            path = tmp / f"mesh{n}.xml"
            # A small film, so that the film's memory is a constant beside the mesh's.
            path.write_text(scene(f"<shape type='ply'><string name='filename' value='mesh{n}.ply'/></shape>").replace(
                "</sensor>", "<film type='hdrfilm'><integer name='width' value='64'/>"
                "<integer name='height' value='64'/></film></sensor>"))
            costs[count] = (*info_cost(args.binary, path, args.repeat), resident_kib(args.binary, path, tmp / "out.exr"))
        (small, (p0, c0, r0)), (large, (p1, c1, r1)) = sorted(costs.items())
        per = 1 / (large - small)
        print(f"{large} triangles against {small}, per triangle:")
        print(f"  resident while rendering: {(r1 - r0) * 1024 * per:6.1f} bytes")
        print(f"  peak while loading:       {(p1 - p0) * 1024 * per:6.1f} bytes")
        print(f"  load (CPU, all threads):  {(c1 - c0) * 1e6 * per:6.3f} us")


if __name__ == "__main__":
    main()
