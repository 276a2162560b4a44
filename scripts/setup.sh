#!/usr/bin/env bash
# Installs every Debian package voxatlas needs to build, test and benchmark.
# Idempotent: packages already present are skipped, and apt-get runs only when
# something is missing. Works as root, uses sudo otherwise.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config git
    libglfw3-dev libglm-dev
    libtinygltf-dev nlohmann-json3-dev libstb-dev libtinyexr-dev
    libegl-dev libopengl-dev libgl-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
    python3-glad
    libgtest-dev libgmock-dev
    libembree-dev
    libimgui-dev
    xvfb xauth
    python3-matplotlib python3-numpy
    clang libclang-rt-14-dev
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

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null; then
        echo "setup: need root or sudo to install: ${missing[*]}" >&2
        exit 1
    fi
    sudo_cmd=(sudo)
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
