#!/usr/bin/env bash
# The convergence and variance suite in one command: installs what it needs,
# builds caustica, then runs bench/suite.py with these arguments, e.g.
#   bench/run-suite.sh --scale quick                 # a few minutes on a laptop
#   bench/run-suite.sh --scale long                  # about an hour on two cores, for the record
#   bench/run-suite.sh --scale quick --publish docs/bench --threads 2
#   bench/run-suite.sh --integrators path,bdpt       # another integrator list
# Results go to bench-results/SCALE/ (see bench/suite.py --help).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
export CAUSTICA_BENCH_COMMAND="bench/run-suite.sh $*"
exec /usr/bin/python3 bench/suite.py "$@"
