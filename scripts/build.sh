#!/usr/bin/env bash
# Configures and builds cpkit into ${CPKIT_BUILD_DIR:-build} (Release). Installs missing Debian
# packages first (scripts/setup-deps.sh). Extra arguments go to the CMake configure step.
# CPKIT_TARGETS (space-separated) builds only those targets, e.g. CPKIT_TARGETS=cpkit_cli for the
# `cpkit` program alone; unset, everything (libraries, program, tests, benchmarks) is built.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup-deps.sh"
build="${CPKIT_BUILD_DIR:-$root/build}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >/dev/null
targets=()
for t in ${CPKIT_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
