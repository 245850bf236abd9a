#!/usr/bin/env python3
"""What instancing costs in memory: the peak resident memory of
`caustica info` (load, Embree build, scene analysis) on one large mesh
alone, on the mesh in a shapegroup placed by N instances, and on K copies
of the mesh written out, so the cost of an instance can be set against the
cost of a copy.

    bench/instancing_memory.py --binary build/caustica --triangles 500000 --instances 1000 --copies 8
"""

import argparse
import math
import re
import struct
import subprocess
import tempfile
from pathlib import Path


def write_sphere_ply(path, triangles):
    """A UV sphere with about `triangles` triangles, as binary PLY."""
    rings = max(4, int(math.sqrt(triangles / 2)))
    segments = max(4, triangles // (2 * rings))
    vertices = [(math.sin(math.pi * i / rings) * math.cos(2 * math.pi * j / segments),
                 math.sin(math.pi * i / rings) * math.sin(2 * math.pi * j / segments), math.cos(math.pi * i / rings))
                for i in range(rings + 1) for j in range(segments)]
    faces = []
    for i in range(rings):
        for j in range(segments):
            a, b = i * segments + j, i * segments + (j + 1) % segments
            c, d = a + segments, b + segments
            faces += [(a, c, b), (b, c, d)]
    with open(path, "wb") as f:
        f.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\n"
                "property float x\nproperty float y\nproperty float z\n"
                f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n".encode())
        f.write(b"".join(struct.pack("<3f", *v) for v in vertices))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))
    return len(faces)


def scene(body):
    return ("<scene version='3.0.0'><sensor type='perspective'><transform name='to_world'>"
            "<lookat origin='0, -80, 40' target='0, 0, 0' up='0, 0, 1'/></transform></sensor>" + body + "</scene>")


def grid(n, i):
    side = math.ceil(math.sqrt(n))
    return f"<translate x='{3 * (i % side - side / 2)}' y='{3 * (i // side - side / 2)}'/>"


def peak_kib(binary, path):
    result = subprocess.run(["/usr/bin/time", "-f", "peak %M", binary, "info", str(path)], capture_output=True,
                            text=True, check=True)
    return int(re.search(r"peak (\d+)", result.stderr).group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default="build/caustica")
    parser.add_argument("--triangles", type=int, default=500000)
    parser.add_argument("--instances", type=int, default=1000)
    parser.add_argument("--copies", type=int, default=8)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        count = write_sphere_ply(tmp / "mesh.ply", args.triangles)
        mesh = "<shape type='ply'><string name='filename' value='mesh.ply'/>{}</shape>"
        scenes = {
            "empty": scene(""),
            "one mesh": scene(mesh.format("")),
            f"{args.instances} instances": scene(
                "<shape type='shapegroup' id='g'>" + mesh.format("") + "</shape>" +
                "".join(f"<shape type='instance'><ref id='g'/><transform name='to_world'>{grid(args.instances, i)}"
                        "</transform></shape>" for i in range(args.instances))),
            f"{args.copies} copies": scene("".join(
                mesh.format(f"<transform name='to_world'>{grid(args.copies, i)}</transform>")
                for i in range(args.copies))),
        }
        peaks = {}
        for name, xml in scenes.items():
            path = tmp / (name.replace(" ", "_") + ".xml")
            path.write_text(xml)
            peaks[name] = peak_kib(args.binary, path)
        base, one = peaks["empty"], peaks["one mesh"] - peaks["empty"]
        print(f"mesh: {count} triangles; peak resident memory of `caustica info`, less the empty scene's "
              f"{base / 1024:.0f} MiB:")
        for name, peak in peaks.items():
            if name != "empty":
                print(f"  {name:>16}: {(peak - base) / 1024:8.1f} MiB  ({(peak - base) / one:5.2f} x one mesh)")


if __name__ == "__main__":
    main()
