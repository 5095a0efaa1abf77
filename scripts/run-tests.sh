#!/usr/bin/env bash
# Set-up + build + the whole test suite through ctest (README's second command).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup-deps.sh" --tests  # the test suite's peers too (python3-siconos)
# With MPI: the tests run `mpirun -np 2 cpkit map ...` (docs/cluster.md); the default build
# (scripts/build.sh alone, as run-main.sh uses it) stays MPI-free.
t0=$SECONDS
"$root/scripts/build.sh" -DCPKIT_WITH_MPI=ON
echo "run-tests.sh: set-up and build took $((SECONDS - t0)) s"
build="${CPKIT_BUILD_DIR:-$root/build}"
cd "$build"
t0=$SECONDS
ctest --output-on-failure -j "$(nproc)" --timeout 600
echo "run-tests.sh: the suite took $((SECONDS - t0)) s"
