#!/usr/bin/env bash
# Installs what VVM needs to build, test and benchmark on Debian 12 (bookworm).
set -euo pipefail
# gmsh, tetgen: the hex-dominant I/O test and the vvm-mesh tests check and re-save meshes with
# gmsh; vvm-mesh optimize is tested on meshes written by both.
# ccache: the build compiles through it when present (CMakeLists.txt).
# pybind11-dev, python3-dev: the Python module vvm; python3-pytest its tests;
# python3-matplotlib its example (examples/python), which the tests run.
# doxygen: the manuals' HTML (cmake --build build --target doc) and the test that they build
# without warnings (doc_without_warnings).
packages=(g++ make cmake ccache libcgal-dev libeigen3-dev libtbb-dev libboost-dev liblbfgspp-dev python3-meshio gmsh tetgen zlib1g-dev
          pybind11-dev python3-dev python3-pytest python3-matplotlib doxygen)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all packages present"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install_dependencies: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
