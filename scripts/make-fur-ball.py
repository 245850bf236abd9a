#!/usr/bin/python3
"""Writes scenes/meshes/fur-ball.txt: the hairs of scenes/fur-ball.xml.

HAIRS cubic B-spline hairs (five points each, and one mirrored past each end) rooted on a unit sphere at
points of a Fibonacci spiral, each leaving along the normal, bent toward -y as if
by gravity and given a small twist, their radius tapering from 8 mm to 1 mm. The
numbers are a pure function of the hair's index, so the file is the same on every
run: python3 scripts/make-fur-ball.py > scenes/meshes/fur-ball.txt
"""

import math

HAIRS = 1200
LENGTH = 0.45

lines = []
golden = math.pi * (3 - math.sqrt(5))
for i in range(HAIRS):
    y = 1 - 2 * (i + 0.5) / HAIRS
    ring = math.sqrt(1 - y * y)
    phi = golden * i
    n = (ring * math.cos(phi), y, ring * math.sin(phi))
    twist = 0.15 * math.sin(7.3 * i)
    hair = []
    for k in range(5):
        s = k / 4
        droop = 0.35 * s * s
        p = [n[j] * (1 + LENGTH * s) for j in range(3)]
        p[1] -= droop * LENGTH
        p[0] += twist * s * s * n[2]
        p[2] -= twist * s * s * n[0]
        r = 0.008 * (1 - s) + 0.001 * s
        hair.append(p + [r])
    # Phantom points mirrored past each end make the B-spline start at the
    # root and end at the tip.
    hair = [[2 * a - b for a, b in zip(hair[0], hair[1])]] + hair + [[2 * a - b for a, b in zip(hair[-1], hair[-2])]]
    hair[0][3] = hair[1][3]
    hair[-1][3] = hair[-2][3]
    lines += [f"{p[0]:.5f} {p[1]:.5f} {p[2]:.5f} {p[3]:.5f}" for p in hair]
    lines.append("")
print("\n".join(lines))
