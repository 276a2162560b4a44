#!/usr/bin/python3
"""Where the cone-trace pass' time goes, and what a change to it saves: `voxatlas render
--timings` of the Cornell box from inside (every pixel traces, 1280x720 unless --size), with
variants of shaders/voxel/cone_tracing.glsl that switch one part off, timed in interleaved
rounds; prints each variant's trace-pass time as a ratio to the unchanged shader's.

The variants are text substitutions in a copy of shaders/ (VOXATLAS_SHADER_DIR); a
substitution that no longer matches stops the script, so the profile cannot silently time
the unchanged shader. With --counts it also renders counters instead of light (the "counts"
variant: what each iteration of a cone's walk did, and the opacity it ends with) and prints
their mean per cone.

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
CONE_CALL = "traceCone(origin, n, maxDistance, tanHalf, false);"
RING_LOOP = "for (int k = 0; k < 3; ++k) {"
LIGHT_CALL = "reflected = coarsestLight("
PYRAMID_READ = "textureLod(voxelPyramidTexture, tc, float(mip));"
PYRAMID_TEXEL = ("texelFetch(voxelPyramidTexture, clamp(ivec3(tc * vec3(textureSize(voxelPyramidTexture, "
                 "mip))), ivec3(0), textureSize(voxelPyramidTexture, mip) - 1), mip);")

TRACE_CONE_DECL = ("vec3 traceCone(vec3 origin, vec3 dir, float maxDistance, float tanHalf, "
                   "bool alone) {")
# The trace of Friduric's demo (the peer of results-performance.md) over the coarsest level:
# steps of one cone diameter from two voxels out, each one trilinear read of the radiance
# pyramid at the mip as wide as the cone, composited front to back. The pyramid keeps six
# faces side by side: the peer's one read takes the face the cone's dominant axis sees.
PEER_TRACE = """
    {
        int peerLevel = voxelLevels() - 1;
        float peerVoxel = levelVoxelSize(peerLevel);
        float peerDist = 2.0 * peerVoxel;
        vec3 peerRadiance = vec3(0.0);
        float peerOpacity = 0.0;
        while (peerDist < maxDistance && peerOpacity < 0.99) {
            vec3 uvw = (origin + dir * peerDist - levelOrigin(peerLevel)) / levelExtent(peerLevel);
            if (any(lessThan(uvw, vec3(0.0))) || any(greaterThan(uvw, vec3(1.0)))) break;
            float peerDiameter = max(2.0 * tanHalf * peerDist, peerVoxel);
            int peerAxis = abs(dir.x) > max(abs(dir.y), abs(dir.z)) ? 0
                    : (abs(dir.y) > abs(dir.z) ? 1 : 2);
            vec3 peerTc = vec3((uvw.x + float(faceSeenAlong(dir, peerAxis))) / float(VOXEL_FACES),
                    uvw.yz);
            vec4 s = textureLod(voxelPyramidTexture, peerTc, log2(peerDiameter / peerVoxel));
            peerRadiance += (1.0 - peerOpacity) * s.rgb / PI;
            peerOpacity += (1.0 - peerOpacity) * s.a;
            peerDist += peerDiameter;
        }
        return peerRadiance + (1.0 - peerOpacity) * frame.sky.rgb;
    }
