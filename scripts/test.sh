#!/usr/bin/env bash
# Builds voxatlas and runs every test: CPU unit tests, command-line tests, headless GPU tests
# under EGL and OSMesa, the viewer under Xvfb, the GL lint and the loader fuzzing run.
# Extra arguments go to ctest (e.g. -L gpu, -R cornell).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure --timeout 900 -j 2 "$@"
