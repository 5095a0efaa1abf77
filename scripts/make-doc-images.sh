#!/usr/bin/env bash
# Redraws every picture in docs/images/ with the commands the docs show (presets of
# `cpkit map --list-presets`), so that each picture is exactly what its command draws.
# Usage: scripts/make-doc-images.sh   (after scripts/build.sh or scripts/run-main.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cpkit="${CPKIT_BUILD_DIR:-$root/build}/apps/cpkit"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$cpkit" map --preset fig5a --out "$tmp/fig5a" --plot
"$cpkit" map --preset fig5b --out "$tmp/fig5b" --plot
"$cpkit" map --preset fig5b --kind param-direction --param mu --from 0.1 --to 4 --n 400 \
  --theta-n 720 --out "$tmp/mu_direction" --plot
"$cpkit" map --preset fig5b --kind param-direction --param mu --from 1.5 --to 4 --n 250 \
  --theta-n 250 --theta-from 0.25 --theta-to 0.5 --out "$tmp/mu_direction_zoom" --plot
"$cpkit" map --preset state-d --out "$tmp/state_d" --plot
"$cpkit" map --preset state-d-mu-kappa --out "$tmp/state_d_mu_kappa" --plot
# N points (docs/maps.md, "N points"): two grazing points whose coupling creates non-uniqueness
grazing="$root/docs/examples/coupled_grazing_points.json"
"$cpkit" map --system "$grazing" --kind param-direction --param coupling --from 0 --to 1 \
  --n 200 --theta-n 360 --out "$tmp/coupled_points_coupling_direction" --plot
"$cpkit" map --system "$grazing" --kind param-param --param coupling --from 0 --to 1 --n 40 \
  --param2 mu --from2 0.2 --to2 2 --n2 40 --out "$tmp/coupled_points_coupling_mu" --plot
# 3-D (docs/contact_3d.md): the sphere map and the fretting orbit
"$cpkit" map --system "$root/docs/examples/sphere_point_3d.json" --kind sphere --n 61 --n2 120 \
  --out "$tmp/sphere_map_3d" --plot
"$cpkit" simulate --system "$root/docs/examples/fretting_point_3d.json" --orbit 0.9 0.5 \
  --orbit-angle 0.4 --cycles 8 --steps-per-cycle 80 --plot "$tmp/fretting_3d"
for name in fig5a fig5b mu_direction mu_direction_zoom state_d state_d_mu_kappa coupled_points_coupling_direction \
    coupled_points_coupling_mu sphere_map_3d fretting_3d_orbit; do
  cp "$tmp/$name.png" "$root/docs/images/$name.png"
done
# The flat punch (docs/simulation.md): 55 s of CPU, minutes on a loaded machine; skipped with
# CPKIT_DOC_IMAGES_QUICK=1.
if [ -z "${CPKIT_DOC_IMAGES_QUICK:-}" ]; then
  "$cpkit" simulate --config "$root/docs/examples/flat_punch_fretting.json" --plot "$tmp/flat_punch"
  cp "$tmp/flat_punch_slip.png" "$tmp/flat_punch_wear.png" "$root/docs/images/"
fi
echo "docs/images/: fig5a fig5b mu_direction mu_direction_zoom state_d state_d_mu_kappa coupled_points_* sphere_map_3d" \
  "fretting_3d_orbit redrawn"
[ -z "${CPKIT_DOC_IMAGES_QUICK:-}" ] && echo "docs/images/: flat_punch_slip flat_punch_wear redrawn"
exit 0
