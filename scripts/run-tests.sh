#!/usr/bin/env bash
# Set-up + build + the whole test suite through ctest (README's second command).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup-deps.sh" --tests  # the test suite's peers too (python3-siconos)
"$root/scripts/build.sh"
build="${CPKIT_BUILD_DIR:-$root/build}"
cd "$build"
ctest --output-on-failure -j "$(nproc)" --timeout 600
