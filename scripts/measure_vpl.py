#!/usr/bin/env python3
"""Scores --mode vpl against the path tracer (one bounce) on the Cornell variants of the scene
suite and on Sponza under a sun, and measures the seed's claims as ratios: interleaving against
every VPL at every pixel (time and error, same VPL count), the share of the frame spent on
visibility, and the energy the clamp removes (default B against a tiny one).

    /usr/bin/python3 scripts/measure_vpl.py [--size 96] [--bin build/voxatlas]
        [--visibility none|cascade|svo]

(scripts/measure_vpl_visibility.py compares the visibilities side by side.)

Prints the Markdown tables docs/results-vpl.md quotes. References are rendered once at
reference.spp=1024 and cached on disk (ReferenceCache); the default plan is used throughout.
"""
import argparse
import os
import tempfile

import measure_common as mc

SUITE = ["cornell_classic", "cornell_double_sided", "cornell_low_light",
         "cornell_open_front_sun", "cornell_spot", "cornell_x10", "closed_white_box",
         "two_rooms_thin_wall"]
SPONZA_SUN = ["--camera", "-1.2,1.7,-8,0.8,3.5,10,60", "--light", "none",
              "--light", "dir:0.2,-1,0.3:1,1,1:4"]
LAMBERTIAN = {"material.specular": 0}


def render(scene, mode, size, settings, extra=(), out_png=None, frames=1):
    """Indirect component (linear HDR) and the timings report of one render."""
    with tempfile.TemporaryDirectory() as tmp:
        pfm, report = os.path.join(tmp, "o.pfm"), os.path.join(tmp, "t.json")
        cmd = [mc.BIN, "render", scene, "--mode", mode, "--output", "indirect",
               "--out", out_png or os.path.join(tmp, "o.png"), "--hdr", pfm,
               "--timings", report, "--exposure", "auto", "--tonemap", "filmic"]
        cmd += mc.size_args(size) + mc.settings_args({**LAMBERTIAN, **settings}) + list(extra)
        if frames > 1:
            cmd += ["--set", f"render.frames={frames}", "--set", "render.warmup=1"]
        mc.run(cmd)
        import json
        return mc.read_pfm(pfm), json.load(open(report))


def reference(scene, size, extra=()):
    image, _ = render(scene, "reference", size, {"reference.spp": 1024}, extra)
    return image, mc.reference_mask(image)


def vpl_ms(report):
    return {k: v for k, v in mc.pass_medians(report).items() if k.startswith("vpl/")}


def score_row(name, scene, size, extra, images, label=None, settings=None):
    truth, mask = reference(scene, size, extra)
    image, report = render(scene, "vpl", size, settings or {}, extra,
                           os.path.join(images, f"vpl-{name}.png") if images else None)
    rmse, energy = mc.errors(image, truth, mask)
    return f"| {label or name} | {rmse:.3f} | {energy:.3f} |", (truth, mask)


def comparison(scene, size, truth, mask, label, variants, frames=3):
    """One row per variant, and the per-pass medians of every variant (ms)."""
    lines = [f"| {label} | relative RMSE | energy | gather + filter ms (median of {frames}) |",
             "| --- | --- | --- | --- |"]
    passes = []
    for name, settings in variants:
        image, report = render(scene, "vpl", size, settings, frames=frames)
        rmse, energy = mc.errors(image, truth, mask)
        medians = mc.pass_medians(report)
        work = sum(v for k, v in medians.items()
                   if k.startswith("vpl/gather") or k == "vpl/filter")
        lines.append(f"| {name} | {rmse:.3f} | {energy:.3f} | {work:.1f} |")
        passes.append(f"{name}: " + ", ".join(f"{k} {v:.1f}" for k, v in medians.items()))
    return lines + [""] + passes


def vpl_arguments(description):
    """The options of the VPL measurements: binary, Sponza, image size, where renders go."""
    parser = argparse.ArgumentParser(description=description)
    mc.add_bin_argument(parser)
    mc.add_sponza_argument(parser)
    parser.add_argument("--size", type=int, default=96)
    parser.add_argument("--images", default=os.path.join(mc.IMAGES, "vpl"),
                        help="where the vpl renders are written ('' = nowhere)")
    return parser


def main():
    parser = vpl_arguments(__doc__.splitlines()[0])
    parser.add_argument("--visibility", choices=["none", "cascade", "svo"], default="cascade",
                        help="vpl.visibility of the accuracy table")
    args = parser.parse_args()
    visibility = {"vpl.visibility": args.visibility}
    mc.use_binary(args.bin)
    if args.images:
        os.makedirs(args.images, exist_ok=True)

    lines = ["| scene | indirect relative RMSE (target <= 0.30) | energy (target 0.9-1.1) |",
             "| --- | --- | --- |"]
    truths = {}
    for name in SUITE:
        scene = os.path.join(mc.ROOT, "assets", "scene_suite", name + ".gltf")
        row, truths[name] = score_row(name, scene, args.size, (), args.images,
                                      settings=visibility)
        lines.append(row)
    if os.path.exists(args.sponza):
        row, _ = score_row("sponza_sun", args.sponza, (128, 72), SPONZA_SUN, args.images,
                           "sponza_sun (energy target 0.85-1.15)", visibility)
        lines.append(row)
    print("\n".join(lines) + "\n")

    classic = os.path.join(mc.ROOT, "assets", "scene_suite", "cornell_classic.gltf")
    truth, mask = truths["cornell_classic"]
    print("\n".join(comparison(classic, args.size, truth, mask, "cornell_classic, 1024 VPLs", [
        ("interleaved 4x4, cascade visibility", {}),
        ("every VPL at every pixel, cascade visibility", {"vpl.interleave": 0}),
        ("interleaved 4x4, no visibility", {"vpl.visibility": "none"}),
        ("every VPL at every pixel, no visibility",
         {"vpl.interleave": 0, "vpl.visibility": "none"}),
        ("interleaved, clamp B = 1e-8 m^2", {"vpl.clamp": 1e-8}),
    ])) + "\n")


if __name__ == "__main__":
    main()
