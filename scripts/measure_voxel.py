#!/usr/bin/python3
"""Measures voxel cone tracing as issue 'Voxel cone tracing GI' asks, as ratios in one run.

Every figure is the median over --frames timed frames after 2 warm-up frames, per pass, from
`voxatlas render --timings` (passes timed with glFinish on llvmpipe, see GpuProfiler.h).
Writes docs/results-voxel.md and images into docs/images/.
Usage: /usr/bin/python3 scripts/measure_voxel.py [--frames N] [--sponza PATH]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "build", "voxatlas")
CORNELL = os.path.join(ROOT, "assets", "cornell_box", "cornell_box.gltf")
SPONZA_CAMERA = "0,2,14,0,4,-10,60"
PASSES = ["voxel/voxelize", "voxel/inject", "voxel/finalize", "voxel/propagate", "voxel/trace",
          "render/forward"]


def render(scene, settings, frames, width=1280, height=720, extra=(), out_png=None):
    with tempfile.TemporaryDirectory() as tmp:
        timings = os.path.join(tmp, "t.json")
        cmd = [BIN, "render", scene, "--out", out_png or os.path.join(tmp, "o.png"),
               "--width", str(width), "--height", str(height), "--timings", timings,
               "--set", f"render.frames={frames}", "--set", "render.warmup=2",
               # Every pass every frame, as in the thesis (static caching would skip them).
               "--set", "voxel.cache=0"]
        for key, value in settings.items():
            cmd += ["--set", f"{key}={value}"]
        cmd += list(extra)
        print(" ".join(cmd[1:]), file=sys.stderr, flush=True)
        subprocess.run(cmd, check=True, stderr=subprocess.DEVNULL)
        report = json.load(open(timings))
    times = {p["name"]: p["gpu_ms_median"] for p in report["passes"]}
    times["frame"] = sum(times.values())
    times["memory"] = report["memory_bytes"]
    times["renderer"] = report["gl_renderer"]
    return times


def read_pfm(path):
    import numpy
    with open(path, "rb") as f:
        f.readline()
        w, h = map(int, f.readline().split())
        f.readline()
        return numpy.frombuffer(f.read(), dtype="<f4").reshape(h, w, 3)[::-1]


def render_image(scene, mode, output, settings, size, out_png):
    """Renders one image (HDR) and returns it as a numpy array."""
    with tempfile.TemporaryDirectory() as tmp:
        pfm = os.path.join(tmp, "o.pfm")
        cmd = [BIN, "render", scene, "--mode", mode, "--output", output, "--out", out_png,
               "--hdr", pfm, "--width", str(size), "--height", str(size)]
        for key, value in settings.items():
            cmd += ["--set", f"{key}={value}"]
        print(" ".join(cmd[1:]), file=sys.stderr, flush=True)
        subprocess.run(cmd, check=True, stderr=subprocess.DEVNULL)
        return read_pfm(pfm)


def errors(image, reference):
    """Relative RMSE and mean-energy ratio (ImageMetrics.h); the Cornell box fills the view."""
    diff = image - reference
    return (float((diff ** 2).sum() / (reference ** 2).sum()) ** 0.5,
            float(image.sum() / reference.sum()))


def voxel_bytes(memory):
    return sum(v for k, v in memory.items() if k in (
        "voxel/albedo", "voxel/normal", "voxel/irradiance", "voxel/helper", "voxel/lock",
        "voxel/pyramid"))


def ratio(a, b):
    return f"x{a / b:.2f}" if b > 0 else "-"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=10)
    parser.add_argument("--sponza", default=os.environ.get(
        "VOXATLAS_SPONZA", os.path.join(ROOT, "..", "shared", "assets", "sponza", "Sponza.gltf")))
    args = parser.parse_args()
    f = args.frames
    voxel = {"material.specular": 0}
    lines = []
    say = lines.append

    base = render(CORNELL, {**voxel}, f, extra=["--mode", "voxel"],
                  out_png=os.path.join(ROOT, "docs", "images", "cornell_voxel_1280.png"))
    say("# Voxel cone tracing: measured costs\n")
    say("Produced by `/usr/bin/python3 scripts/measure_voxel.py` (after `bash scripts/build.sh`)")
    say(f"on {base['renderer']}. Medians of {f} frames after 2 warm-up frames, 1280x720, the")
    say("thesis' reference settings (v=32, l=3, multiplier 8, injection = v, trace scale 1/2)")
    say("unless a row says otherwise. llvmpipe runs on 2 CPU cores: compare ratios, not")
    say("milliseconds, with the thesis' GTX 1060 figures.")
    say(f"Load average when the run started: {os.getloadavg()[0]:.1f} (2 cores); other jobs")
    say("inflate every millisecond and blur ratios between rows measured minutes apart.\n")

    say("## Per-pass time at the defaults (Cornell box)\n")
    say("| pass | ms | share of frame |")
    say("|---|---|---|")
    for p in PASSES:
        say(f"| {p} | {base.get(p, 0):.1f} | {100 * base.get(p, 0) / base['frame']:.0f}% |")
    say(f"| whole frame | {base['frame']:.1f} | |\n")
    say(f"Target: the default voxel-GI frame at 1280x720 on the Cornell box under 500 ms median:")
    say(f"**{base['frame']:.0f} ms**.\n")

    say("## Cone-trace resolution (Cornell box)\n")
    trace = {s: render(CORNELL, {**voxel, "voxel.trace_scale": s}, f, extra=["--mode", "voxel"])
             for s in (1.0, 0.5, 0.25)}
    full = trace[1.0]["voxel/trace"]
    say("| trace scale | trace ms | / full | thesis | ideal |")
    say("|---|---|---|---|---|")
    for s, thesis, ideal in ((1.0, "x1", "x1"), (0.5, "x0.346", "x0.25"), (0.25, "x0.102", "x0.0625")):
        say(f"| {s} | {trace[s]['voxel/trace']:.1f} | {ratio(trace[s]['voxel/trace'], full)} | {thesis} | {ideal} |")
    say("")

    say("## Voxel resolution 32 -> 64, and 4 levels with doubled extent (Cornell box)\n")
    v32 = base
    v64 = render(CORNELL, {**voxel, "voxel.resolution": 64}, f, extra=["--mode", "voxel"])
    l4 = render(CORNELL, {**voxel, "voxel.resolution": 64, "voxel.cascades": 4}, f,
                extra=["--mode", "voxel"])
    thesis64 = {"voxel/voxelize": "x2.07", "voxel/inject": "x1.28", "voxel/propagate": "x9.73",
                "voxel/trace": "x1.09"}
    thesis_l4 = {"voxel/propagate": "x14.65", "voxel/trace": "x2.64"}
    say("| pass | v=32 ms | v=64 ms | 64/32 | thesis 64/32 | v=64, l=4 ms | l4/v32 | thesis |")
    say("|---|---|---|---|---|---|---|---|")
    for p in PASSES[:-1]:
        say(f"| {p} | {v32.get(p, 0):.1f} | {v64.get(p, 0):.1f} | {ratio(v64.get(p, 0), v32.get(p, 0))} "
            f"| {thesis64.get(p, '-')} | {l4.get(p, 0):.1f} | {ratio(l4.get(p, 0), v32.get(p, 0))} "
            f"| {thesis_l4.get(p, '-')} |")
    say("")
    say("With l=4 the coarsest level doubles the covered edge at the same finest voxel size.\n")

    say("## A second light; injection resolution doubled (Cornell box)\n")
    two = render(CORNELL, {**voxel}, f, extra=["--mode", "voxel", "--light",
                                                 "point:0.15,0.45,-0.15:1,1,1:0.1"])
    inj = render(CORNELL, {**voxel, "voxel.inject_resolution": 64}, f, extra=["--mode", "voxel"])
    say("| change | inject ms | finalize ms | inject ratio | thesis |")
    say("|---|---|---|---|---|")
    say(f"| defaults (1 point light, 32^2 per face) | {base['voxel/inject']:.2f} | {base['voxel/finalize']:.2f} | x1 | x1 |")
    say(f"| + second point light | {two['voxel/inject']:.2f} | {two['voxel/finalize']:.2f} | {ratio(two['voxel/inject'], base['voxel/inject'])} | x2.36 |")
    say(f"| injection 64^2 per face | {inj['voxel/inject']:.2f} | {inj['voxel/finalize']:.2f} | {ratio(inj['voxel/inject'], base['voxel/inject'])} | x4.11 |")
    say("")

    say("## Voxel-GI frame against the direct-only frame\n")
    direct_c = render(CORNELL, {**voxel}, f)
    rows = [("Cornell box", base, direct_c)]
    if os.path.exists(args.sponza):
        sponza_v = render(args.sponza, {**voxel}, f, extra=["--mode", "voxel", "--camera", SPONZA_CAMERA],
                          out_png=os.path.join(ROOT, "docs", "images", "sponza_voxel_1280.png"))
        sponza_d = render(args.sponza, {**voxel}, f, extra=["--camera", SPONZA_CAMERA])
        rows.append(("Sponza", sponza_v, sponza_d))
    say("| scene | direct frame ms | voxel-GI frame ms | GI / direct |")
    say("|---|---|---|---|")
    for name, gi, direct in rows:
        say(f"| {name} | {direct['frame']:.0f} | {gi['frame']:.0f} | {ratio(gi['frame'], direct['frame'])} |")
    say("")

    say("## Accuracy against the path tracer (Cornell box, indirect component)\n")
    size = 128
    images = os.path.join(ROOT, "docs", "images")
    truth = render_image(CORNELL, "reference", "indirect", {"reference.spp": 1024}, size,
                         os.path.join(images, "cornell_reference_indirect.png"))
    say(f"{size}x{size}, camera 0, `material.specular=0`; reference: `--mode reference` with one")
    say("bounce, 1024 spp. Relative RMSE and mean-energy ratio over all pixels (the box fills")
    say("the view), as in src/reference/ImageMetrics.h.\n")
    say("| configuration | relative RMSE | energy ratio (voxel / reference) |")
    say("|---|---|---|")
    variants = [
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
    for label, settings in variants:
        name = "cornell_voxel_indirect_" + "_".join(
            f"{k.split('.')[1]}{v}" for k, v in settings.items()) if settings else "cornell_voxel_indirect"
        image = render_image(CORNELL, "voxel", "indirect", {**voxel, **settings}, size,
                             os.path.join(images, name + ".png"))
        rmse, energy = errors(image, truth)
        say(f"| {label} | {rmse:.3f} | {energy:.3f} |")
    say("")
    say("| voxel GI (defaults), indirect | reference, indirect |")
    say("|---|---|")
    say("| ![voxel](images/cornell_voxel_indirect.png) | ![reference](images/cornell_reference_indirect.png) |")
    say("")

    say("## GPU memory of the cascade\n")
    say("Five textures of v^3 l texels: albedo, irradiance and the per-light helper in RGBA16F,")
    say("normals in RGBA8_SNORM, the lock in R32UI (32 bytes per voxel), and the RGBA16F pyramid")
    say("of the coarsest level's light ((v/2)^3 texels and their mips). Thesis: 3.46 MB at")
    say("v=32, l=3; 27 MB at v=64; 216 MB at v=128; 36 MB at v=64, l=4.\n")
    say("| v | l=3 | l=4 |")
    say("|---|---|---|")
    for v in (32, 64, 128):
        cells = []
        for l in (3, 4):
            r = render(CORNELL, {**voxel, "voxel.resolution": v, "voxel.cascades": l}, 1,
                       width=64, height=64, extra=["--mode", "voxel"])
            cells.append(f"{voxel_bytes(r['memory']) / 1e6:.2f} MB")
        say(f"| {v} | {cells[0]} | {cells[1]} |")
    say("")
    say("![Cornell box, voxel GI, 1280x720](images/cornell_voxel_1280.png)\n")
    if len(rows) > 1:
        say("![Sponza, voxel GI, 1280x720](images/sponza_voxel_1280.png)\n")
    with open(os.path.join(ROOT, "docs", "results-voxel.md"), "w") as out:
        out.write("\n".join(lines) + "\n")
    print("wrote docs/results-voxel.md")


if __name__ == "__main__":
    main()
