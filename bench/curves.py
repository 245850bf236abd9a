#!/usr/bin/python3
"""Hair as Embree's round curves against the same hair as triangles: the fur ball's cost both ways.

scenes/fur-ball.xml holds 1200 hairs as cubic B-spline curves (bsplinecurve). This writes the same hairs as
closed triangle tubes (SIDES sides around, STEPS rings along each B-spline segment, ends left open), swaps them
into a copy of the scene, and renders both with `path` on one thread, reporting the render loop's seconds, the
peak resident memory of the process and the error of each against a longer render of the curves. Written to OUT:

    curves.md     the table and the command that made it

    bench/curves.py --out /tmp/curves [--res 128] [--spp 16] [--sides 8] [--steps 8]
"""

import argparse
import math
import subprocess
import sys
from pathlib import Path

from caustica_cli import read_metadata

ROOT = Path(__file__).resolve().parent.parent
SCENE = ROOT / "scenes" / "fur-ball.xml"
HAIRS = ROOT / "scenes" / "meshes" / "fur-ball.txt"


def read_hairs(path):
    hairs, current = [], []
    for line in path.read_text().splitlines():
        if not line.strip():
            if current:
                hairs.append(current)
            current = []
            continue
        current.append([float(v) for v in line.split()])
    if current:
        hairs.append(current)
    return hairs


def bspline(points, v):
    a = 1 - v
    weights = [a * a * a / 6, (3 * v ** 3 - 6 * v * v + 4) / 6, (-3 * v ** 3 + 3 * v * v + 3 * v + 1) / 6, v ** 3 / 6]
    return [sum(w * p[i] for w, p in zip(weights, points)) for i in range(4)]


def frame(t):
    n = math.sqrt(sum(c * c for c in t))
    t = [c / n for c in t]
    helper = [1, 0, 0] if abs(t[0]) < 0.9 else [0, 1, 0]
    s = [t[1] * helper[2] - t[2] * helper[1], t[2] * helper[0] - t[0] * helper[2], t[0] * helper[1] - t[1] * helper[0]]
    n = math.sqrt(sum(c * c for c in s))
    s = [c / n for c in s]
    u = [t[1] * s[2] - t[2] * s[1], t[2] * s[0] - t[0] * s[2], t[0] * s[1] - t[1] * s[0]]
    return s, u


def tessellate(hairs, sides, steps, out):
    """Writes the hairs as an OBJ of triangle tubes; returns the triangle count."""
    vertices, faces = [], []
    for hair in hairs:
        rings = []
        for seg in range(len(hair) - 3):
            for k in range(steps + (1 if seg == len(hair) - 4 else 0)):
                v = k / steps
                c = bspline(hair[seg:seg + 4], v)
                ahead = bspline(hair[seg:seg + 4], min(v + 1e-3, 1.0))
                behind = bspline(hair[seg:seg + 4], max(v - 1e-3, 0.0))
                s, u = frame([ahead[i] - behind[i] for i in range(3)])
                ring = len(vertices)
                for j in range(sides):
                    phi = 2 * math.pi * j / sides
                    vertices.append([c[i] + c[3] * (math.cos(phi) * s[i] + math.sin(phi) * u[i]) for i in range(3)])
                rings.append(ring)
        for a, b in zip(rings, rings[1:]):
            for j in range(sides):
                j1 = (j + 1) % sides
                faces.append((a + j, a + j1, b + j1))
                faces.append((a + j, b + j1, b + j))
    with open(out, "w") as f:
        f.writelines(f"v {x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in vertices)
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    return len(faces)


def render(binary, scene, output, spp, res, seed):
    """Renders on one thread; returns (seconds of the render loop, peak resident MiB of the process)."""
    timed = subprocess.run(["/usr/bin/time", "-f", "%M", binary, "render", str(scene), "-o", str(output), "--spp", str(spp), "--seed", str(seed),
                    "-D", f"res={res}", "-D", "sampler=independent", "--threads", "1", "--exr-format", "float",
                    "-q"], check=True, capture_output=True, text=True)
    return float(read_metadata(output)["seconds"]), int(timed.stderr.split()[-1]) / 1024


def rel_mse(binary, image, reference):
    out = subprocess.run([binary, "compare", str(image), str(reference)], check=True, capture_output=True,
                         text=True).stdout
    return float(next(line.split()[1] for line in out.splitlines() if line.startswith("rel_mse ")))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--caustica", default=str(ROOT / "build" / "caustica"))
    parser.add_argument("--res", type=int, default=128)
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--sides", type=int, default=8)
    parser.add_argument("--steps", type=int, default=8)
    args = parser.parse_args()
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    hairs = read_hairs(HAIRS)
    triangles = tessellate(hairs, args.sides, args.steps, out / "fur-ball-tubes.obj")
    text = SCENE.read_text()
    start = text.index('<shape type="bsplinecurve">')
    name_at = text.index('<string name="filename" value="meshes/fur-ball.txt"/>', start)
    tubes = (text[:start] + '<shape type="obj">' + text[start + len('<shape type="bsplinecurve">'):name_at] +
             f'<string name="filename" value="{out / "fur-ball-tubes.obj"}"/>' +
             text[name_at + len('<string name="filename" value="meshes/fur-ball.txt"/>'):])
    tube_scene = out / "fur-ball-tubes.xml"
    tube_scene.write_text(tubes)
    reference = out / "reference.exr"
    render(args.caustica, SCENE, reference, args.spp * 16, args.res, 99)
    rows = []
    for name, scene in (("bsplinecurve", SCENE), (f"triangles ({triangles} in all)", tube_scene)):
        image = out / (name.split()[0] + ".exr")
        seconds, mib = render(args.caustica, scene, image, args.spp, args.res, 1)
        rows.append((name, seconds, mib, rel_mse(args.caustica, image, reference)))
    lines = ["# Hair as curves and as triangles", "",
             f"The fur ball ({len(hairs)} hairs), `path`, one thread, {args.res}x{args.res}, {args.spp} spp; the "
             f"tubes have {args.sides} sides and {args.steps} rings a segment. relMSE against {args.spp * 16} spp "
             "of the curves.", "",
             "| hairs as | seconds | peak MiB | relMSE |", "| --- | ---: | ---: | ---: |"]
    lines += [f"| {name} | {seconds:.3g} | {mib:.0f} | {err:.3g} |" for name, seconds, mib, err in rows]
    lines += ["", f"Command: `{' '.join([Path(sys.argv[0]).name] + sys.argv[1:])}`", ""]
    (out / "curves.md").write_text("\n".join(lines))
    print((out / "curves.md").read_text())


if __name__ == "__main__":
    main()
