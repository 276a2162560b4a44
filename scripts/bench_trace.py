#!/usr/bin/python3
"""Where the cone-trace pass' time goes, and what a change to it saves: `voxatlas render
--timings` of the Cornell box from inside (every pixel traces, 1280x720 unless --size), with
variants of shaders/voxel/cone_tracing.glsl that switch one part off, timed in interleaved
rounds; prints each variant's trace-pass time as a ratio to the unchanged shader's.

The variants are text substitutions in a copy of shaders/ (VOXATLAS_SHADER_DIR); a
substitution that no longer matches stops the script, so the profile cannot silently time
the unchanged shader. With --counts it also renders each shader's step counters instead of
its light (the "counts" variant) and prints the mean per cone.

Usage: /usr/bin/python3 scripts/bench_trace.py [--rounds N] [--frames N] [--size WxH]
       [--set key=value ...] [--against DIR] [--counts] [--check]
  --against DIR: time the base folder (--base, default shaders/) against another shader
  folder (a change's after and before) instead of the profile variants.
"""
import argparse
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
# Imported in main() after --check, which needs neither (nor their numpy): see load_modules.
il = common = None
SHADERS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "shaders")


def load_modules():
    global il, common
    import interleaved as il  # noqa: E402
    import measure_common as common  # noqa: E402

TRACE = os.path.join("voxel", "cone_tracing.glsl")
TRACE_MAIN = os.path.join("voxel", "cone_trace.frag")
CONE_CALL = "traceCone(origin, n, maxDistance, tanHalf);"
RING_LOOP = "for (int i = 0; i < 8; ++i) {"
LIGHT_CALL = "reflected = coarsestLight("

# name -> (what it switches off, [(old, new), ...] in cone_tracing.glsl)
PROFILE = {
    "no cones": ("every cone (rasterisation, material and set-up remain)", [
        ("vec3 e = voxel.traceWeights.x * " + CONE_CALL, "vec3 e = vec3(origin * 1e-9);"),
        (RING_LOOP, "for (int i = 0; i < 0; ++i) {")]),
    "1 cone": ("the 8 ring cones (the central cone remains)", [
        (RING_LOOP, "for (int i = 0; i < 0; ++i) {")]),
    "no light reads": ("the light read where a cone meets a surface (coarsestLight: "
                       "filtered voxels and the pyramid)", [
        (LIGHT_CALL, "reflected = vec3(0.25) + 0.0 * (")]),
}

COUNTER_DECL = "vec3 traceCone(vec3 origin, vec3 dir, float maxDistance, float tanHalf) {"
COUNTS = [
    (COUNTER_DECL, "int gSteps = 0, gFetches = 0, gHits = 0;\n" + COUNTER_DECL),
    ("coverage = clamp(texelFetch(voxelAlbedoTexture, texel, 0).a, 0.0, 1.0);",
     "coverage = clamp(texelFetch(voxelAlbedoTexture, texel, 0).a, 0.0, 1.0); ++gSteps; "
     "++gFetches;"),
    ("vec4 plane = texelFetch(voxelNormalTexture, texel, 0);",
     "vec4 plane = texelFetch(voxelNormalTexture, texel, 0); ++gFetches;"),
    (LIGHT_CALL, "++gHits; " + LIGHT_CALL),
    ("VoxelSample s = readLevel(p, level);", "VoxelSample s = readLevel(p, level); "
     "++gSteps; gFetches += 3;"),
    (TRACE_MAIN,
     "outIndirect = vec4(irradiance, viewDepth);",
     "outIndirect = vec4(float(gSteps) / 9.0, float(gFetches) / 9.0, float(gHits) / 9.0, "
     "viewDepth + 0.0 * irradiance.x);"),
    # The counters reach the image unscaled by the surface's albedo.
    (os.path.join("render", "forward.frag"),
     "indirect = diffuse / PI * upsampledIndirect(indirectTexture, viewDepth);",
     "indirect = upsampledIndirect(indirectTexture, viewDepth);"),
]


