#!/usr/bin/env bash
# Prints the SHA-256 of the beauty pixels (R, G, B as float32) of small
# renders of the Cornell box and the glass box with path, direct, bdpt and
# ptracer (independent sampler), on 1 and 2 threads. A refactor of the
# transport code must reproduce them bit for bit unless a changed random
# stream explains it.
# Usage: scripts/image-hashes.sh [CAUSTICA_BINARY]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
binary="${1:-$root/build/caustica}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for scene in cornell-box cornell-box-glass; do
  for integrator in path direct bdpt ptracer; do
    for threads in 1 2; do
      out="$work/$scene-$integrator-$threads.exr"
      "$binary" render "$root/scenes/$scene.xml" -D res=48 --spp 8 --seed 3 --integrator "$integrator" \
        --threads "$threads" -D sampler=independent --exr-format float -q -o "$out"
      hash=$(/usr/bin/python3 - "$out" <<'PY'
import hashlib, sys
import OpenImageIO as oiio
import numpy as np
image = oiio.ImageInput.open(sys.argv[1])
names = list(image.spec().channelnames)
pixels = image.read_image(oiio.FLOAT)
image.close()
rgb = np.ascontiguousarray(pixels[:, :, [names.index(c) for c in ("R", "G", "B")]], dtype=np.float32)
print(hashlib.sha256(rgb.tobytes()).hexdigest())
PY
)
      echo "$scene $integrator threads=$threads $hash"
    done
  done
done
