#!/usr/bin/python3
"""The shadow methods (shadow.method) against the path tracer and against each other, written
to docs/results-linespace.md:
- accuracy: the direct light of the emissive Cornell box (assets/cornell_box/
  cornell_box_emissive.gltf, lit only by its ceiling panel) by each method at shadow.rays=25,
  against the path tracer at 1024 spp, 96x96, on the surfaces the panel lights;
- speed: the forward pass (where the shadow rays are cast) at 25 rays per pixel and area
  light, 256x256, over scenes of rising size: the shadow-scaling spheres (70 k, 1.1 M, 1.9 M
  triangles, assets/shadow_scaling/make_shadow_scenes.py) and Sponza (231 k) under a 3 m
  square area light; methods interleaved round by round, medians, ratios within a round;
- memory and build time of each method's structures (the --timings report's `shadows`),
  beside the line-space paper's figures (SEEDS.md section 3).
The N x depth sweep of the line space is scripts/measure_linespace_sweep.py.

Usage: /usr/bin/python3 scripts/measure_shadows.py [--bin build/voxatlas] [--sponza PATH]
       [--rounds 3]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

EMISSIVE = os.path.join(common.ROOT, "assets", "cornell_box", "cornell_box_emissive.gltf")
GENERATOR = os.path.join(common.ROOT, "assets", "shadow_scaling", "make_shadow_scenes.py")
SPONZA_VIEW = ["--camera", "-1.2,1.7,-8,0.8,3.5,10,60", "--light", "none",
               "--light", "rect:0,11,0:3,0,0:0,0,3:1,1,1:40"]
RAYS = 25


def methods():
    """The shadow.method choices this build offers, from `render --help`."""
    text = subprocess.run([common.BIN, "render", "--help"], capture_output=True, text=True).stdout
    match = re.search(r"shadow\.method\s+\S+\s.*\[([a-z|]+)\]", text)
    return match.group(1).split("|") if match else ["shadowmap"]


def accuracy(names, lines):
    base = {"material.specular": 0, "shadow.rays": RAYS}
    # The path tracer averages each pixel's square; 4x4 samples per pixel do the same here,
    # so edges (silhouettes, shadow boundaries) are compared as averages, not point samples.
    gpu = {"render.supersample": 4}
    size = common.size_args(96)
    reference = common.render(EMISSIVE, ["--mode", "reference", "--output", "direct"] + size +
                              common.settings_args({**base, "reference.spp": 1024}), hdr=True).image
    indirect = common.render(EMISSIVE, ["--mode", "reference", "--output", "indirect"] + size +
                             common.settings_args({**base, "reference.spp": 1024}), hdr=True).image
    lit = common.reference_mask(indirect) & (reference.max(axis=2) < 2.0)
    lines += ["## Accuracy: the emissive Cornell box's direct light", "",
              f"shadow.rays={RAYS}, 96x96 with render.supersample=4 (pixels averaged over their "
              "square as the path tracer does), against the path tracer at 1024 spp, over the "
              f"{int(lit.sum())} pixels of the surfaces the panel lights (the panel itself, "
              "alike in every mode, left out). Pictures: `docs/images/shadows_<method>.png`.", "",
              "| method | relative RMSE | energy | target |", "|---|---|---|---|"]
    targets = {"linespace": "RMSE <= 0.10, energy 0.95-1.05", "bvh": "RMSE <= 0.05"}
    for name in names:
        png = os.path.join(common.IMAGES, f"shadows_{name}.png")
        image = common.render(EMISSIVE, ["--mode", "direct", "--output", "direct"] + size +
                              common.settings_args({**base, **gpu, "shadow.method": name}),
                              png, hdr=True).image
        rmse, energy = common.errors(image, reference, lit)
        error_image(image, reference, lit, os.path.join(common.IMAGES, f"shadows_error_{name}.png"))
        lines.append(f"| {name} | {rmse:.3f} | {energy:.3f} | {targets.get(name, '')} |")
    lines += ["", "Error images `docs/images/shadows_error_<method>.png`: red where the method is "
              "darker than the path tracer (over-occlusion), blue where it is brighter, full "
              "colour at 50% of the reference; grey where the surface is not compared. The line "
              "space's red bands along the tops of the walls, where rays to the panel pass "
              "close to the ceiling, and at the edge of the tall block's shadow are its "
              "approximation: a ray through a non-empty shaft one level above the leaves counts "
              "as blocked. The voxel cones darken the same bands more and blur the shadows "
              "(red and blue beside each other).", ""]


def error_image(image, reference, mask, path):
    ref = reference.mean(axis=2)
    rel = (image.mean(axis=2) - ref) / np.maximum(ref, 1e-3 * ref[mask].mean())
    rel = np.clip(rel / 0.5, -1.0, 1.0)
    rgb = np.ones(ref.shape + (3,))
    rgb[..., 1] = 1.0 - np.abs(rel)
    rgb[..., 0] = np.where(rel < 0, 1.0, 1.0 - rel)
    rgb[..., 2] = np.where(rel > 0, 1.0, 1.0 + rel)
    rgb[~mask] = 0.35
    common.write_png(path, rgb, scale=3)


def forward_ms(scene, extra, method):
    report = common.render_timed(scene, {"shadow.method": method, "shadow.rays": RAYS,
                                         "material.specular": 0}, 3, 1, 256,
                                 extra=extra, mode="direct").report
    times = common.pass_medians(report)
    return times["render/forward"], report["shadows"]


# LS(6,3) against the BVH in the paper (GTX 1080, 1024x1024, 25 rays per pixel): frame time
# of LS / that of the BVH = BVH fps / LS fps, for the model nearest in size.
PAPER = [(69_000, "Bunny 69k", 95.3 / 69.9), (871_000, "Dragon 871k", 22.4 / 33.6),
         (1_090_000, "Buddha 1.09M", 16.4 / 60.8), (1_960_000, "Buddha+Dragon 1.96M", 12.7 / 26.6)]


def paper_ratio(triangles):
    """The paper's ratio for a model within 1.5x of this size, else none."""
    count = int(triangles.replace(",", ""))
    size, name, ratio = min(PAPER, key=lambda p: abs(p[0] - count))
    return f"x{ratio:.2f} ({name})" if max(size, count) / min(size, count) <= 1.5 else "-"