"""

# name -> (what it switches off, [(old, new), ...] in cone_tracing.glsl)
PROFILE = {
    "no cones": ("every cone (rasterisation, material and set-up remain)", [
        ("vec3 e = voxel.cones.x * " + CONE_CALL, "vec3 e = vec3(origin * 1e-9);"),
        (RING_LOOP, "for (int k = 0; k < 0; ++k) {")]),
    "1 cone": ("the ring cones (the central cone remains)", [
        (RING_LOOP, "for (int k = 0; k < 0; ++k) {")]),
    "no light reads": ("the light read where a cone meets a surface (coarsestLight: "
                       "filtered voxels and the pyramid)", [
        (LIGHT_CALL, "reflected = vec3(0.25) + 0.0 * (")]),
    # The light read kept, its pyramid sample made cheaper (what the texture sample costs
    # within the read): the same mip for every lane, or one texel fetch at the mip below.
    "light read at one mip for all": ("the pyramid sample's per-lane mip: every lane reads "
                                      "mip 2", [(PYRAMID_READ, "textureLod(voxelPyramidTexture, tc, 2.0);")]),
    "light read as one texel": ("the pyramid sample's filtering: one texel fetch at the mip "
                                "below the cone's", [(PYRAMID_READ, PYRAMID_TEXEL)]),
    # Not a part switched off but the whole walk replaced: what the peer's trace costs in
    # this program (its accuracy: `--make NAME DIR`, then `voxatlas bench --suite quick`
    # with VOXATLAS_SHADER_DIR=DIR).
    "peer's trace": ("the walk: a cone samples the radiance pyramid at its own width, one "
                     "trilinear read per step, each step as long as the cone is wide", [
        (TRACE_CONE_DECL, TRACE_CONE_DECL + PEER_TRACE)]),
}

# What each iteration of a cone's walk did, counted per pixel over all its cones.
COUNTER_NAMES = ["leaps through empty space", "empty voxels stepped through",
                 "occupied voxels facing away", "planes the axis missed", "surfaces met",
                 "finer-level samples", "final opacity"]
COUNTS = [
    (TRACE_CONE_DECL, "float gCount[7] = float[7](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);\n"
     + TRACE_CONE_DECL),
    ("diameter = max(2.0 * tanHalf * dist, finest);\n                    continue;",
     "diameter = max(2.0 * tanHalf * dist, finest);\n                    gCount[0] += 1.0; "
     "continue;"),
    ("if (!voxelOccupied(plane)) continue;",
     "if (!voxelOccupied(plane)) { gCount[1] += 1.0; continue; }"),
    ("if (cosine > 0.0) continue;",
     "if (cosine > 0.0) { gCount[2] += 1.0; continue; }"),
    ("tolerance)) {\n                        continue;",
     "tolerance)) {\n                        gCount[3] += 1.0; continue;"),
    (LIGHT_CALL, "gCount[4] += 1.0; " + LIGHT_CALL),
    ("VoxelSample s = readLevel(p, level);",
     "VoxelSample s = readLevel(p, level); gCount[5] += 1.0;"),
    ("    if (steps < kMaxSteps) radiance += (1.0 - opacity) * frame.sky.rgb;",
     "    gCount[6] += opacity;\n"
     "    if (steps < kMaxSteps) radiance += (1.0 - opacity) * frame.sky.rgb;"),
    # Columns x mod 4 = 0, 1, 2 carry three counters each; 3 carries 1, which calibrates
    # the read-back (the renderer divides every image by the scene's pre-exposure).
    (TRACE_MAIN,
     "outIndirect = vec4(irradiance, viewDepth);",
     "int column = int(gl_FragCoord.x) & 3;\n"
     "    outIndirect = vec4(column == 3 ? vec3(9.0) : vec3(gCount[3 * column], "
     "column < 2 ? gCount[3 * column + 1] : 0.0, column < 2 ? gCount[3 * column + 2] : 0.0),"
     " viewDepth + 0.0 * irradiance.x);"),
    # The counters reach the image unfiltered and unscaled by the surface's albedo.
    (os.path.join("render", "forward.frag"),
     "indirect = diffuse / PI * upsampledIndirect(indirectTexture, viewDepth, vin.position, n);",
     "indirect = texelFetch(indirectTexture, ivec2(gl_FragCoord.xy), 0).rgb;"),
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
    """Mean of each counter per cone over the traced pixels, in COUNTER_NAMES' order."""
    env = dict(os.environ, VOXATLAS_SHADER_DIR=shader_dir)
    options = ["--mode", "voxel", "--output", "indirect", "--camera", il.INSIDE_CAMERA,
               "--set", "render.plan=adaptive", "--set", "voxel.filter=0",
               "--set", "gi.temporal_filter=0"] + common.size_args(size)
    settings = dict(settings, **{"voxel.trace_scale": 1})
    image = common.render(common.CORNELL, options + common.settings_args(settings), hdr=True,
                          env=env).image
    width = image.shape[1] // 4 * 4
    columns = [image[:, k:width:4] for k in range(4)]
    covered = columns[3].sum(axis=2) > 0
    per_cone = columns[3][covered][:, 0].mean()   # all the pixel's cones' worth, as read back
    means = [columns[k][covered].mean(axis=0) / per_cone for k in range(3)]
    values = [means[0][0], means[0][1], means[0][2], means[1][0], means[1][1], means[1][2],
              means[2][0]]
    return dict(zip(COUNTER_NAMES, values))


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
    parser.add_argument("--make", nargs=2, metavar=("VARIANT", "DIR"),
                        help="only write one variant's shaders to DIR (e.g. to score it with "
                        "VOXATLAS_SHADER_DIR=DIR voxatlas bench --suite quick) and exit")
    parser.add_argument("--check", action="store_true",
                        help="only make every variant's shaders (each substitution must still "
                        "match) and exit: ctest's lint.bench_trace_variants")
    args = parser.parse_args()
    if args.make:
        name, target = args.make
        variants = {**PROFILE, "counts": (None, COUNTS)}
        if name not in variants:
            parser.error(f"no variant '{name}' (variants: {', '.join(variants)})")
        if os.path.exists(target):
            parser.error(f"{target} exists; give a new folder")
        parent = os.path.dirname(os.path.abspath(target))
        with tempfile.TemporaryDirectory(dir=parent) as tmp:
            shutil.move(variant_dir(tmp, name, variants[name][1], args.base), target)
        print(f"wrote variant '{name}' to {target}")
        return
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
            per_cone = counts(step_dir, settings, args.size)
            print("per cone: " + ", ".join(f"{name} {value:.2f}"
                                           for name, value in per_cone.items()))
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
