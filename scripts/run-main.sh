#!/usr/bin/env bash
# Set-up + build + the main job (README's first command): the non-uniqueness maps of the rate
# problem in the intermediate contact state b (Fig. 5 of Stromberg, Johansson & Klarbring 1996).
# Writes PNG/SVG pictures, CSV data and JSON summaries into ${CPKIT_OUT_DIR:-<repo>/out}.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# Only the `cpkit` program (target cpkit_cli): the main job runs nothing else, and --plot needs
# only the Python scripts in scripts/. The tests and benchmarks are scripts/run-tests.sh's job.
# The C library (cpkit_c, libcpkit.so) too: `cmake --install` (printed below) installs it with
# its pkg-config and CMake files, and failed without it (issue 37).
CPKIT_TARGETS="cpkit_cli cpkit_c" "$root/scripts/build.sh"
build="${CPKIT_BUILD_DIR:-$root/build}"
out="${CPKIT_OUT_DIR:-$root/out}"
mkdir -p "$out"
echo "== Fig. 5(b): solutions per load direction, state b, mu = 3 > a11/a12 = 2"
"$build/apps/cpkit" map --preset fig5b --out "$out/fig5b" --plot
echo "== mu x load direction, state b (a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25)"
"$build/apps/cpkit" map --preset fig5b --kind param-direction --param mu --from 0.1 --to 4 \
  --n 400 --theta-n 720 --out "$out/mu_direction" --plot
# The three-solution wedge is about 3 % of the full circle above: the same map over its
# directions (theta from 0.25 to 0.5 rad: the L+=0 curve up to the N=0 direction 0.4636).
echo "== the same, zoomed on the three-solution wedge (mu 1.5 to 4, theta 0.25 to 0.5 rad)"
"$build/apps/cpkit" map --preset fig5b --kind param-direction --param mu --from 1.5 --to 4 \
  --n 250 --theta-n 250 --theta-from 0.25 --theta-to 0.5 --out "$out/mu_direction_zoom" --plot
echo "== done: pictures and data in $out"
echo "the cpkit program: $build/apps/cpkit"
echo "  run it from anywhere: export PATH=\"$build/apps:\$PATH\""
echo "  or install it (program, plotting scripts, libraries): cmake --install $build --prefix \$HOME/.local"
