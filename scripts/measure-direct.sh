#!/usr/bin/env bash
# Measures what the scenes issue asks for: Sponza's load time and GPU memory, and the
# direct-light frame time at 1280x720 (median of 20 frames after 2 warm-up frames), for the
# Cornell box and Sponza. Writes docs/results-direct.md. Usage: scripts/measure-direct.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/voxatlas
sponza=${VOXATLAS_SPONZA:-../shared/assets/sponza/Sponza.gltf}
[ -x "$bin" ] || { echo "build first: bash scripts/build.sh" >&2; exit 1; }
[ -f "$sponza" ] || { echo "Sponza not found at $sponza (set VOXATLAS_SPONZA)" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

loads=()
for i in 1 2 3; do
    loads+=("$("$bin" info "$sponza" | awk '/^load time/ {print $3}')")
done
sponza_camera="0,2,14,0,4,-10,60"
"$bin" render assets/cornell_box/cornell_box.gltf --out "$out/c.png" --width 1280 --height 720 \
    --set render.frames=20 --set render.warmup=2 --timings "$out/cornell.json" 2>/dev/null
"$bin" render "$sponza" --camera "$sponza_camera" --out "$out/s.png" --width 1280 --height 720 \
    --set render.frames=20 --set render.warmup=2 --timings "$out/sponza.json" 2>/dev/null
cp "$out/s.png" docs/images/sponza_direct.png

/usr/bin/python3 - "$out" "${loads[@]}" <<'PY' > docs/results-direct.md
import json, statistics, sys
out, loads = sys.argv[1], [float(x) for x in sys.argv[2:]]
def load(name):
    return json.load(open(f"{out}/{name}.json"))
c, s = load("cornell"), load("sponza")
def ms(report, name):
    return next((p["gpu_ms_median"] for p in report["passes"] if p["name"] == name), 0.0)
def mib(report, prefix=""):
    return sum(v for k, v in report["memory_bytes"].items() if k.startswith(prefix)) / 2**20
print("# Direct light: load time, memory, frame time\n")
print("Produced by `bash scripts/measure-direct.sh` (after `bash scripts/build.sh`) on",
      s["gl_renderer"] + ".")
print("llvmpipe renders on the CPU: absolute milliseconds here are not GPU figures; compare the")
print("ratios. Passes are timed with glFinish around each (llvmpipe's timer queries miss its")
print("rasterizer threads; see src/gl/GpuProfiler.h).\n")
print("| figure | Cornell box | Sponza |")
print("|---|---|---|")
print(f"| load time (median of 3; parse, buffers, texture decode, validation) | - | {statistics.median(loads):.2f} s |")
print(f"| GPU memory total | {mib(c):.1f} MiB | {mib(s):.1f} MiB |")
print(f"| of which textures | {mib(c, 'scene/textures'):.1f} MiB | {mib(s, 'scene/textures'):.1f} MiB |")
print(f"| of which shadow maps | {mib(c, 'render/shadow'):.1f} MiB | {mib(s, 'render/shadow'):.1f} MiB |")
print(f"| direct-light frame (render/forward), 1280x720, median of 20 | {ms(c, 'render/forward'):.1f} ms | {ms(s, 'render/forward'):.1f} ms |")
print(f"| Sponza / Cornell frame time | | x{ms(s, 'render/forward') / ms(c, 'render/forward'):.2f} |")
print()
print("Shadow maps are rendered once and reused while lights and geometry stay still, so they")
print("are not part of the per-frame time.")
print()
print("Sponza (230,831 triangles, 23 textures) with its documented default light, from camera", "`0,2,14,0,4,-10,60`:\n")
print("![Sponza, direct light](images/sponza_direct.png)")
PY
echo "wrote docs/results-direct.md"
