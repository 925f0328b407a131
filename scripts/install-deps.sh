#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds and runs with. Idempotent: does
# nothing (and needs no network) when every package is already present.
#
# With --no-install-recommends, apt leaves out packages whose files the -dev packages' CMake
# exports still name: openimageio-tools (OpenImageIO::iconvert and the other tools) and
# python3-imath (Imath::PyImath_Python3_11). CMakeLists.txt fails at configure, naming the
# target and file, if any imported target's file is missing; scripts/check-new-machine.sh
# reruns the quick start on a machine purged back to the image's packages.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libglm-dev
  libopenvdb-dev libboost-iostreams-dev libtinygltf-dev libstb-dev nlohmann-json3-dev
  libopenimageio-dev openimageio-tools libopencv-core-dev python3-imath libembree-dev libtbb-dev libcli11-dev
  libgtest-dev libbenchmark-dev chromium python3-matplotlib libssl-dev git
  pybind11-dev python3-pytest python3-numpy python3-openimageio
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
