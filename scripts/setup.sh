#!/usr/bin/env bash
# Installs the Debian 12 packages impossible needs, only when some are missing.
# Idempotent and non-interactive; uses apt-get as root or through sudo.
# Usage: scripts/setup.sh [PACKAGE...]   (extra packages a script needs too,
# e.g. fuzz.sh's clang)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libglm-dev libegl-dev libosmesa6-dev libglfw3-dev libtinygltf-dev
  nlohmann-json3-dev libstb-dev libgtest-dev libbenchmark-dev python3-glad libglu1-mesa-dev
  libboost-dev
  xvfb libegl-mesa0 libgl1-mesa-dri
  python3-dev pybind11-dev python3-numpy python3-pytest
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
