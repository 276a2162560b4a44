#!/usr/bin/env python3
"""Compares vpl.visibility=none|cascade|svo against the path tracer (one bounce) on the scene
suite's Cornell variants, two_rooms_thin_wall (light leaking through a thin wall) and Sponza
under a sun: relative RMSE, energy, the gather pass's time, the time and memory of what the
visibility is built from (the cascade's voxel occupancy, or the octree's fragment list and
levels), the octree's resolution on three scenes, and the light each visibility leaks into
two_rooms_thin_wall's dark room (its camera 1, where the path tracer sees none).

    /usr/bin/python3 scripts/measure_vpl_visibility.py [--size 96] [--bin build/voxatlas]
        [--tables visibility,resolution,leak]

Prints the Markdown tables docs/results-vpl.md quotes and writes the Cornell box's and
Sponza's renders with each visibility to docs/images/vpl/. References come from the disk
cache (reference.spp=1024, as scripts/measure_vpl.py renders them).
"""
import os

import measure_common as mc
from measure_vpl import SPONZA_SUN, SUITE, reference, render, vpl_arguments

VISIBILITIES = ["none", "cascade", "svo"]
FRAMES = 3
PICTURED = ("cornell_classic", "sponza_sun")
# What each visibility builds once per geometry change: its passes and its memory rows.
BUILD_PASSES = {"cascade": ("voxel/",), "svo": ("vpl/svo_",)}
BUILD_MEMORY = {"cascade": ("occupancy/voxel/",), "svo": ("vpl/svo_",)}
OCTREE_NODES = "vpl/svo_nodes"


def scenes(sponza):
    for name in SUITE:
        yield name, os.path.join(mc.ROOT, "assets", "scene_suite", name + ".gltf"), None, ()
    if os.path.exists(sponza):
        yield "sponza_sun", sponza, (128, 72), SPONZA_SUN


def measure(scene, size, extra, truth, mask, settings, out_png=None):
    """Errors, and from the timings of FRAMES frames without warm-up (so the first frame
    holds the build): the gather's median, the build's time and memory, the octree's bytes."""
    frames = {"render.frames": FRAMES, "render.warmup": 0}
    image, report = render(scene, "vpl", size, {**settings, **frames}, extra, out_png)
    rmse, energy = mc.errors(image, truth, mask)
    times = {p["name"]: p["gpu_ms_median"] for p in report["passes"]}
    visibility = settings.get("vpl.visibility", "cascade")
    gather = sum(v for k, v in times.items() if k.startswith("vpl/gather"))
    build = sum(v for k, v in times.items()
                if k.startswith(BUILD_PASSES.get(visibility, ("-",))))
    memory = report["memory_bytes"]
    built = sum(v for k, v in memory.items() if k.startswith(BUILD_MEMORY.get(visibility, ("-",))))
    return rmse, energy, gather, build, built, memory.get(OCTREE_NODES, 0)


def visibility_table(args):
    lines = ["| scene | visibility | relative RMSE | energy | gather ms | build ms | "
             "build memory | octree nodes |", "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for name, scene, size, extra in scenes(args.sponza):
        size = size or args.size
        truth, mask = reference(scene, size, extra)
        for visibility in VISIBILITIES:
            png = (os.path.join(args.images, f"vpl-visibility-{name}-{visibility}.png")
                   if args.images and name in PICTURED else None)
            mc.progress(f"{name} {visibility}")
            rmse, energy, gather, build, built, nodes = measure(
                    scene, size, extra, truth, mask, {"vpl.visibility": visibility}, png)
            lines.append(f"| {name} | {visibility} | {rmse:.3f} | {energy:.3f} | {gather:.1f} | "
                         + (f"{build:.1f} | {mc.mib(built)} | " if built else "- | - | ")
                         + (f"{mc.mib(nodes)} |" if nodes else "- |"))
    return lines


def resolution_table(args, resolutions=(64, 128, 256)):
    lines = ["| scene | vpl.svo_resolution | relative RMSE | energy | gather ms | build ms | "
             "octree nodes |", "| --- | --- | --- | --- | --- | --- | --- |"]
    chosen = ("cornell_classic", "two_rooms_thin_wall", "sponza_sun")
    for name, scene, size, extra in scenes(args.sponza):
        if name not in chosen:
            continue
        size = size or args.size
        truth, mask = reference(scene, size, extra)
        for r in resolutions:
            mc.progress(f"{name} svo {r}")
            rmse, energy, gather, build, _, nodes = measure(
                    scene, size, extra, truth, mask,
                    {"vpl.visibility": "svo", "vpl.svo_resolution": r})
            lines.append(f"| {name} | {r} | {rmse:.3f} | {energy:.3f} | {gather:.1f} | "
                         f"{build:.1f} | {mc.mib(nodes)} |")
    return lines


def leak_table(args):
    """The dark room's mean indirect irradiance over the lit room's (camera 0, the path
    tracer's): what leaks through the wall, one finest voxel of the adaptive plan thick."""
    scene = os.path.join(mc.ROOT, "assets", "scene_suite", "two_rooms_thin_wall.gltf")
    lit, _ = reference(scene, args.size)
    lines = ["| two_rooms_thin_wall, dark room | indirect light / the lit room's |",
             "| --- | --- |"]
    dark, _ = reference(scene, args.size, ("--camera", "1"))
    lines.append(f"| path tracer | {dark.mean() / lit.mean():.5f} |")
    for visibility in VISIBILITIES:
        image, _ = render(scene, "vpl", args.size, {"vpl.visibility": visibility},
                          ("--camera", "1"))
        lines.append(f"| {visibility} | {image.mean() / lit.mean():.5f} |")
    return lines


def main():
    parser = vpl_arguments(__doc__.splitlines()[0])
    parser.add_argument("--tables", default="visibility,resolution,leak",
                        help="which tables, comma-separated")
    args = parser.parse_args()
    mc.use_binary(args.bin)
    if args.images:
        os.makedirs(args.images, exist_ok=True)
    tables = {"visibility": visibility_table, "resolution": resolution_table,
              "leak": leak_table}
    for name in args.tables.split(","):
        print("\n".join(tables[name](args)) + "\n")


if __name__ == "__main__":
    main()
