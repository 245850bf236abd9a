#!/usr/bin/env bash
# Installs the Debian 12 packages caustica builds against. Idempotent: packages
# already present are left alone, so a second run costs only a dpkg query.
set -euo pipefail

packages=(
  build-essential cmake pkg-config clang-format
  libembree-dev libtbb-dev
  libopenimageio-dev openimageio-tools libopenexr-dev libimath-dev
  libopencolorio-dev opencolorio-tools
  # glare's FFT convolution
  libfftw3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev libpugixml-dev libtinyobjloader-dev libfmt-dev zlib1g-dev
  # .vdb grids for heterogeneous media
  libopenvdb-dev
  # mpirun -n N caustica render ...
  libopenmpi-dev openmpi-bin
  # tests/fuzz: libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer
  clang libclang-rt-14-dev
  # bench/: the convergence suite reads EXRs and plots from Python
  python3 python3-numpy python3-matplotlib python3-openimageio
  # the Python module (python/) and its tests
  pybind11-dev python3-dev python3-pytest
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
