#!/usr/bin/python3
"""Writes scenes/meshes/pool/water.obj: the rippled water surface of
scenes/cornell-box-pool.xml, a height field over the Cornell box's floor
(and 1 cm past its walls, so that no gap is left at them) with the
ripples' exact normals. Metres.

    scripts/make-pool-mesh.py
"""

import math
from pathlib import Path

N = 48  # vertices along each side
X0, X1, Z0, Z1 = -0.01, 0.5628, -0.01, 0.5692
DEPTH, AMPLITUDE = 0.08, 0.004


def height(x, z):
    return DEPTH + AMPLITUDE * (math.sin(2 * math.pi * x / 0.13) * math.cos(2 * math.pi * z / 0.17) +
                                0.5 * math.sin(2 * math.pi * (x + z) / 0.07))


def normal(x, z):
    dx = AMPLITUDE * (2 * math.pi / 0.13 * math.cos(2 * math.pi * x / 0.13) * math.cos(2 * math.pi * z / 0.17) +
                      0.5 * 2 * math.pi / 0.07 * math.cos(2 * math.pi * (x + z) / 0.07))
    dz = AMPLITUDE * (-2 * math.pi / 0.17 * math.sin(2 * math.pi * x / 0.13) * math.sin(2 * math.pi * z / 0.17) +
                      0.5 * 2 * math.pi / 0.07 * math.cos(2 * math.pi * (x + z) / 0.07))
    length = math.sqrt(dx * dx + 1 + dz * dz)
    return -dx / length, 1 / length, -dz / length


def main():
    lines = ["# Rippled water over the Cornell box's floor, written by scripts/make-pool-mesh.py"]
    points = [(X0 + (X1 - X0) * i / (N - 1), Z0 + (Z1 - Z0) * j / (N - 1)) for j in range(N) for i in range(N)]
    lines += [f"v {x:.6f} {height(x, z):.6f} {z:.6f}" for x, z in points]
    lines += ["vn {:.6f} {:.6f} {:.6f}".format(*normal(x, z)) for x, z in points]
    for j in range(N - 1):
        for i in range(N - 1):
            a, b, c, d = j * N + i + 1, j * N + i + 2, (j + 1) * N + i + 2, (j + 1) * N + i + 1
            # Counter-clockwise seen from above, so the geometric normal points up.
            lines.append(f"f {a}//{a} {d}//{d} {c}//{c}")
            lines.append(f"f {a}//{a} {c}//{c} {b}//{b}")
    out = Path(__file__).resolve().parent.parent / "scenes" / "meshes" / "pool" / "water.obj"
    out.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
