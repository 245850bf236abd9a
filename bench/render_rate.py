"""Samples per second of one render, as the scaling benchmarks measure it."""

import resource


def cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def add_render_arguments(parser):
    """The render every scaling benchmark repeats: binary, scene, integrator, size, samples, repetitions."""
    parser.add_argument("--binary", default="build/caustica")
    parser.add_argument("--scene", default="scenes/cornell-box.xml")
    parser.add_argument("--integrator", default="path")
    parser.add_argument("--res", type=int, default=256)
    parser.add_argument("--spp", type=int, default=32)
    parser.add_argument("--repeat", type=int, default=3)


def render_rate(caustica, args, out):
    """Samples per second of the render loop (the EXR's caustica:seconds, loading and writing aside) and per
    CPU-second of every process the render ran (loading included)."""
    before = cpu_seconds()
    metadata = caustica.render(args.scene, out, integrator=args.integrator, spp=args.spp, seed=1, res=args.res)
    samples = int(metadata["samples"])
    return samples / float(metadata["seconds"]), samples / (cpu_seconds() - before)
