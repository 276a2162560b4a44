#!/usr/bin/python3
"""Voxel GI's indirect energy in Sponza under a sun at three elevations, against the path
tracer, for the light injection and voxel sizes that decide it: the defaults (one level of
128^3 voxels of 0.32 m voxelized at four samples a raster pixel, four light pixels per finest
voxel), voxelization at one sample a pixel (voxel.msaa=1), injection at two light pixels
per voxel (233), the diffuse cones reading the surface they meet (voxel.light_read=surface)
and one level of 256^3 voxels of 0.16 m (voxel.resolution=64, voxel.one_level_limit=256: the
quality preset's level). The camera is the suite's sponza_sun view (assets/scene_suite/README.md); the
indirect term at 160x90, reference.spp=512 (cached on disk), material.specular=0.

Usage: /usr/bin/python3 scripts/measure_sponza_sun.py [--bin build/voxatlas] [--sponza PATH]
       [--picture docs/images/sponza_sun_voxel_size.png] [--light-read]
Prints a markdown table (energy and relative RMSE of every configuration at every
elevation) and writes the picture: one row per sun, left to right the path tracer, the
defaults, the surface read and 256^3, each row at the exposure that shows the path tracer's
mean at 0.2. With --light-read the configurations are the default, anisotropic voxels and anisotropic
voxels read as the surface met faces (voxel.light_read=surface), all three pictured
(docs/images/sponza_sun_light_read.png).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

CAMERA = "-1.2,1.7,-8,0.8,3.5,10,60"
SIZE = (160, 90)
SUNS = [("0.2,-1,0.3", "the suite's sun (elevation 70 degrees)"),
        ("0.1,-1,0.1", "elevation 82 degrees"),
        ("0,-1,0", "straight down")]
BASE = {"render.plan": "adaptive", "material.specular": 0}
CONFIGS = [("defaults (128^3 of 0.32 m, four light pixels per voxel)", {}),
           ("one voxelization sample a pixel (voxel.msaa=1)", {"voxel.msaa": 1}),
           ("two light pixels per voxel", {"voxel.inject_resolution": 233}),
           ("voxel.light_read=surface", {"voxel.light_read": "surface"}),
           ("voxel.resolution=64 voxel.one_level_limit=256 (256^3 of 0.16 m)",
            {"voxel.resolution": 64, "voxel.one_level_limit": 256})]
PICTURED = [0, 3, 4]
# --light-read: the anisotropic voxels' two light reads (voxel.light_read) beside the default.
LIGHT_READ_CONFIGS = [("default (isotropic voxels)", {}),
                      ("voxel.anisotropic=1 (light read as the cone sees the faces)",
                       {"voxel.anisotropic": 1}),
                      ("voxel.anisotropic=1 voxel.light_read=surface",
                       {"voxel.anisotropic": 1, "voxel.light_read": "surface"})]
LIGHT_READ_PICTURE = "sponza_sun_light_read.png"


def indirect(sponza, mode, sun, settings):
    extra = ["--camera", CAMERA, "--light", "none", "--light", f"dir:{sun}:1,1,1:4"]
    return common.render_indirect(sponza, mode, {**BASE, **settings}, SIZE, extra=extra).image


def main():
    args = common.sponza_picture_arguments(__doc__, "sponza_sun_voxel_size.png", [
        ("--light-read", "compare the light reads of anisotropic voxels (voxel.light_read) "
         f"instead of the voxel sizes; the picture defaults to docs/images/{LIGHT_READ_PICTURE}")])
    configs, pictured = CONFIGS, PICTURED
    if args.light_read:
        configs, pictured = LIGHT_READ_CONFIGS, [0, 1, 2]
        if os.path.basename(args.picture) == "sponza_sun_voxel_size.png":
            args.picture = os.path.join(os.path.dirname(args.picture), LIGHT_READ_PICTURE)
    import numpy
    header = "| configuration | " + " | ".join(f"sun {d} ({why})" for d, why in SUNS) + " |"
    rows = {name: [] for name, _ in configs}
    strips = []
    for sun, _ in SUNS:
        ref = indirect(args.sponza, "reference", sun, {"reference.spp": 512})
        mask = common.reference_mask(ref)
        exposure = 0.2 / max(float(ref[mask].mean()), 1e-12)
        strip = [ref]
        for i, (name, settings) in enumerate(configs):
            image = indirect(args.sponza, "voxel", sun, settings)
            rmse, energy = common.errors(image, ref, mask)
            rows[name].append(f"{energy:.3f} / {rmse:.3f}")
            if i in pictured:
                strip.append(image)
        strips.append(numpy.concatenate([im * exposure for im in strip], axis=1))
    print("energy / relative RMSE of the indirect term against the path tracer\n")
    print(header)
    print("|---" * (len(SUNS) + 1) + "|")
    for name, _ in configs:
        print(f"| {name} | " + " | ".join(rows[name]) + " |")
    rgb = numpy.concatenate(strips, axis=0) ** (1.0 / 2.2)
    common.write_png(args.picture, rgb, scale=2)
    print(f"\nwrote {args.picture}")


if __name__ == "__main__":
    main()
