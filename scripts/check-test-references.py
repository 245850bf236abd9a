#!/usr/bin/python3
"""Checks the stored Cornell-family references (made by `path`) against a
second estimator, `bdpt`, at a high sample count, so that a bug `path`
shares with the references it made cannot hide behind them.

For every 4x4-pixel region and channel, and for the whole image per
channel (which sees a bias of a few tenths of a percent), the mean of
`bdpt`'s chunks (independent seeds) is compared with the reference's by
Welch's statistic:
the chunks' spread gives bdpt's standard error (its splats leave it no
variance layers), the reference's variance layers give its own. The
critical value is Student's t with chunks - 1 degrees of freedom at 1 %,
Sidak-corrected over every comparison of every scene checked.

    scripts/check-test-references.py                 # every stored reference
    scripts/check-test-references.py cornell-box-glass --chunks 64 --chunk-spp 64
"""

import argparse
import math
import pathlib
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

ROOT = pathlib.Path(__file__).resolve().parent.parent
REFERENCES = ROOT / "tests" / "data" / "references"
REGION = 4


def read_channels(path, names):
    image = oiio.ImageBuf(str(path))
    if image.has_error:
        sys.exit(f"{path}: {image.geterror()}")
    spec = image.spec()
    pixels = image.get_pixels(oiio.FLOAT)
    missing = [n for n in names if n not in spec.channelnames]
    if missing:
        sys.exit(f"{path}: no channel {', '.join(missing)}")
    return np.stack([pixels[:, :, spec.channelnames.index(n)] for n in names], axis=-1).astype(np.float64)


def region_sums(image):
    """Per 4x4 region and channel, then over the whole image per channel."""
    h, w, c = image.shape
    regions = image.reshape(h // REGION, REGION, w // REGION, REGION, c).sum(axis=(1, 3))
    return np.concatenate([regions.reshape(-1, c), regions.sum(axis=(0, 1))[None, :]])


def region_rows(image):
    return (image.shape[0] // REGION) * (image.shape[1] // REGION) + 1


def describe_region(index, width):
    per_row = width // REGION
    return f"region ({index % per_row * REGION}, {index // per_row * REGION})"


def student_t_sf(t, dof):
    """P(T > t) for t >= 0, by Simpson's rule on the density from 0 to t."""
    log_norm = math.lgamma((dof + 1) / 2) - math.lgamma(dof / 2) - 0.5 * math.log(dof * math.pi)
    density = lambda x: math.exp(log_norm - (dof + 1) / 2 * math.log1p(x * x / dof))
    steps = 4000
    h = t / steps
    total = density(0) + density(t)
    total += sum((4 if i % 2 else 2) * density(i * h) for i in range(1, steps))
    return 0.5 - total * h / 3


def two_sided_t_critical(alpha, dof):
    lo, hi = 0.0, 1000.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if 2 * student_t_sf(mid, dof) > alpha else (lo, mid)
    return hi


def render_chunks(name, res, chunks, chunk_spp, workdir):
    images = []
    for k in range(chunks):
        out = pathlib.Path(workdir) / f"{name}-{k}.exr"
        subprocess.run([str(ROOT / "build" / "caustica"), "render", str(ROOT / "scenes" / f"{name}.xml"), "-o",
                        str(out), "-D", f"res={res}", "--integrator", "bdpt", "--spp", str(chunk_spp), "--seed",
                        str(1000 + k), "--exr-format", "float", "-q"], check=True)
        images.append(read_channels(out, ["R", "G", "B"]))
    return images


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("names", nargs="*", help="reference names (default: every one stored)")
    parser.add_argument("--references", type=pathlib.Path, default=REFERENCES, help="folder of the references")
    parser.add_argument("--chunks", type=int, default=64)
    parser.add_argument("--chunk-spp", type=int, default=64)
    args = parser.parse_args()
    names = args.names or sorted(p.stem for p in args.references.glob("*.exr"))
    if args.chunks < 2:
        sys.exit("--chunks must be at least 2")

    references = {n: read_channels(args.references / f"{n}.exr", ["R", "G", "B", "variance.R", "variance.G", "variance.B"])
                  for n in names}
    tests = sum(((r.shape[0] // REGION) * (r.shape[1] // REGION) + 1) * 3 for r in references.values())
    critical = two_sided_t_critical(1 - (1 - 0.01) ** (1 / tests), args.chunks - 1)
    pixels = REGION * REGION
    failed = False
    with tempfile.TemporaryDirectory() as workdir:
        for name, ref in references.items():
            chunks = render_chunks(name, ref.shape[1], args.chunks, args.chunk_spp, workdir)
            # Each region's pixel count, the last row being the whole image.
            counts = np.full((region_rows(ref), 1), float(pixels))
            counts[-1] = ref.shape[0] * ref.shape[1]
            means = np.stack([region_sums(c) / counts for c in chunks])
            bdpt_mean = means.mean(axis=0)
            bdpt_se2 = means.var(axis=0, ddof=1) / args.chunks
            ref_mean = region_sums(ref[:, :, :3]) / counts
            ref_se2 = region_sums(ref[:, :, 3:]) / counts**2
            t = (bdpt_mean - ref_mean) / np.sqrt(bdpt_se2 + ref_se2)
            worst = np.unravel_index(np.argmax(np.abs(t)), t.shape)
            where = "the whole image" if worst[0] == len(t) - 1 else describe_region(worst[0], ref.shape[1])
            verdict = "agrees" if np.abs(t).max() < critical else "DISAGREES"
            failed |= verdict != "agrees"
            ratio = ", ".join(f"{b / r:.4f}" for b, r in zip(bdpt_mean[-1], ref_mean[-1]))
            print(f"{name}: {verdict}; bdpt {args.chunks}x{args.chunk_spp} spp, worst |t| {abs(t[worst]):.2f} "
                  f"(critical {critical:.2f}) at {where} channel {'RGB'[worst[1]]}: bdpt {bdpt_mean[worst]:.5f}, "
                  f"reference {ref_mean[worst]:.5f}; image mean bdpt / reference (R, G, B): {ratio}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
