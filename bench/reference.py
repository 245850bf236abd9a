#!/usr/bin/python3
"""Renders a scene's reference image: many samples, in independent chunks.

Each chunk is an ordinary render with a seed of its own, kept beside the
reference (REF.chunks/), so a long reference can be stopped and resumed
(finished chunks are kept, an interrupted one is rendered again) or its
chunks rendered on several machines. `caustica merge` then combines them by
sample count and stores the reference's estimated error (its mean pixel
variance, caustica:estimated_mse and caustica:estimated_rel_mse) in its
metadata, with the scene, integrator, spp, seeds and seconds.

    bench/reference.py scenes/cornell-box.xml -o ref.exr --spp 65536 --chunk-spp 4096 --res 128
"""

import argparse
import os
import sys
from pathlib import Path

from caustica_cli import Caustica, image_size, read_metadata
from suite_config import REFERENCE_INTEGRATOR, REFERENCE_SEED_BASE


def chunk_plan(spp, chunk_spp):
    """Sample counts of the chunks: whole chunks, then the remainder."""
    return [min(chunk_spp, spp - first) for first in range(0, spp, chunk_spp)]


def is_complete(chunk, *, scene, integrator, spp, res):
    """Whether a chunk on disk is the one planned, with all its samples (Ctrl-C leaves fewer)."""
    if not chunk.exists():
        return False
    metadata = read_metadata(chunk)
    return (metadata.get("scene") == str(scene) and metadata.get("integrator", "").split(" ")[0] == integrator
            and metadata.get("spp") == str(spp) and metadata.get("interrupted") == "false"
            and image_size(chunk) == (res, res))


def make_reference(caustica, scene, output, *, spp, chunk_spp, res, integrator=REFERENCE_INTEGRATOR,
                   options=(), log=print):
    """Renders the missing chunks of `output` and merges them; returns its metadata.

    `options` go to every chunk's render; a chunk on disk is not checked for them, so a reference made with
    other options needs an output of its own."""
    output = Path(output)
    chunks_dir = output.with_suffix(".chunks")
    chunks_dir.mkdir(parents=True, exist_ok=True)
    plan = chunk_plan(spp, chunk_spp)
    chunks = [chunks_dir / f"chunk-{k:04d}.exr" for k in range(len(plan))]
    for k, (chunk, count) in enumerate(zip(chunks, plan)):
        if is_complete(chunk, scene=scene, integrator=integrator, spp=count, res=res):
            continue
        log(f"  reference {output.name}: chunk {k + 1} of {len(chunks)}, {count} spp")
        caustica.render(scene, chunk, integrator=integrator, spp=count, seed=REFERENCE_SEED_BASE + k, res=res,
                        options=options)
    metadata = caustica.merge(chunks, output)
    log(f"  reference {output.name}: {metadata['spp']} spp, estimated relMSE {metadata.get('estimated_rel_mse')}")
    return metadata


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("-o", "--output", required=True, help="reference EXR; its chunks go to OUTPUT.chunks/")
    parser.add_argument("--spp", type=int, required=True)
    parser.add_argument("--chunk-spp", type=int, default=4096)
    parser.add_argument("--res", type=int, required=True, help="image width and height (the scene's res)")
    parser.add_argument("--integrator", default=REFERENCE_INTEGRATOR)
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--caustica", default=Path(__file__).resolve().parent.parent / "build" / "caustica")
    args = parser.parse_args()
    make_reference(Caustica(args.caustica, args.threads), args.scene, args.output, spp=args.spp,
                   chunk_spp=args.chunk_spp, res=args.res, integrator=args.integrator)


if __name__ == "__main__":
    sys.exit(main())
