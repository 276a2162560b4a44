#!/usr/bin/python3
"""The converged atlas with its senders' visibility decided by the voxel occupancy's march
(atlas.visibility=voxel, the scoreboard's) and by rays through the scene's triangles
(atlas.visibility=bvh) on the scene suite: relative RMSE and energy ratio of the indirect term
against the path tracer (one bounce, 4096 spp), 128x128 from camera 0 (the full scoreboard's
size), material.specular=0, the default plan, accumulated to atlas.target_samples (11 frames
of 100); the thin wall's leak as the dark room's mean indirect light over the lit room's; and
the gather pass's time with rays over its time with the march (medians over the frames, the two
renders interleaved scene by scene). What the rays gain is the part of the atlas' error the
march causes.

Usage: /usr/bin/python3 scripts/measure_atlas_visibility.py [--bin build/voxatlas] [--scenes a,b]
Prints a markdown table; about 5 minutes on llvmpipe.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

SUITE = os.path.join(common.ROOT, "assets", "scene_suite")
SCENES = ["cornell_classic", "cornell_double_sided", "cornell_low_light", "cornell_spot",
          "cornell_open_front_sun", "closed_white_box", "two_rooms_thin_wall"]
SIZE = 128
FRAMES = 11
BASE = {"material.specular": 0, "render.plan": "adaptive"}
VISIBILITIES = ("voxel", "bvh")


def atlas(path, visibility, camera):
    rendered = common.render(path, ["--mode", "atlas", "--output", "indirect", "--camera",
                                    str(camera)] + common.size_args(SIZE) + common.settings_args(
        {**BASE, "atlas.visibility": visibility, "render.frames": FRAMES}), hdr=True,
        timings=True)
    return rendered.image, common.pass_medians(rendered.report)["atlas/gather"]


def reference(path, camera):
    image = common.render(path, ["--mode", "reference", "--output", "indirect", "--camera",
                                 str(camera)] + common.size_args(SIZE) + common.settings_args(
        {**BASE, "reference.spp": 4096}), hdr=True).image
    return image, common.reference_mask(image)


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    parser.add_argument("--scenes", default=",".join(SCENES))
    args = parser.parse_args()
    common.use_binary(args.bin)
    print("| scene | march: rel. RMSE / energy | rays: rel. RMSE / energy | gather, rays / march |")
    print("|---|---:|---:|---:|")
    for name in args.scenes.split(","):
        path = os.path.join(SUITE, name + ".gltf")
        ref, mask = reference(path, 0)
        cells, times = [], {}
        means = {}
        for visibility in VISIBILITIES:
            image, times[visibility] = atlas(path, visibility, 0)
            rmse, energy = common.errors(image, ref, mask)
            cells.append(f"{rmse:.3f} / {energy:.3f}")
            means[visibility] = image.mean()
        ratio = times["bvh"] / times["voxel"]
        print(f"| {name} | {cells[0]} | {cells[1]} | x{ratio:.2f} |")
        if name == "two_rooms_thin_wall":
            leaks = [atlas(path, v, 1)[0].mean() / means[v] for v in VISIBILITIES]
            print(f"| two_rooms_thin_wall, dark room: leak | {100 * leaks[0]:.2f} % | "
                  f"{100 * leaks[1]:.2f} % | |")


if __name__ == "__main__":
    main()
