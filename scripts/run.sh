#!/usr/bin/env bash
# Installs the dependencies, builds only the voxatlas program (not the tests) and opens the
# viewer in voxel GI mode on the default scene, the Cornell box. Without a display the viewer
# says so and writes a headless screenshot with GI instead, voxatlas-view.png in the current
# directory (ignored by git), and prints its path. Extra arguments go to `voxatlas view`
# (e.g. a scene path, or --mode atlas).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" >/dev/null
cmake --build build -j "$(nproc)" --target voxatlas
exec ./build/voxatlas view "$@"   # the viewer opens in voxel GI mode unless --mode is given
