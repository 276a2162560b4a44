#!/usr/bin/python3
"""Measures voxel cone tracing as issue 'Voxel cone tracing GI' asks, as ratios in one run.

Every figure is the median over --frames timed frames after 2 warm-up frames, per pass, from
`voxatlas render --timings` (passes timed with glFinish on llvmpipe, see GpuProfiler.h).
Writes docs/results-voxel.md and images into docs/images/.
Usage: /usr/bin/python3 scripts/measure_voxel.py [--bin build/voxatlas] [--frames N]
       [--sponza PATH]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

CORNELL = common.CORNELL
SPONZA_CAMERA = common.SPONZA_CAMERA
PASSES = ["voxel/voxelize", "voxel/inject", "voxel/finalize", "voxel/propagate", "voxel/trace",
          "render/forward"]
NO_SPECULAR = {"material.specular": 0}


def render(scene, settings, frames, width=1280, height=720, extra=(), out_png=None):
    """Per-pass median ms, 'frame' = their sum, the memory report and the renderer."""
    # Every pass every frame, as in the thesis (static caching would skip them).
    report = common.render_timed(scene, {"voxel.cache": 0, **NO_SPECULAR, **settings}, frames,
                                 2, (width, height), extra, out_png=out_png).report
    times = common.pass_medians(report)
    times["memory"] = report["memory_bytes"]
    times["renderer"] = report["gl_renderer"]
    return times


def voxel_gi(settings, frames, extra=(), **kwargs):
    """The Cornell box in voxel GI mode."""
    return render(CORNELL, settings, frames, extra=["--mode", "voxel", *extra], **kwargs)


def ratio(a, b):
    return f"x{a / b:.2f}" if b > 0 else "-"


def say_header(say, base, frames):
    say("# Voxel cone tracing: measured costs\n")
    say("Produced by `/usr/bin/python3 scripts/measure_voxel.py` (after `bash scripts/build.sh`)")
    say(f"on {base['renderer']}. Medians of {frames} frames after 2 warm-up frames, 1280x720, the")
    say("thesis' reference settings (render.plan=fixed: v=32, l=3, multiplier 8, injection = v,")
    say("trace scale 1/2)")
    say("unless a row says otherwise. llvmpipe runs on 2 CPU cores: compare ratios, not")
    say("milliseconds, with the thesis' GTX 1060 figures.")
    say(f"Load average when the run started: {os.getloadavg()[0]:.1f} (2 cores); other jobs")
    say("inflate every millisecond and blur ratios between rows measured minutes apart.\n")


def say_passes(say, base):
    say("## Per-pass time at the defaults (Cornell box)\n")
    say("| pass | ms | share of frame |")
    say("|---|---|---|")
    for p in PASSES:
        say(f"| {p} | {base.get(p, 0):.1f} | {100 * base.get(p, 0) / base['frame']:.0f}% |")
    say(f"| whole frame | {base['frame']:.1f} | |\n")
    say("Target: the default voxel-GI frame at 1280x720 on the Cornell box under 500 ms median:")
    say(f"**{base['frame']:.0f} ms**.\n")


def measure_trace_scale(say, frames):
    say("## Cone-trace resolution (Cornell box)\n")
    trace = {s: voxel_gi({"voxel.trace_scale": s}, frames) for s in (1.0, 0.5, 0.25)}
    full = trace[1.0]["voxel/trace"]
    say("| trace scale | trace ms | / full | thesis | ideal |")
    say("|---|---|---|---|---|")
    for s, thesis, ideal in ((1.0, "x1", "x1"), (0.5, "x0.346", "x0.25"),
                             (0.25, "x0.102", "x0.0625")):
        ms = trace[s]["voxel/trace"]
        say(f"| {s} | {ms:.1f} | {ratio(ms, full)} | {thesis} | {ideal} |")
    say("")


def measure_resolution(say, base, frames):
    say("## Voxel resolution 32 -> 64, and 4 levels with doubled extent (Cornell box)\n")
    v32 = base
    v64 = voxel_gi({"voxel.resolution": 64}, frames)
    l4 = voxel_gi({"voxel.resolution": 64, "voxel.cascades": 4}, frames)
    thesis64 = {"voxel/voxelize": "x2.07", "voxel/inject": "x1.28", "voxel/propagate": "x9.73",
                "voxel/trace": "x1.09"}
    thesis_l4 = {"voxel/propagate": "x14.65", "voxel/trace": "x2.64"}
    say("| pass | v=32 ms | v=64 ms | 64/32 | thesis 64/32 | v=64, l=4 ms | l4/v32 | thesis |")
    say("|---|---|---|---|---|---|---|---|")
    for p in PASSES[:-1]:
        a, b, c = v32.get(p, 0), v64.get(p, 0), l4.get(p, 0)
        say(f"| {p} | {a:.1f} | {b:.1f} | {ratio(b, a)} | {thesis64.get(p, '-')} | {c:.1f} "
            f"| {ratio(c, a)} | {thesis_l4.get(p, '-')} |")
    say("")
    say("With l=4 the coarsest level doubles the covered edge at the same finest voxel size.\n")


def measure_lights(say, base, frames):
    say("## A second light; injection resolution doubled (Cornell box)\n")
    two = voxel_gi({}, frames, ["--light", "point:0.15,0.45,-0.15:1,1,1:0.1"])
    inj = voxel_gi({"voxel.inject_resolution": 64}, frames)
    say("| change | inject ms | finalize ms | inject ratio | thesis |")
    say("|---|---|---|---|---|")
    for label, run, inject_ratio, thesis in (
            ("defaults (1 point light, 32^2 per face)", base, "x1", "x1"),
            ("+ second point light", two, ratio(two["voxel/inject"], base["voxel/inject"]),
             "x2.36"),
            ("injection 64^2 per face", inj, ratio(inj["voxel/inject"], base["voxel/inject"]),
             "x4.11")):
        say(f"| {label} | {run['voxel/inject']:.2f} | {run['voxel/finalize']:.2f} "
            f"| {inject_ratio} | {thesis} |")
    say("")


def measure_against_direct(say, base, frames, sponza):
    """Returns whether Sponza was measured (and its image written)."""
    say("## Voxel-GI frame against the direct-only frame\n")
    direct_c = render(CORNELL, {}, frames)
    rows = [("Cornell box", base, direct_c)]
    if os.path.exists(sponza):
        camera = ["--camera", SPONZA_CAMERA]
        sponza_v = render(sponza, {}, frames, extra=["--mode", "voxel", *camera],
                          out_png=os.path.join(common.IMAGES, "sponza_voxel_1280.png"))
        sponza_d = render(sponza, {}, frames, extra=camera)
        rows.append(("Sponza", sponza_v, sponza_d))
    say("| scene | direct frame ms | voxel-GI frame ms | GI / direct |")
    say("|---|---|---|---|")
    for name, gi, direct in rows:
        say(f"| {name} | {direct['frame']:.0f} | {gi['frame']:.0f} "
            f"| {ratio(gi['frame'], direct['frame'])} |")
    say("")
    return len(rows) > 1


ACCURACY_VARIANTS = [
    ("defaults (thesis settings; flux/area injection; back faces skipped)", {}),
    ("the thesis' fragment-mean injection", {"voxel.inject_fragment_mean": 1}),
    ("the thesis' 1/(1+d^2) falloff", {"voxel.falloff": 1}),
    ("bilinear upsampling (thesis)", {"voxel.upsample_depth": 0}),
    ("trace scale 0.25", {"voxel.trace_scale": 0.25}),
    ("trace scale 1", {"voxel.trace_scale": 1}),
    ("v = 16", {"voxel.resolution": 16}),
    ("v = 64", {"voxel.resolution": 64}),
    ("v = 128, 2 cascades", {"voxel.resolution": 128, "voxel.cascades": 2}),
    ("injection 4v", {"voxel.inject_resolution": 128}),
    ("scene-centred cascade + max-axis coverage", {"voxel.scene_centred": 1,
                                                   "voxel.coverage_max_axis": 1}),
]


def measure_accuracy(say):
    say("## Accuracy against the path tracer (Cornell box, indirect component)\n")
    size = 128
    images = common.IMAGES
    truth = common.render_indirect(CORNELL, "reference", {"reference.spp": 1024}, size,
                                   os.path.join(images, "cornell_reference_indirect.png")).image
    say(f"{size}x{size}, camera 0, `material.specular=0`; reference: `--mode reference` with one")
    say("bounce, 1024 spp. Relative RMSE and mean-energy ratio over all pixels (the box fills")
    say("the view), as in src/reference/ImageMetrics.h.\n")
    say("| configuration | relative RMSE | energy ratio (voxel / reference) |")
    say("|---|---|---|")
    for label, settings in ACCURACY_VARIANTS:
        name = "_".join(["cornell_voxel_indirect"] + [
            f"{k.split('.')[1]}{v}" for k, v in settings.items()])
        image = common.render_indirect(CORNELL, "voxel", {**NO_SPECULAR, **settings}, size,
                                       os.path.join(images, name + ".png")).image
        # The Cornell box fills the view: every pixel counts.
        rmse, energy = common.errors(image, truth)
        say(f"| {label} | {rmse:.3f} | {energy:.3f} |")
    say("")
    say("| voxel GI (defaults), indirect | reference, indirect |")
    say("|---|---|")
    say("| ![voxel](images/cornell_voxel_indirect.png) "
        "| ![reference](images/cornell_reference_indirect.png) |")
    say("")


def measure_memory(say):
    say("## GPU memory of the cascade\n")
    say("Five textures of v^3 l texels: albedo, irradiance and the per-light helper in RGBA16F,")
    say("normals in RGBA8_SNORM, the lock in R32UI (32 bytes per voxel), and the RGBA16F pyramid")
    say("of the coarsest level's light ((v/2)^3 texels and their mips). Thesis: 3.46 MB at")
    say("v=32, l=3; 27 MB at v=64; 216 MB at v=128; 36 MB at v=64, l=4. Not counted: the")
    say("fixed-point flux sums injection adds to (three R32UI, 12 bytes per voxel), which the")
    say("thesis' float sums under the lock do without.\n")
    say("| v | l=3 | l=4 |")
    say("|---|---|---|")
    for v in (32, 64, 128):
        cells = []
        for levels in (3, 4):
            r = voxel_gi({"voxel.resolution": v, "voxel.cascades": levels}, 1,
                         width=64, height=64)
            cells.append(f"{common.voxel_cascade_bytes(r['memory']) / 1e6:.2f} MB")
        say(f"| {v} | {cells[0]} | {cells[1]} |")
    say("")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=10)
    common.add_sponza_argument(parser)
    common.add_bin_argument(parser)
    args = parser.parse_args()
    common.use_binary(args.bin)
    f = args.frames
    lines = []
    say = lines.append

    base = voxel_gi({}, f, out_png=os.path.join(common.IMAGES, "cornell_voxel_1280.png"))
    say_header(say, base, f)
    say_passes(say, base)
    measure_trace_scale(say, f)
    measure_resolution(say, base, f)
    measure_lights(say, base, f)
    with_sponza = measure_against_direct(say, base, f, args.sponza)
    measure_accuracy(say)
    measure_memory(say)
    say("![Cornell box, voxel GI, 1280x720](images/cornell_voxel_1280.png)\n")
    if with_sponza:
        say("![Sponza, voxel GI, 1280x720](images/sponza_voxel_1280.png)\n")
    common.write_page("results-voxel.md", lines)
    print("wrote docs/results-voxel.md")


if __name__ == "__main__":
    main()
