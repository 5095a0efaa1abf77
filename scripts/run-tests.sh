#!/usr/bin/env bash
# Set-up + build + the whole test suite through ctest (README's second command).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup-deps.sh" --tests  # the test suite's peers too (python3-siconos)
# With MPI: the tests run `mpirun -np 2 cpkit map ...` (docs/cluster.md); the default build
# (scripts/build.sh alone, as run-main.sh uses it) stays MPI-free.
"$root/scripts/build.sh" -DCPKIT_WITH_MPI=ON
build="${CPKIT_BUILD_DIR:-$root/build}"
cd "$build"
ctest --output-on-failure -j "$(nproc)" --timeout 600
