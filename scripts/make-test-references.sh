#!/usr/bin/env bash
# Renders the stored references the Cornell-variant regression tests compare
# against: 24x24 pixels, 16384 samples per pixel, seed 0, float EXR with the
# per-pixel variance layers. Run after a change that alters the images on
# purpose, and commit the result with it. Each new reference is then checked
# against bdpt (scripts/check-test-references.py), so that path cannot make
# a reference that only agrees with itself.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
mkdir -p tests/data/references
names=()
for scene in "$@"; do
  name=$(basename "$scene" .xml)
  build/caustica render "$scene" -o "tests/data/references/$name.exr" -D res=24 --spp 16384 --seed 0 \
    --exr-format float -q
  rm -f "tests/data/references/$name.png"
  echo "tests/data/references/$name.exr"
  names+=("$name")
done
scripts/check-test-references.py "${names[@]}"
