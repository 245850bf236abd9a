"""What the convergence suite runs: its scenes, its integrators and its scales.

The one place to change when an integrator lands: add its name to
INTEGRATORS. Names the caustica binary does not know are skipped with a note,
so the list may run ahead of the binary.
"""

from dataclasses import dataclass

# In plot and table order.
INTEGRATORS = ["path", "bdpt", "ptracer", "photon:photons=10000", "sppm:photons=10000", "vcm", "direct"]

# Every integrator runs with each sampler; a run is named INTEGRATOR@SAMPLER
# for every sampler but the first (independent, passed to the scene even
# where its default differs), which keeps the integrator's plain name.
SAMPLERS = ["independent", "ldsampler", "stratified", "multijitter", "halton"]


def runs(integrators, samplers):
    """The run names of integrators x samplers, each integrator's samplers together."""
    return [i if s == SAMPLERS[0] else f"{i}@{s}" for i in integrators for s in samplers]


# The Cornell-box family: diffuse, glass (caustics), mirror, glossy metal, and
# filled with fog (integrators that do not render media are skipped there).
SCENES = ["cornell-box", "cornell-box-glass", "cornell-box-mirror", "cornell-box-glossy", "cornell-box-fog"]

# The reference is the converged image of the full light transport; an
# integrator that estimates something else (direct: one bounce only) shows
# its bias as an error that stops falling.
REFERENCE_INTEGRATOR = "path"

# Seeds: the references' chunks and the runs never share one, or the runs
# would share the reference's samples and errors.
REFERENCE_SEED_BASE = 1_000_000
RUN_SEED_BASE = 1
# Twins of the longest runs, for the variance of integrators that splat.
TWIN_SEED_BASE = 500_000


@dataclass(frozen=True)
class Scale:
    res: int  # image width and height
    reference_spp: int
    chunk_spp: int  # the reference is rendered in independent chunks of this many samples
    max_spp: int  # runs at 1, 2, 4, ..., max_spp samples per pixel
    target_rel_mse: float  # the error the summary reports the time to reach
    scenes: tuple = tuple(SCENES)


# The reference holds 16 times the samples of the longest run, so its own
# variance is a small part of the measured error, and is subtracted besides.
SCALES = {
    # For ctest: seconds in all.
    "tiny": Scale(res=16, reference_spp=256, chunk_spp=128, max_spp=16, target_rel_mse=0.1, scenes=("cornell-box",)),
    # For a laptop: a few minutes on two cores.
    "quick": Scale(res=48, reference_spp=8192, chunk_spp=2048, max_spp=512, target_rel_mse=0.01),
    # For the record: about an hour on two cores.
    "long": Scale(res=128, reference_spp=65536, chunk_spp=4096, max_spp=4096, target_rel_mse=0.001),
}


def spp_ladder(max_spp):
    """1, 2, 4, ... up to max_spp: geometrically growing runs."""
    ladder = [1]
    while ladder[-1] * 2 <= max_spp:
        ladder.append(ladder[-1] * 2)
    return ladder
