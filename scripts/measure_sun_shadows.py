#!/usr/bin/python3
"""The direct sunlight in Sponza against the path tracer's, per shadow-map resolution: how much
light a sun's map lets past occluders when its texels, spread over the whole scene, are wide.
The suite's sponza_sun view (assets/scene_suite/README.md) at 192x108, direct light only,
render.supersample=2 (so the raster's pixels average their area as the path tracer's do and
the score is the shadows', not the edges' aliasing), material.specular=0; the path tracer's
direct term at reference.spp=1024 (cached on disk). Each row also gives the shadow pass' time
(one frame, llvmpipe: the map is drawn once while nothing moves) and the map's memory.

Usage: /usr/bin/python3 scripts/measure_sun_shadows.py [--bin build/voxatlas] [--sponza PATH]
       [--picture docs/images/sponza_sun_shadows.png]
Prints a markdown table and writes the picture: the path tracer, the 1024 map, the default
map, then the signed error of each map (red: brighter than the path tracer, blue: darker,
full strength at the path tracer's mean). A second table scores the final image (direct +
indirect) of direct mode and of voxel GI against the path tracer's at 1, 2x2 and 4x4 samples
per pixel: how much of the suite's final-image error (one sample per pixel) is the raster's
pixel centres against the path tracer's pixel areas, and how much GI could still remove. A
third scores VPL GI's indirect light at reflective shadow maps of 112 to 144 pixels a side:
which VPLs the sun's map yields moves with its pixels, and with it the score of one render.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

SIZE = (192, 108)
VIEW = ["--camera", "-1.2,1.7,-8,0.8,3.5,10,60", "--light", "none", "--light",
        "dir:0.2,-1,0.3:1,1,1:4"]
BASE = {"material.specular": 0, "render.plan": "adaptive"}
CONFIGS = [("shadow.sun_resolution=1024", {"shadow.sun_resolution": 1024}),
           ("shadow.sun_resolution=2048", {"shadow.sun_resolution": 2048}),
           ("shadow.sun_resolution=4096 (default)", {}),
           ("shadow.sun_resolution=8192", {"shadow.sun_resolution": 8192}),
           ("shadow.method=bvh (rays, for scale)", {"shadow.method": "bvh"})]
PICTURED = [0, 2]


def direct(sponza, mode, settings, timings=False, output="direct"):
    options = ["--mode", mode, "--output", output] + common.size_args(SIZE) + \
        common.settings_args({**BASE, **settings}) + VIEW
    return common.render(sponza, options, hdr=True, timings=timings)


def final_table(sponza):
    ref = direct(sponza, "reference", {"reference.spp": 1024}, output="final").image[..., :3]
    mask = common.reference_mask(direct(sponza, "reference", {"reference.spp": 1024},
                                        output="indirect").image)
    print("\n| samples per pixel | direct mode: final rel. RMSE | voxel GI: final rel. RMSE "
          "| voxel / direct |")
    print("|---|---:|---:|---:|")
    for n in (1, 2, 4):
        errors = []
        for mode in ("direct", "voxel"):
            image = direct(sponza, mode, {"render.supersample": n}, output="final").image
            errors.append(common.errors(image[..., :3], ref, mask)[0])
        print(f"| {n}x{n} | {errors[0]:.3f} | {errors[1]:.3f} | x{errors[1] / errors[0]:.2f} |")


def signed_error(image, ref, scale):
    import numpy
    luminance = numpy.array([0.2126, 0.7152, 0.0722])
    d = ((image - ref) @ luminance) * scale
    return numpy.stack([numpy.clip(d, 0, 1), numpy.zeros_like(d), numpy.clip(-d, 0, 1)], -1)


def vpl_spread(sponza):
    ref = direct(sponza, "reference", {"reference.spp": 1024}, output="indirect").image[..., :3]
    mask = common.reference_mask(ref)
    print("\n| VPL GI, vpl.rsm_resolution | indirect rel. RMSE | indirect energy |")
    print("|---|---:|---:|")
    for pixels in (112, 120, 128, 136, 144):
        image = direct(sponza, "vpl", {"vpl.rsm_resolution": pixels}, output="indirect").image
        rmse, energy = common.errors(image[..., :3], ref, mask)
        default = " (default)" if pixels == 128 else ""
        print(f"| {pixels}{default} | {rmse:.3f} | {energy:.3f} |")


def main():
    args = common.sponza_picture_arguments(__doc__, "sponza_sun_shadows.png")
    import numpy
    ref = direct(args.sponza, "reference", {"reference.spp": 1024}).image[..., :3]
    mask = common.reference_mask(ref)
    mean = float(ref[mask].mean())
    print("| shadows | relative RMSE | energy | shadow pass (ms) | shadow maps (MiB) |")
    print("|---|---:|---:|---:|---:|")
    pictured = []
    for i, (name, settings) in enumerate(CONFIGS):
        run = direct(args.sponza, "direct", {"render.supersample": 2, **settings}, timings=True)
        image = run.image[..., :3]
        rmse, energy = common.errors(image, ref, mask)
        passes = common.pass_medians(run.report)
        shadow_ms = passes.get("render/shadow", 0.0)
        memory = run.report.get("memory_bytes", {})
        maps = sum(v for k, v in memory.items() if k.startswith("render/shadow/maps"))
        print(f"| {name} | {rmse:.3f} | {energy:.3f} | {shadow_ms:.0f} | "
              f"{maps / 2**20:.0f} |")
        if i in PICTURED:
            pictured.append(image)
    exposure = 0.2 / max(mean, 1e-12)
    tiles = [ref * exposure] + [im * exposure for im in pictured]
    tiles = [numpy.clip(t, 0, 1) ** (1.0 / 2.2) for t in tiles]
    tiles += [signed_error(im, ref, 1.0 / max(mean, 1e-12)) for im in pictured]
    common.write_png(args.picture, numpy.concatenate(tiles, axis=1), scale=2)
    print(f"\nwrote {args.picture}")
    final_table(args.sponza)
    vpl_spread(args.sponza)


if __name__ == "__main__":
    main()
