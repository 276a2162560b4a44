#!/usr/bin/python3
"""The diffuse cone sets of voxel GI (voxel.cones, voxel.jitter_elevation, voxel.cone_interleave,
voxel.cone_angle; src/gi/voxel/ConeSet.h) on the scoreboard and in time:

- accuracy: `voxatlas bench --suite full` on the Cornell box, its low light, its spot and its
  open front, voxel GI for each cone configuration at the defaults and at the quality
  preset's other settings (v=64, full-resolution trace, injection at 4v), relative RMSE /
  energy of the indirect term against the path tracer;
- cost: the cone trace pass (median ms over 3 frames) of each configuration at 1280x720,
  inside the Cornell box and in Sponza's sun view, in interleaved rounds, at the program's
  defaults (ratios to the thesis' 9 cones) and at the quality preset's settings (ratios to 19
  cones), the ratios taken within each round and their median quoted;
- maps: docs/images/cones_quality_error_maps.png, the quality preset's settings with 19 cones
  and with its 37 moved in elevation, against the path tracer on two Cornell boxes; and
  docs/images/cones_elevation_default_pair.png, the spot box at the defaults without and with
  voxel.jitter_elevation.

Usage: /usr/bin/python3 scripts/measure_cones.py [--bin build/voxatlas] [--sponza PATH]
       [--rounds 3] [--parts accuracy,cost,maps] [--columns defaults,quality]
Prints markdown tables (docs/accuracy-analysis.md, "Nineteen cones" and "Thirty-seven cones
moved in elevation"); about 40 minutes.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import interleaved  # noqa: E402
import measure_common as common  # noqa: E402

SCENES = ["cornell_classic", "cornell_low_light", "cornell_spot", "cornell_open_front_sun"]
# Each names its cone settings in full: the quality preset brings its own.
CONFIGURATIONS = {
    "9 cones, 45 degrees (the thesis')": {"voxel.cones": 9},
    "19 cones at 45 degrees": {"voxel.cones": 19, "voxel.cone_angle": 45},
    "19 cones, 37.3 degrees (default)": {"voxel.cones": 19},
    "19 cones, 10 at each pixel (voxel.cone_interleave=1)":
        {"voxel.cones": 19, "voxel.cone_interleave": 1},
    "19 cones moved in elevation (voxel.jitter_elevation=1)":
        {"voxel.cones": 19, "voxel.jitter_elevation": 1},
    "37 cones, 26.6 degrees": {"voxel.cones": 37},
    "37 cones moved in elevation (the quality preset's)":
        {"voxel.cones": 37, "voxel.jitter_elevation": 1},
}
# The quality preset's settings besides its cones (src/bench/BenchSweep.cpp).
QUALITY = {"voxel.resolution": 64, "voxel.trace_scale": 1, "voxel.inject_resolution": 256}
# The quality preset's settings are slow on a software rasterizer: the sets that matter.
QUALITY_ACCURACY = ["19 cones, 37.3 degrees (default)",
                    "19 cones moved in elevation (voxel.jitter_elevation=1)",
                    "37 cones, 26.6 degrees",
                    "37 cones moved in elevation (the quality preset's)"]
COST_CONFIGURATIONS = {
    "the defaults": ["9 cones, 45 degrees (the thesis')", "19 cones, 37.3 degrees (default)",
                 "19 cones moved in elevation (voxel.jitter_elevation=1)",
                 "37 cones, 26.6 degrees",
                 "37 cones moved in elevation (the quality preset's)"],
    "the quality preset's settings": ["19 cones, 37.3 degrees (default)",
                "37 cones moved in elevation (the quality preset's)"],
}
SPONZA_SUN = ["--camera", "-1.2,1.7,-8,0.8,3.5,10,60", "--light", "none",
              "--light", "dir:0.2,-1,0.3:1,1,1:4"]


def suite_scores(settings):
    """scene -> (relative RMSE, energy) of voxel GI under `settings` from the full suite (its
    "voxel" configuration: the base settings, which `settings` replace)."""
    with tempfile.TemporaryDirectory() as out:
        cmd = [common.BIN, "bench", "--suite", "full", "--scene", ",".join(SCENES),
               "--out-dir", out] + common.settings_args(settings)
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(out, "accuracy.csv")) as f:
            return {row["scene"]: (float(row["rel_rmse_indirect"]),
                                   float(row["energy_indirect"]))
                    for row in csv.DictReader(f) if row["configuration"] == "voxel"}


def accuracy(columns):
    for key, column, base, names in (
            ("defaults", "the defaults", {}, list(CONFIGURATIONS)),
            ("quality", "the quality preset's settings", QUALITY, QUALITY_ACCURACY)):
        if key not in columns:
            continue
        scores = {}
        for name in names:
            settings = CONFIGURATIONS[name]
            common.progress(f"suite, {column}: {name}")
            scores[name] = suite_scores({**base, **settings})
        print(f"\nvoxel GI, {column} (relative RMSE / energy)\n")
        print("| cones | " + " | ".join(SCENES) + " |")
        print("|---|" + "---|" * len(SCENES))
        for name in names:
            cells = [f"{scores[name][s][0]:.3f} / {scores[name][s][1]:.3f}" for s in SCENES]
            print(f"| {name} | " + " | ".join(cells) + " |")


def trace_ms(scene, camera_args, settings):
    report = common.render_timed(scene, {"render.plan": "adaptive", **settings}, 3, 1,
                                 (interleaved.WIDTH, interleaved.HEIGHT), camera_args,
                                 mode="voxel").report
    return common.pass_medians(report)


def cost(sponza, rounds):
    views = {"Cornell box, inside": (common.CORNELL, ["--camera", interleaved.INSIDE_CAMERA])}
    if os.path.exists(sponza):
        views["Sponza, sun view"] = (sponza, SPONZA_SUN)
    else:
        print(f"(Sponza not found at {sponza}: its row is left out; pass --sponza PATH or set "
              "VOXATLAS_SPONZA)")
    start = interleaved.load_average()
    for column, base in (("the defaults", {}), ("the quality preset's settings", QUALITY)):
        names = COST_CONFIGURATIONS[column]
        reference = names[0]
        print(f"\ncone trace pass at 1280x720, {column}: median ms, and the median of the "
              f"rounds' ratios to {reference} ({rounds} interleaved rounds)\n")
        print("| view | " + " | ".join(names) + " |")
        print("|---|" + "---|" * len(names))
        for view, (scene, camera_args) in views.items():
            configs = {name: (lambda s={**base, **CONFIGURATIONS[name]}:
                              trace_ms(scene, camera_args, s)) for name in names}
            results = interleaved.run_rounds(configs, rounds)
            cells = []
            for name in names:
                ms = interleaved.median(results, name, "voxel/trace")
                ratio, values = interleaved.ratio_median(results, name, reference, "voxel/trace")
                cells.append(f"{ms:.1f} ms, x{ratio:.2f} ({interleaved.spread(values)})")
            print(f"| {view} | " + " | ".join(cells) + " |")
    print(f"\nload average {start} at the start, {interleaved.load_average()} at the end")


MAP_SCENES = ["cornell_classic", "cornell_spot"]
MAP_CONFIGURATIONS = ["19 cones, 37.3 degrees (default)",
                      "37 cones moved in elevation (the quality preset's)"]
MAP_SIZE = 128


def maps():
    """docs/images/cones_quality_error_maps.png: per scene, the path tracer's indirect light,
    voxel GI at the quality preset's settings with 19 cones and with the preset's 37 moved in
    elevation, and the log2 ratio of each to the path tracer."""
    plt = common.pyplot()
    suite = os.path.join(common.ROOT, "assets", "scene_suite")
    base = {"render.plan": "adaptive", "material.specular": 0}
    fig, axes = plt.subplots(len(MAP_SCENES), 5, figsize=(15, 3.6 * len(MAP_SCENES)))
    for row, scene in enumerate(MAP_SCENES):
        path = os.path.join(suite, scene + ".gltf")
        common.progress(f"maps: {scene}")
        reference = common.render_indirect(path, "reference", {**base, "reference.spp": 1024},
                                           MAP_SIZE).image
        scale = max(float(numpy.percentile(reference, 99)), 1e-9)
        images = [("path tracer", reference, None)]
        for name in MAP_CONFIGURATIONS:
            image = common.render_indirect(path, "voxel",
                                           {**base, **QUALITY, **CONFIGURATIONS[name]},
                                           MAP_SIZE).image
            rmse, energy = common.errors(image, reference)
            images.append((f"{name.split(' (')[0]}\nrel. RMSE {rmse:.3f}, energy {energy:.3f}",
                           image, None))
        for col, (title, image, _) in enumerate(images):
            axes[row][col].imshow(numpy.clip(image / scale, 0.0, 1.0) ** (1.0 / 2.2))
            axes[row][col].set_title((scene + "\n" if col == 0 else "") + title, fontsize=9)
        luminance = reference.mean(axis=-1)
        for k, (title, image, _) in enumerate(images[1:]):
            ratio = numpy.log2((image.mean(axis=-1) + 1e-4 * scale) /
                               (luminance + 1e-4 * scale))
            shown = axes[row][3 + k].imshow(ratio, cmap="coolwarm", vmin=-1.0, vmax=1.0)
            axes[row][3 + k].set_title("log2 ratio to the path tracer:\n" +
                                       title.split("\n")[0], fontsize=9)
        fig.colorbar(shown, ax=axes[row][4], fraction=0.046)
        for axis in axes[row]:
            axis.axis("off")
    fig.suptitle("Voxel GI at the quality preset's settings, indirect light: 19 cones against "
                 "37 moved in elevation (blue: too dark, red: too bright)", fontsize=10)
    fig.tight_layout()
    out = os.path.join(common.IMAGES, "cones_quality_error_maps.png")
    fig.savefig(out, dpi=80)
    print(f"\nwrote {os.path.relpath(out, common.ROOT)}")
    default_pair(suite)


def default_pair(suite):
    """docs/images/cones_elevation_default_pair.png: the spot box at the defaults (the
    half-resolution trace) without and with voxel.jitter_elevation, side by side."""
    plt = common.pyplot()
    scene = os.path.join(suite, "cornell_spot.gltf")
    halves = []
    with tempfile.TemporaryDirectory() as tmp:
        for jitter in (0, 1):
            png = os.path.join(tmp, f"{jitter}.png")
            common.render(scene, ["--mode", "voxel", "--width", "320", "--height", "320",
                                  "--exposure", "auto", "--set", "render.plan=adaptive",
                                  "--set", f"voxel.jitter_elevation={jitter}"], png)
            halves.append(plt.imread(png)[..., :3])
    out = os.path.join(common.IMAGES, "cones_elevation_default_pair.png")
    plt.imsave(out, numpy.concatenate(halves, axis=1))
    print(f"wrote {os.path.relpath(out, common.ROOT)}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    common.add_bin_argument(parser)
    common.add_sponza_argument(parser)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--parts", default="accuracy,cost,maps")
    parser.add_argument("--columns", default="defaults,quality",
                        help="accuracy at the defaults, the quality preset's settings or both")
    args = parser.parse_args()
    common.use_binary(args.bin)
    parts = args.parts.split(",")
    if "accuracy" in parts:
        accuracy(args.columns.split(","))
    if "cost" in parts:
        cost(args.sponza, args.rounds)
    if "maps" in parts:
        maps()


if __name__ == "__main__":
    main()