def speed(names, scenes, rounds, lines):
    lines += ["## Speed: the forward pass at 25 rays per pixel and area light", "",
              f"256x256, direct mode; per scene {rounds} rounds, each method once per round in "
              "turn (median of 3 frames after 1), medians over the rounds; ratios are taken "
              "within each round, then their median.", ""]
    header = "| scene | triangles | " + " | ".join(f"{n} (ms)" for n in names)
    ratio_names = [n for n in names if n != "bvh"] if "bvh" in names else []
    header += "".join(f" | {n} / bvh" for n in ratio_names) + " | paper linespace / bvh |"
    lines += [header, "|" + "---|" * (header.count("|") - 1)]
    builds = []
    for label, path, extra, triangles in scenes:
        per_method = {n: [] for n in names}
        structures = {}
        for _ in range(rounds):
            for name in names:
                ms, shadows = forward_ms(path, extra, name)
                per_method[name].append(ms)
                structures[name] = shadows
        row = f"| {label} | {triangles} | " + " | ".join(
            f"{statistics.median(per_method[n]):.0f}" for n in names)
        for n in ratio_names:
            ratios = [a / b for a, b in zip(per_method[n], per_method["bvh"])]
            row += f" | x{statistics.median(ratios):.2f}"
        lines.append(row + f" | {paper_ratio(triangles)} |")
        builds.append((label, structures))
    lines += ["", "## Structures: build time and memory", "",
              "The last round's build of each method's structure (the --timings report's "
              "`shadows`; shadow maps and the voxel occupancy are drawn every time the scene "
              "changes and have no build of their own here). The paper: LS(6,3) 12-16 MB, built "
              "in 100-131 ms; the BVH 4-77 MB (GTX 1080).", "",
              "| scene | method | structure | build (ms) | memory |", "|---|---|---|---|---|"]
    for label, structures in builds:
        for name, shadows in structures.items():
            build = f"{shadows['build_ms']:.0f}" if shadows["build_ms"] > 0 else ""
            lines.append(f"| {label} | {name} | {shadows['structure']} | {build} | "
                         f"{common.mib(shadows['bytes'])} |")
    lines.append("")


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    common.add_sponza_argument(parser)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    common.use_binary(args.bin)
    names = methods()
    load = open("/proc/loadavg").read().split()[0]
    lines = ["# Shadow methods", "",
             "Made by `/usr/bin/python3 scripts/measure_shadows.py` "
             f"({time.strftime('%Y-%m-%d %H:%M')}, load average {load} at the start). "
             f"Methods in this build: {', '.join(names)}. Timings are llvmpipe's on a shared "
             "2-core machine: compare ratios, not milliseconds. The line space's N x depth "
             "sweep: `docs/results-linespace-sweep.md`.", ""]
    accuracy(names, lines)
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([sys.executable, GENERATOR, tmp], check=True, capture_output=True)
        scenes = [("spheres 70k", os.path.join(tmp, "spheres_70k.gltf"), [], "69,604")]
        if os.path.exists(args.sponza):
            scenes.append(("Sponza, 3 m area light", args.sponza, SPONZA_VIEW, "230,831"))
        scenes += [("spheres 1.1M", os.path.join(tmp, "spheres_1m.gltf"), [], "1,113,604"),
                   ("spheres 1.9M", os.path.join(tmp, "spheres_2m.gltf"), [], "1,948,804")]
        speed(names, scenes, args.rounds, lines)
    lines.append(f"Load average at the end: {open('/proc/loadavg').read().split()[0]}.")
    common.write_page("results-linespace.md", lines)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
