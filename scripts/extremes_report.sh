#!/usr/bin/env bash
# Runs the stress matrix (ctest label `extremes`) and writes docs/results-extremes.md: one row
# per case and mode with its outcome, mean radiance, the plausible band it had to fall in, and
# the run's wall time. Usage: bash scripts/extremes_report.sh (after bash scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/tests/voxatlas_extremes_tests ] || { echo "build first: bash scripts/build.sh" >&2; exit 1; }
rows=build/test-output/extremes
rm -f "$rows"/*.md
start=$(date +%s)
status=0
ctest --test-dir build -L extremes -j2 --output-on-failure > build/test-output/extremes.log 2>&1 || status=$?
seconds=$(( $(date +%s) - start ))
order=$(build/tests/voxatlas_extremes_tests --gtest_list_tests | awk '/^  / {sub(/.*\//, "", $1); print $1}')
/usr/bin/python3 - "$rows" "$seconds" "$status" <<PY > docs/results-extremes.md
import os, sys
rows, seconds, status = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
order = """$order""".split()
print("# Numerical stability at the extremes\n")
print("Produced by \`bash scripts/extremes_report.sh\`, which runs \`ctest -L extremes\`")
print(f"(tests/extremes/ExtremesMatrixTest.cpp) and collects one row per run; {len(order)} runs")
print(f"took {seconds // 60} min {seconds % 60} s on 2 cores (llvmpipe), ctest exit status {status}.\n")
print("Every run is a \`voxatlas render\` process at 32x32 with a time limit (300 s, 900 s for the")
print("4096 extremes), \`material.specular=0\`, \`render.plan=fixed\` (the thesis' allocation,")
print("whose ends the cases push), the atlas at 256^2 unless the case sets it, the")
print("reference at 16 paths per pixel. It must exit 0 and write only finite, non-negative")
print("pixels whose mean radiance falls in the band: the unmodified Cornell box's mean in the same")
print("mode times the factor the case predicts (scaling the scene and its light by s and s^2")
print("changes nothing; radiance is linear in the light's intensity), or under an analytic")
print("ceiling. Rows marked *indirect* also check the indirect component alone against its")
print("prediction: that is where half floats would clip or underflow. Settings outside their")
print("range and resources over the 2 GiB budget must exit 2 with one line.\n")
print("| case | what | mode | outcome | mean radiance | plausible | seconds |")
print("|---|---|---|---|---|---|---|")
for name in order:
    path = os.path.join(rows, name + ".md")
    if os.path.exists(path):
        print(open(path).read().strip())
    else:
        print(f"| {name} | | | no result (crashed or timed out: see build/test-output/extremes.log) | | | |")
PY
cat >> docs/results-extremes.md <<'MD'

## What the matrix found, and what changed

Its first run failed 9 of 59 cases. The x1e4 ones, and part of the x1e-3 ones, came from
the test scene: its camera kept clip planes in metres. With those scaled, the remaining
failures were real defects. They are fixed as follows, along with other gaps the matrix
showed:

- **Light 1e7 cd**: voxel GI kept 0.05% and the atlas 0.35% of the predicted indirect light,
  because irradiance above 65504 W/m^2 was clipped in the RGBA16F volumes and atlas layers.
  Every radiometric GPU value now carries a power-of-two pre-exposure, chosen from the lights
  and the scene's size and divided out on read-back and presentation (`src/scene/Exposure.h`).
  Both modes now match their prediction to 0.1% at 1e-6 and at 1e7 cd.
- **Cornell box x 1e-3**: voxel GI and the atlas lost 60% of their indirect light. The 1/r^2
  cut-off of point lights was a fixed 0.1 mm, and the light hangs 10 um under the ceiling of
  the scaled box. The cut-off is now 1e-4 of the scene's diagonal (`lighting.glsl`). The
  matrix first showed the failure in every mode, because the test scene's camera kept its
  1 cm near plane; the scaled variant now scales the camera's clip planes too.
- **Cornell box moved 1e5 m**: float positions at 8 mm steps tore the walls and streaked the
  shadows, making the image 1.3x (voxel) and 1.7x (atlas) too bright. Scenes whose centre
  lies more than 16 of their own sizes from the origin are now moved next to it at load
  (`src/scene/Recentre.h`). The band for this case is +-10%.
- **Empty scene, atlas mode**: it was refused with exit 2. It now renders black like the
  other modes.
- **Zero lights**: the default light hid this case. `--light none` now removes the scene's
  lights and the default one.
- **64 point lights at `shadow.resolution=8192`** would allocate 96 GiB of cube maps. Shadow
  maps, atlas layers and voxel cascades are now each checked against one 2 GiB budget before
  anything is allocated (`src/gl/Limits.h`), and refused with exit 2. GL errors are reported
  by name (`GL_OUT_OF_MEMORY (0x0505)`), never ignored.

Left as they are, and visible in the table:

- The atlas on the 1e-3 box is 1.18x the unscaled box's mean, inside the +-25% band. The
  other modes match to 0.1%. Some atlas quantity (a texel area, or the r^2 clamp of the
  gather) still depends on absolute size.
- On the single triangle, both GPU modes read 1.14x the path tracer's mean. At 32x32 the
  triangle's edges cover partial pixels: the rasterizer counts pixel centres, while the path
  tracer averages over each pixel.
- The 64-light runs are the slowest in the GPU modes: 12 s on a quiet machine, 30 s under
  load. Each frame renders 64 cube shadow maps and 384 injection views.

Monotone convergence (issue item 2) has one test per mode. Atlas samples:
`AtlasReferenceGpuTest.AreaEstimatorErrorDoesNotGrowWithSamples`. Reference paths per pixel:
`ReferenceCornell.NoiseFallsWithSamples`. Voxel resolution and trace scale:
`tests/gpu/VoxelConvergenceGpuTest.cpp`, which scores each setting over six sub-voxel shifts
of the scene, since a single grid position moves the error by +-0.1. Voxel GI did not
converge at first. On the Cornell box's indirect light (96x96, against 256 spp), one grid
position measured:

| knob | values | relative RMSE before -> after | energy ratio before -> after |
|---|---|---|---|
| voxel.resolution | 16, 32, 64, 128 (l = 2) | 0.888, 0.591, 0.731, 1.016 -> 0.696, 0.468, 0.303, 0.336 | 1.33, 0.94, 0.74, 0.71 -> 1.42, 1.10, 0.98, 0.91 |
| voxel.trace_scale | 0.25, 0.5, 1 | 0.526, 0.591, 0.604 -> 0.461, 0.468, 0.476 | |

The causes, each fixed:

- Albedo was averaged without coverage while irradiance was premultiplied, so a filtered
  read beside empty voxels counted coverage twice.
- Cones wider than the coarsest voxels read one voxel around their axis. A ray sees the
  light's 2 cm ceiling hot spot either fully or not at all, and finer voxels made it miss
  more often. A mipmapped radiance pyramid of the coarsest level now serves them.
- Filtering smeared a one-voxel wall into two half-covered layers that leaked up to 25% of
  the light. Each voxel now stores its surface's offset from the voxel centre, and the cone
  axis is walked exactly through the coarsest level.
- The indirect filter's radius was counted in trace texels, so a finer trace was smoothed
  less. The radius now scales with the trace scale.

Left: at v = 16 the energy is 1.42, and on Sponza v = 64 is slightly worse than v = 32
(relative RMSE 0.75 against 0.72). The pyramid averages in surfaces that face away from a
cone.
MD
echo "wrote docs/results-extremes.md (ctest exit $status)"
exit $status
