#!/usr/bin/env bash
# Builds voxatlas and opens the viewer on the default scene (the Cornell box). Without a
# display the viewer says so and writes a headless screenshot, voxatlas-view.png, instead.
# Extra arguments go to `voxatlas view` (e.g. a scene path).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
exec ./build/voxatlas view "$@"
