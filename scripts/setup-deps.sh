#!/usr/bin/env bash
# Installs the Debian 12 packages cpkit needs, only those that are missing.
# Usage: scripts/setup-deps.sh [--bench] [--tests]
#   --bench  also the peers the benchmarks compare against (Siconos numerics, lrslib).
#   --tests  also the peers the test suite compares against: Siconos' own .dat reader and writer
#            (python3-siconos, with python3-scipy for its sparse matrices), pytest for the
#            Python module's tests, GetFEM for its example (docs/examples/getfem_punch.py) and
#            lrslib (lrsnash: the peer of the bimatrix-game enumeration test), gfortran (the
#            Fortran example of the C API, docs/library.md), and Open MPI
#            (libopenmpi-dev, openmpi-bin) for the distributed maps (docs/cluster.md).
#            Without them those tests are skipped, saying why.
# The base set includes pybind11-dev and python3-dev: the Python module `cpkit` (python/), and
# libfclib-dev (with HDF5): the FCLIB frictional contact problem reader (docs/friction_contact.md).
# Runs `apt-get update` once, and only when something is missing. Needs root (or sudo).
set -euo pipefail

packages=(g++ cmake make pkg-config libeigen3-dev coinor-libipopt-dev libnlopt-cxx-dev
          catch2 libcli11-dev nlohmann-json3-dev libsimdjson-dev python3-matplotlib python3-numpy
          pybind11-dev python3-dev libfclib-dev)
for arg in "$@"; do
  case "$arg" in
    --bench) packages+=(libsiconos-numerics-dev lrslib) ;;
    --tests) packages+=(python3-siconos python3-scipy python3-pytest python3-getfem lrslib gfortran
                        libopenmpi-dev openmpi-bin) ;;
    *) echo "cpkit setup: unknown option $arg (valid: --bench, --tests)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "cpkit setup: installing missing Debian packages: ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "cpkit setup: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
