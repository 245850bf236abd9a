"""The suite's summary table: per scene and integrator, how fast the error falls,
what a unit of accuracy costs, and how long a stated error takes.

The error is rel_mse_corrected (relative MSE less the reference's own): it
compares across scenes of different brightness.
"""

import math
from collections import defaultdict

import fit

METRIC = "rel_mse_corrected"


def by_scene_and_integrator(rows):
    """{scene: {integrator: [rows in order of spp]}}, in the order rows first name them."""
    groups = defaultdict(lambda: defaultdict(list))
    for row in rows:
        groups[row["scene"]][row["integrator"]].append(row)
    for integrators in groups.values():
        for runs in integrators.values():
            runs.sort(key=lambda r: r["spp"])
    return groups


def summarize(rows, target):
    """One dict per (scene, integrator) with the table's figures."""
    table = []
    for scene, integrators in by_scene_and_integrator(rows).items():
        for integrator, runs in integrators.items():
            times = [r["seconds"] for r in runs]
            errors = [r[METRIC] for r in runs]
            slope = fit.fit_slope(times, errors)
            last = runs[-1]
            table.append({
                "scene": scene,
                "integrator": integrator,
                "max_spp": int(last["spp"]),
                "seconds": last["seconds"],
                "error": last[METRIC],
                "slope": slope[0] if slope else math.nan,
                "efficiency": fit.efficiency(last[METRIC], last["seconds"]),
                "time_to_target": fit.time_to_reach(times, errors, target),
                "mrays_per_second": last["rays"] / last["seconds"] * 1e-6 if last["seconds"] > 0 else math.nan,
            })
    return table


def _time_text(reached):
    if reached is None:
        return "not reached"
    seconds, extrapolated = reached
    return f"~{seconds:.3g} (extrapolated)" if extrapolated else f"{seconds:.3g}"


def markdown(table, target):
    """The table as Markdown, with the notes a reader needs."""
    lines = [
        f"| scene | integrator | spp | time (s) | relMSE | slope | efficiency 1/(relMSE x s) "
        f"| s to relMSE {target:g} | Mrays/s |",
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |",
    ]
    for t in table:
        lines.append(f"| {t['scene']} | {t['integrator']} | {t['max_spp']} | {t['seconds']:.3g} | {t['error']:.3g} "
                     f"| {t['slope']:.2f} | {t['efficiency']:.3g} | {_time_text(t['time_to_target'])} "
                     f"| {t['mrays_per_second']:.3g} |")
    lines += [
        "",
        "relMSE: the relative MSE (x - ref)^2 / (ref^2 + 0.01) less the reference's own variance, at the longest run.",
        "slope: of log relMSE against log time over all runs (-1 for an unbiased estimator in its asymptotic regime).",
        "efficiency: 1 / (relMSE x seconds) at the longest run. Time to the target: interpolated between runs, or",
        f"extrapolated along the last {fit.TAIL_RUNS} runs when they fall at least as steeply as "
        f"{fit.MIN_EXTRAPOLATION_SLOPE}; 'not reached' when the error stalls (bias).",
    ]
    return "\n".join(lines) + "\n"
