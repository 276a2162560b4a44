#!/usr/bin/python3
"""Voxel cone tracing's indirect light against the path tracer on the scene suite, per
resource plan: relative RMSE and energy ratio (src/reference/ImageMetrics.h) of the 1-bounce
indirect term, 96x96 from camera 0, material.specular=0, and the thin-wall leak (mean
indirect light in the dark room, camera 1, over that of the lit room, camera 0).

Usage: /usr/bin/python3 scripts/measure_voxel_accuracy.py [--bin build/voxatlas]
       [--plans fixed,adaptive] [--scenes a,b] [--set key=value ...] [--images DIR]
Prints one table row per scene and plan; --set applies to the voxel renders only.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

SUITE = os.path.join(common.ROOT, "assets", "scene_suite")
CORNELLS = ["cornell_classic", "cornell_double_sided", "cornell_low_light", "cornell_x10",
            "cornell_spot", "cornell_open_front_sun"]
SPONZA_SUN = ["--camera", "-1.2,1.7,-8,0.8,3.5,10,60", "--light", "none",
              "--light", "dir:0.2,-1,0.3:1,1,1:4"]
SIZE = 96
BASE = {"material.specular": 0}


def scene_list(sponza):
    scenes = [(name, os.path.join(SUITE, name + ".gltf"), []) for name in CORNELLS]
    scenes.append(("closed_white_box", os.path.join(SUITE, "closed_white_box.gltf"), []))
    if os.path.exists(sponza):
        scenes.append(("sponza_sun", sponza, SPONZA_SUN))
    return scenes


def reference(path, extra):
    image = common.render_indirect(path, "reference", {**BASE, "reference.spp": 1024}, SIZE,
                                   extra=extra).image
    return image, common.reference_mask(image)


def voxel(path, extra, plan, settings, png=None):
    return common.render_indirect(path, "voxel", {**BASE, "render.plan": plan, **settings},
                                  SIZE, out_png=png, extra=extra).image


def leak(plan, settings, images):
    """Mean indirect light the dark room's camera sees over the lit room camera's."""
    path = os.path.join(SUITE, "two_rooms_thin_wall.gltf")
    means = []
    for camera in (0, 1):
        png = os.path.join(images, f"two_rooms_{camera}_{plan}.png") if images else None
        means.append(voxel(path, ["--camera", str(camera)], plan, settings, png).mean())
    return means[1] / means[0] if means[0] > 0 else float("nan")


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    common.add_sponza_argument(parser)
    parser.add_argument("--plans", default="fixed,adaptive")
    parser.add_argument("--scenes", default="", help="comma-separated subset (names as printed)")
    parser.add_argument("--set", action="append", default=[], help="key=value for voxel mode")
    parser.add_argument("--images", default="", help="folder for the voxel PNGs")
    args = parser.parse_args()
    common.use_binary(args.bin)
    settings = dict(s.split("=", 1) for s in args.set)
    wanted = set(filter(None, args.scenes.split(",")))
    if args.images:
        os.makedirs(args.images, exist_ok=True)
    rows = []
    for name, path, extra in scene_list(args.sponza):
        if wanted and name not in wanted:
            continue
        ref, mask = reference(path, extra)
        for plan in args.plans.split(","):
            png = os.path.join(args.images, f"{name}_{plan}.png") if args.images else None
            rmse, energy = common.errors(voxel(path, extra, plan, settings, png), ref, mask)
            rows.append(f"| {name} | {plan} | {rmse:.3f} | {energy:.3f} |")
    if not wanted or "two_rooms" in wanted:
        for plan in args.plans.split(","):
            rows.append(f"| two_rooms leak (dark/lit) | {plan} | {leak(plan, settings, args.images):.3f} | |")
    print("| scene | plan | relative RMSE | energy |")
    print("|---|---|---|---|")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
