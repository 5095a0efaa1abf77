#!/usr/bin/env bash
# Set-up + build + the main job (README's first command).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build="${CPKIT_BUILD_DIR:-$root/build}"
"$build/apps/cpkit" lcp solve "$root/tests/data/lcp/murty_exp_6.json"
