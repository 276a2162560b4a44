#!/usr/bin/env bash
# Builds voxatlas and runs every test: CPU unit tests, command-line tests, headless GPU tests
# under EGL and OSMesa, the viewer under Xvfb, the lints, the loader fuzzing run and the
# bench's CI form. Extra arguments go to ctest (e.g. -L gpu, -R cornell). After ctest's
# summary it lists every skipped test with its reason (e.g. how to provide Sponza).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
results=test-results.xml
rm -f "$results"
status=0
ctest --output-on-failure --timeout 900 -j 2 --output-junit "$results" "$@" || status=$?
if [ -f "$results" ]; then
    python3 ../scripts/test_summary.py "$results" || true
fi
exit "$status"
