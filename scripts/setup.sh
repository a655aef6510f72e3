#!/usr/bin/env bash
# Installs the Debian 12 packages rattleback needs, only those missing.
# Runs apt-get as root (directly, or through sudo when available).
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config
  libeigen3-dev libyaml-cpp-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libosmesa6-dev libegl-dev libegl-mesa0 libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  libpng-dev libfreetype-dev fonts-dejavu-core
  ffmpeg gnuplot-nox
  dpkg-dev
  clang libclang-rt-14-dev clang-format black
  libboost-dev nlohmann-json3-dev libtinyobjloader-dev
  chromium chromium-driver python3-selenium
  parallel slurm-wlm munge time
  libhdf5-dev python3-h5py
  pybind11-dev python3-dev python3-numpy python3-pytest python3-pandas python3-matplotlib
  python3-nbclient python3-ipykernel python3-nbformat python3-yaml
  mkdocs mkdocs-material
)
# The report's 3D player is bundled with node and npm (player/build.sh). Debian's nodejs and npm,
# unless node and npm are already there (a machine with NodeSource's nodejs, which carries its
# own npm and conflicts with Debian's).
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi

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

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo_cmd=(sudo); else
    echo "setup: need root to install: ${missing[*]}" >&2; exit 1
  fi
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