def variant_dir(root, name, substitutions, base):
    target = os.path.join(root, name.replace(" ", "_"))
    shutil.copytree(base, target)
    for substitution in substitutions:
        file, old, new = substitution if len(substitution) == 3 else (TRACE, *substitution)
        path = os.path.join(target, file)
        text = open(path).read()
        if old not in text:
            sys.exit(f"variant '{name}': '{old}' is not in {file} any more")
        open(path, "w").write(text.replace(old, new, 1))
    return target


def counts(shader_dir, settings, size):
    """Mean steps, fetches and surfaces met per cone over the traced pixels."""
    env = dict(os.environ, VOXATLAS_SHADER_DIR=shader_dir)
    options = ["--mode", "voxel", "--output", "indirect", "--camera", il.INSIDE_CAMERA,
               "--set", "render.plan=adaptive", "--set", "voxel.filter=0",
               "--set", "voxel.trace_scale=1"] + common.size_args(size)
    image = common.render(common.CORNELL, options + common.settings_args(settings), hdr=True,
                          env=env).image
    covered = image.sum(axis=2) > 0
    return image[covered].mean(axis=0)


def parse_size(text):
    w, h = text.split("x")
    return int(w), int(h)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin", help="voxatlas executable (default build/voxatlas)")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--frames", type=int, default=2)
    parser.add_argument("--size", type=parse_size, default=None,
                        help="output size (default 1280x720)")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    parser.add_argument("--against", help="shader folder to time the base folder against")
    parser.add_argument("--against-bin", help="voxatlas that runs the --against shaders "
                        "(default --bin): a change in the passes' C++ as well")
    parser.add_argument("--base", default=SHADERS,
                        help="shader folder the variants start from (default shaders/)")
    parser.add_argument("--counts", action="store_true")
    parser.add_argument("--check", action="store_true",
                        help="only make every variant's shaders (each substitution must still "
                        "match) and exit: ctest's lint.bench_trace_variants")
    args = parser.parse_args()
    if args.check:
        with tempfile.TemporaryDirectory() as tmp:
            for name, (_, subs) in {**PROFILE, "counts": (None, COUNTS)}.items():
                variant_dir(tmp, name, subs, args.base)
        print(f"{len(PROFILE) + 1} variants of {args.base} made")
        return
    load_modules()
    args.size = args.size or (il.WIDTH, il.HEIGHT)
    common.use_binary(args.bin or common.BIN)
    settings = {"voxel.trace_scale": 1, "voxel.cache": 0}
    settings.update(kv.split("=", 1) for kv in args.set)
    with tempfile.TemporaryDirectory() as tmp:
        dirs = {"shader": variant_dir(tmp, "shader", [], args.base)}
        if args.against:
            dirs["against"] = os.path.abspath(args.against)
        else:
            for name, (_, subs) in PROFILE.items():
                dirs[name] = variant_dir(tmp, name, subs, args.base)
        if args.counts:
            step_dir = variant_dir(tmp, "counts", COUNTS, args.base)
            steps, fetches, hits = counts(step_dir, settings, args.size)
            print(f"per cone: {steps:.1f} steps, {fetches:.1f} fetches (coverage + normal "
                  f"texels, 3 per finer-level sample), {hits:.2f} surfaces met")
        load_start = il.load_average()
        bins = {name: common.BIN for name in dirs}
        if args.against_bin:
            bins["against"] = os.path.abspath(args.against_bin)
        configs = {name: (lambda d=d, b=bins[name]: il.voxatlas_frame(
            settings, args.frames, 1, args.size, shader_dir=d, binary=b))
                   for name, d in dirs.items()}
        results = il.run_rounds(configs, args.rounds)
    print(f"load average {load_start} -> {il.load_average()}; settings {settings}; "
          f"size {args.size[0]}x{args.size[1]}; {args.rounds} rounds x {args.frames} frames")
    print("| variant | trace / unchanged | rounds | trace ms (median) | filter ms |")
    print("|---|---|---|---|---|")
    for name in dirs:
        value, values = il.ratio_median(results, name, "shader", "voxel/trace")
        print(f"| {name} | x{value:.3f} | {il.spread(values)} | "
              f"{il.median(results, name, 'voxel/trace'):.0f} | "
              f"{il.median(results, name, 'voxel/filter'):.0f} |")


if __name__ == "__main__":
    main()
