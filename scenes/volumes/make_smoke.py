"""Writes smoke.vol, the density grid of the smoky Cornell box: a plume
rising from a source near the floor, widening and thinning as it rises,
broken up by a few octaves of smooth value noise. Deterministic (a fixed
seed), so the committed file is what this script writes.

    /usr/bin/python3 scenes/volumes/make_smoke.py
"""

import os
import struct

import numpy as np

N = 32


def value_noise(rng, n, cells):
    """Smooth noise in [0, 1]: random values on a coarse lattice, trilinearly interpolated."""
    lattice = rng.random((cells + 1,) * 3)
    x = np.linspace(0, cells, n, endpoint=False) + cells / (2 * n)
    i = np.minimum(x.astype(int), cells - 1)
    f = x - i
    f = f * f * (3 - 2 * f)
    out = np.zeros((n, n, n))
    for dz in (0, 1):
        for dy in (0, 1):
            for dx in (0, 1):
                w = ((f if dz else 1 - f)[:, None, None] * (f if dy else 1 - f)[None, :, None] *
                     (f if dx else 1 - f)[None, None, :])
                out += w * lattice[np.ix_(i + dz, i + dy, i + dx)]
    return out


def main():
    rng = np.random.default_rng(7)
    c = (np.arange(N) + 0.5) / N
    z, y, x = np.meshgrid(c, c, c, indexing="ij")
    # The plume's axis sways a little with height; its radius grows.
    axis_x = 0.5 + 0.08 * np.sin(5 * y)
    axis_z = 0.5 + 0.06 * np.cos(4 * y)
    radius = 0.10 + 0.25 * y
    r2 = ((x - axis_x) ** 2 + (z - axis_z) ** 2) / radius ** 2
    plume = np.exp(-2.5 * r2) * np.clip(1.2 - y, 0, 1) * np.clip(y * 8, 0, 1)
    turbulence = sum(value_noise(rng, N, cells) / k for k, cells in ((1, 4), (2, 8), (4, 16))) / 1.75
    density = np.clip(plume * (0.35 + 1.3 * turbulence) - 0.05, 0, None).astype("<f4")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "smoke.vol")
    with open(path, "wb") as out:
        out.write(b"VOL" + bytes([3]))
        out.write(struct.pack("<iiiii", 1, N, N, N, 1))
        out.write(struct.pack("<6f", 0, 0, 0, 1, 1, 1))
        out.write(density.tobytes())  # z slowest, x fastest: as .vol files order voxels


if __name__ == "__main__":
    main()
