#!/usr/bin/python3
"""The atlas gather's near field (atlas.near_rays, atlas.near_reach; docs/accuracy-analysis.md,
"The atlas gather's near field"), measured at the full scoreboard's 128x128 from camera 0
against the path tracer at 4096 spp (one bounce, indirect term, material.specular=0, the
default plan), the converged atlas at 1024 samples with voxel visibility:

- on the open-front box, how far the near field reaches (atlas.near_reach, in texel edges) and
  how many rays a set it casts (atlas.near_rays), beside the atlas without it;
- on every scene of the suite, the atlas without the near field, with its default rays and
  with twice as many.

Usage: /usr/bin/python3 scripts/measure_near_field.py [--bin build/voxatlas] [--parts reach,suite]
Prints markdown tables; about 10 minutes on llvmpipe (the references come from the cache when
the scoreboard or measure_misses.py made them).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

SUITE = os.path.join(common.ROOT, "assets", "scene_suite")
OPEN_FRONT = "cornell_open_front_sun"
SCENES = ["closed_white_box", "cornell_classic", "cornell_double_sided", "cornell_glossy",
          "cornell_low_light", "cornell_spot", "cornell_x10", OPEN_FRONT, "two_rooms_thin_wall"]
SIZE = 128
BASE = {"material.specular": 0, "render.plan": "adaptive"}
CONVERGED = {"atlas.visibility": "voxel", "atlas.target_samples": 1024, "render.frames": 11}
DEFAULT_RAYS = 4
REACHES = [2, 4, 6, 8, 12]
RAYS = [2, 4, 8, 32]


def scene_path(name):
    return os.path.join(SUITE, name + ".gltf")


def reference(name):
    common.progress(f"{name}: path tracer, 4096 spp")
    image = common.render_indirect(scene_path(name), "reference",
                                   {**BASE, "reference.spp": 4096}, SIZE).image
    return image, common.reference_mask(image)


def atlas_score(name, truth, settings):
    image = common.render_indirect(scene_path(name), "atlas",
                                   {**BASE, **CONVERGED, **settings}, SIZE).image
    rmse, energy = common.errors(image, truth[0], truth[1])
    return f"{rmse:.3f} / {energy:.3f}"


def reach_tables():
    truth = reference(OPEN_FRONT)
    print("Open-front box, converged atlas (relative RMSE / energy):\n")
    print("| near field | relative RMSE / energy |")
    print("|---|---:|")
    print(f"| none (`atlas.near_rays=0`) | {atlas_score(OPEN_FRONT, truth, {'atlas.near_rays': 0})} |")
    for reach in REACHES:
        score = atlas_score(OPEN_FRONT, truth, {"atlas.near_reach": reach})
        print(f"| within {reach} texel edges, {DEFAULT_RAYS} rays a set | {score} |")
    for rays in RAYS:
        if rays == DEFAULT_RAYS:
            continue
        score = atlas_score(OPEN_FRONT, truth, {"atlas.near_rays": rays})
        print(f"| within 6 texel edges, {rays} rays a set | {score} |")
    print()


def suite_table():
    print("Every scene of the suite, converged atlas (relative RMSE / energy):\n")
    print(f"| scene | without (`atlas.near_rays=0`) | {DEFAULT_RAYS} rays a set (default) "
          f"| {2 * DEFAULT_RAYS} rays a set |")
    print("|---|---:|---:|---:|")
    for name in SCENES:
        truth = reference(name)
        scores = [atlas_score(name, truth, {"atlas.near_rays": rays})
                  for rays in (0, DEFAULT_RAYS, 2 * DEFAULT_RAYS)]
        print(f"| {name} | " + " | ".join(scores) + " |", flush=True)
    print()


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    parser.add_argument("--parts", default="reach,suite", help="which tables (comma-separated)")
    args = parser.parse_args()
    common.use_binary(args.bin)
    parts = args.parts.split(",")
    if "reach" in parts:
        reach_tables()
    if "suite" in parts:
        suite_table()


if __name__ == "__main__":
    main()
