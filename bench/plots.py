"""Log-log plots of error against render time, one line per integrator, per scene."""

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

from summary import METRIC, by_scene_and_integrator  # noqa: E402


def _draw_scene(ax, scene, integrators, target):
    lowest = None
    for integrator, runs in integrators.items():
        points = [(r["seconds"], r[METRIC]) for r in runs if r["seconds"] > 0 and r[METRIC] > 0]
        if not points:
            continue
        ax.loglog(*zip(*points), marker="o", markersize=3, label=integrator)
        if lowest is None or points[0][0] < lowest[0]:
            lowest = points[0]
    if lowest is not None:
        # A guide of slope -1 through the earliest run: where unbiased Monte Carlo heads.
        t0, e0 = lowest
        ax.loglog([t0, t0 * 1e3], [e0, e0 * 1e-3], color="0.7", linestyle=":", linewidth=1, label="slope -1")
    ax.axhline(target, color="0.5", linestyle="--", linewidth=0.8, label=f"target {target:g}")
    ax.set_title(scene, fontsize=10)
    ax.set_xlabel("render time (s)")
    ax.set_ylabel("relative MSE")
    ax.grid(True, which="major", linewidth=0.3)
    ax.legend(fontsize=7)


def _fit_limits(ax, integrators):
    """Keeps the axes on the data; the guide line is not allowed to stretch them."""
    points = [(r["seconds"], r[METRIC]) for runs in integrators.values() for r in runs
              if r["seconds"] > 0 and r[METRIC] > 0]
    if points:
        times, errors = zip(*points)
        ax.set_xlim(min(times) / 1.5, max(times) * 1.5)
        ax.set_ylim(min(errors) / 3, max(errors) * 3)


def _save(fig, stem):
    for suffix in (".png", ".svg"):
        fig.savefig(stem.with_suffix(suffix), dpi=110)
    plt.close(fig)


def plot_convergence(rows, out_dir, target, title):
    """One figure per scene (SCENE.png/.svg) and all scenes side by side (convergence.png/.svg)."""
    out_dir.mkdir(parents=True, exist_ok=True)
    groups = by_scene_and_integrator(rows)
    for scene, integrators in groups.items():
        fig, ax = plt.subplots(figsize=(4.5, 3.5), layout="constrained")
        _draw_scene(ax, scene, integrators, target)
        _fit_limits(ax, integrators)
        _save(fig, out_dir / scene)
    columns = min(len(groups), 2)
    rows_of_plots = (len(groups) + columns - 1) // columns
    fig, axes = plt.subplots(rows_of_plots, columns, figsize=(4.5 * columns, 3.5 * rows_of_plots),
                             layout="constrained", squeeze=False)
    for ax, (scene, integrators) in zip(axes.flat, groups.items()):
        _draw_scene(ax, scene, integrators, target)
        _fit_limits(ax, integrators)
    for ax in list(axes.flat)[len(groups):]:
        ax.set_visible(False)
    fig.suptitle(title, fontsize=10)
    _save(fig, out_dir / "convergence")
