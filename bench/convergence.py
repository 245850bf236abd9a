"""Convergence runs: renders at growing sample counts, each judged against the reference.

Every run is an independent render (a seed of its own) of 1, 2, 4, ...
samples per pixel. Its time is the render loop's (caustica:seconds: no
scene loading, no file writing), beside its samples, rays and its error
against the reference as `caustica compare` measures it.
"""

import csv

from caustica_cli import SceneRefused, UnknownIntegrator
from suite_config import RUN_SEED_BASE

FIELDS = ["scene", "integrator", "spp", "seconds", "samples", "rays", "threads", "mse", "mse_corrected", "rel_mse",
          "rel_mse_corrected", "mae", "estimated_mse", "reference_estimated_mse", "reference_estimated_rel_mse"]

# Written above the header, so the file explains its own columns.
HEADER_NOTE = """\
# Convergence runs of caustica: one independent render per row, judged against the scene's reference.
# seconds: the render loop alone. mse, rel_mse, mae: mean over pixels and R, G, B of (x - ref)^2,
# (x - ref)^2 / (ref^2 + 0.01) and |x - ref|.
# The reference is noisy too: for an unbiased reference independent of the render,
# E[(x - ref)^2] = E[(x - truth)^2] + Var[ref], so mse_corrected = mse - reference_estimated_mse (the reference's
# mean pixel variance) and rel_mse_corrected = rel_mse - reference_estimated_rel_mse estimate the render's own
# error; they can be negative once it is as small as the reference's. mae is as measured.
# estimated_mse: the render's own mean pixel variance (its expected MSE if unbiased).
"""


def render_path(renders_dir, integrator, spp):
    """Where a run's EXR goes."""
    return renders_dir / f"{integrator}-{spp:06d}spp.exr"


def ladder_seed(i):
    """The seed of the ladder's i-th run."""
    return RUN_SEED_BASE + i


def run_integrator(caustica, scene_name, scene_path, reference, integrator, ladder, res, renders_dir, log=print):
    """The runs of one integrator on one scene, as CSV rows (dicts).

    Raises UnknownIntegrator from the first render if the binary lacks it.
    """
    rows = []
    renders_dir.mkdir(parents=True, exist_ok=True)
    for i, spp in enumerate(ladder):
        image = render_path(renders_dir, integrator, spp)
        metadata = caustica.render(scene_path, image, integrator=integrator, spp=spp, seed=ladder_seed(i), res=res)
        metrics = caustica.compare(image, reference)
        row = {"scene": scene_name, "integrator": integrator, "spp": spp, "seconds": float(metadata["seconds"]),
               "samples": int(metadata["samples"]), "rays": int(metadata["rays"]), "threads": caustica.threads}
        row.update({k: metrics[k] for k in FIELDS if k in metrics})
        rows.append(row)
    last = rows[-1]
    log(f"  {scene_name} / {integrator}: {last['spp']} spp in {last['seconds']:.2f} s, "
        f"relMSE {last['rel_mse_corrected']:.3g}")
    return rows


def run_scene(caustica, scene_name, scene_path, reference, integrators, ladder, res, renders_dir, skipped,
              log=print):
    """Every integrator's runs on one scene. Integrators the binary does not know
    are added to `skipped` (name -> message) and not tried again."""
    rows = []
    for integrator in integrators:
        if integrator in skipped:
            continue
        try:
            rows += run_integrator(caustica, scene_name, scene_path, reference, integrator, ladder, res,
                                   renders_dir, log)
        except UnknownIntegrator as e:
            skipped[integrator] = str(e)
            log(f"  skipping integrator '{integrator}': {e}")
        except SceneRefused as e:
            skipped[f"{integrator} on {scene_name}"] = str(e)
            log(f"  skipping integrator '{integrator}' on {scene_name}: {e}")
    return rows


def retime_longest(caustica, scene, scene_path, rows, ladder, res, renders, repeat):
    """Renders each integrator's longest run of `scene` repeat - 1 more times, taking turns, and keeps the
    least seconds in its row. The image is the same each time (same seed); its samples are checked."""
    longest = [r for r in rows if r["scene"] == scene and r["spp"] == ladder[-1]]
    for _ in range(repeat - 1):
        for row in longest:
            again = renders / f"{row['integrator']}-retimed.exr"
            metadata = caustica.render(scene_path, again, integrator=row["integrator"], spp=row["spp"],
                                       seed=ladder_seed(len(ladder) - 1), res=res)
            if int(metadata["samples"]) != row["samples"]:
                raise RuntimeError(f"{scene} / {row['integrator']}: a repeated run took {metadata['samples']} "
                                   f"samples, the first {row['samples']}")
            row["seconds"] = min(row["seconds"], float(metadata["seconds"]))


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        f.write(HEADER_NOTE)
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)


def read_csv(path):
    """Rows of a convergence CSV, numbers as numbers."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    for row in rows:
        for key in FIELDS[2:]:
            row[key] = float(row[key])
    return rows
