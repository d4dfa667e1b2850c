#!/usr/bin/env bash
# Installs every build and test dependency of tetblend from Debian 12 packages.
# Idempotent: packages already present are skipped, apt is not touched when
# nothing is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libcgal-dev libtet1.5-dev libsuitesparse-dev libceres-dev
  libvtk9-dev libcli11-dev nlohmann-json3-dev libtbb-dev zlib1g-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # The Python module and its tests, for Debian's /usr/bin/python3.
  pybind11-dev python3-dev python3-numpy python3-pytest
  clang libclang-rt-14-dev  # libFuzzer + ASan/UBSan runtimes for ./dev.sh fuzz
  libcgal-demo  # closed test meshes: data.tar.gz with data/meshes/*.off
  # ParaView's libraries and an X server for the pvpython tests. pvpython
  # itself (python3-paraview) conflicts with libvtk9-dev's python3-vtk9: the
  # tests unpack it into the build tree instead (tools/run_pvpython.py).
  paraview xvfb
  # Multithreaded BLAS for CHOLMOD's supernodal factorisations (becomes the
  # libblas.so.3 alternative): the 1M-tet compatible-mesh factorisation takes
  # ~4 s instead of ~6.5 s with ATLAS on 2 cores.
  libopenblas0-pthread
  # METIS's header for ordering large interiors with options of our own
  # (meshing/src/interior_ordering.cpp); CHOLMOD already links its library.
  libmetis-dev
  # Distributed batches (mpirun -n N tetblend batch) and their test; optional
  # at build time (the batch runs as one process without them).
  libopenmpi-dev openmpi-bin
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
