"""Per-pixel variance images and their means, per integrator.

The variance comes from the film's per-pixel moments (the EXR's variance.R,
.G, .B layers: the variance of each pixel's estimate), averaged over R, G, B.
Scaled by the samples per pixel it is the variance of one sample, which
compares integrators run at different sample counts; scaled by the render
time it is variance x time, which also charges for what a sample costs
(lower is better). The relative variance, variance / (value^2 + 0.01), is
the render's own estimate of its relative MSE, were it unbiased.
"""

import csv

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import OpenImageIO as oiio  # noqa: E402

FIELDS = ["scene", "integrator", "spp", "seconds", "mean_variance", "mean_rel_variance", "variance_per_sample",
          "variance_x_seconds"]

# As in relative MSE: variance / (value^2 + epsilon), so bright pixels do not dominate.
REL_EPSILON = 0.01


def _read(exr):
    image = oiio.ImageInput.open(str(exr))
    if image is None:
        raise RuntimeError(f"cannot read {exr}: {oiio.geterror()}")
    names = list(image.spec().channelnames)
    pixels = image.read_image("float")
    image.close()
    return names, pixels


def _channels(names, pixels, wanted, exr):
    try:
        return pixels[:, :, [names.index(c) for c in wanted]]
    except ValueError:
        raise RuntimeError(f"{exr} has no {', '.join(wanted)} layers") from None


def has_variance_layers(exr):
    """Integrators that splat (bdpt, ptracer) write none: a pixel's splats come from other pixels' samples."""
    names, _ = _read(exr)
    return "variance.R" in names


def variance_images(exr, twin=None):
    """Per-pixel variance of the estimate and its relative form, averaged over R, G, B (2-D arrays).

    From the EXR's variance layers, or, given `twin` (an independent render with the same settings), from
    the two estimates: (a - b)^2 / 2 is an unbiased estimate of each pixel's variance, noisy per pixel
    but exact on average.
    """
    names, pixels = _read(exr)
    values = _channels(names, pixels, ["R", "G", "B"], exr)
    if twin is None:
        variances = _channels(names, pixels, [f"variance.{c}" for c in "RGB"], exr)
    else:
        twin_names, twin_pixels = _read(twin)
        variances = (values - _channels(twin_names, twin_pixels, ["R", "G", "B"], twin)) ** 2 / 2
    return variances.mean(axis=2), (variances / (values**2 + REL_EPSILON)).mean(axis=2)


def measure(scene, integrator, run, exr, twin=None):
    """A variance.csv row for one render (`run`: its convergence row) and its variance image."""
    image, relative = variance_images(exr, twin)
    mean = float(image.mean())
    return {"scene": scene, "integrator": integrator, "spp": int(run["spp"]), "seconds": run["seconds"],
            "mean_variance": mean, "mean_rel_variance": float(relative.mean()),
            "variance_per_sample": mean * run["spp"], "variance_x_seconds": mean * run["seconds"]}, image


def plot(scenes, path):
    """The variance images, a row per scene and a column per integrator, each row
    on one log scale. `scenes`: [(scene, [(row, image), ...]), ...]."""
    columns = max(len(measured) for _, measured in scenes)
    fig, axes = plt.subplots(len(scenes), columns, figsize=(2.6 * columns + 1, 2.6 * len(scenes)),
                             layout="constrained", squeeze=False)
    for axes_row, (scene, measured) in zip(axes, scenes):
        values = np.concatenate([image[image > 0] for _, image in measured])
        lo, hi = (np.percentile(values, 1), values.max()) if values.size else (1e-6, 1.0)
        norm = matplotlib.colors.LogNorm(vmin=lo, vmax=max(hi, lo * 10))
        for ax in axes_row:
            ax.axis("off")
        for ax, (row, image) in zip(axes_row, measured):
            shown = ax.imshow(np.maximum(image, lo), norm=norm, cmap="magma", interpolation="nearest")
            ax.set_title(f"{scene}\n{row['integrator']}, {row['spp']} spp, mean {row['mean_variance']:.3g}",
                         fontsize=8)
        fig.colorbar(shown, ax=list(axes_row), shrink=0.9, label="pixel variance")
    fig.savefig(path, dpi=110)
    plt.close(fig)


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)


def markdown(rows):
    lines = ["| scene | integrator | spp | mean pixel variance | relative | per sample | x seconds |",
             "| --- | --- | ---: | ---: | ---: | ---: | ---: |"]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['integrator']} | {r['spp']} | {r['mean_variance']:.3g} "
                     f"| {r['mean_rel_variance']:.3g} | {r['variance_per_sample']:.3g} "
                     f"| {r['variance_x_seconds']:.3g} |")
    return "\n".join(lines) + "\n"
