#!/usr/bin/python3
"""Further bounces of indirect light (gi.bounces) against the path tracer, for voxel and atlas
GI on the Cornell variants of the scene suite and the classic Cornell box: relative RMSE and
energy ratio (src/reference/ImageMetrics.h) of the indirect term, 96x96 from camera 0,
material.specular=0, the default (adaptive) plan. gi.bounces=B is scored against
`--mode reference --set reference.bounces=R` with R = B, and the two-bounce figures also
against the all-bounce path tracer (R = 16; reference.spp=1024, cached on disk). The atlas
renders `--set render.frames=N` frames so its progressive sums reach atlas.target_samples.

Usage: /usr/bin/python3 scripts/measure_bounces.py [--bin build/voxatlas] [--scenes a,b]
       [--bounces 1,2] [--modes voxel,atlas] [--atlas-frames 11] [--set KEY=VALUE ...] [--page]
Prints one table row per scene, technique and bounce count; --page writes
docs/results-bounces.md's table (the page's text outside the markers is kept) and, for the
scenes in STRIPS, docs/images/bounces_<scene>.png: the path tracer with 1, 2 and all
bounces, then each technique with 1 and 2.
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

SUITE = os.path.join(common.ROOT, "assets", "scene_suite")
SCENES = ["cornell_classic", "cornell_double_sided", "cornell_low_light", "cornell_open_front_sun",
          "cornell_spot", "cornell_x10", "closed_white_box", "two_rooms_thin_wall"]
ALL_BOUNCES = 16
SIZE = 96
BASE = {"material.specular": 0, "render.plan": "adaptive"}
PAGE = "results-bounces.md"
BEGIN, END = "<!-- table begin -->", "<!-- table end -->"
STRIPS = ["cornell_classic", "closed_white_box"]


def scene_path(name):
    if name == "cornell_box":
        return common.CORNELL
    return os.path.join(SUITE, name + ".gltf")


def reference(path, bounces, png=None):
    settings = {**BASE, "reference.spp": 1024, "reference.bounces": bounces}
    image = common.render_indirect(path, "reference", settings, SIZE, out_png=png).image
    return image, common.reference_mask(image)


def technique(path, mode, bounces, atlas_frames, extra, png=None):
    settings = {**BASE, **extra, "gi.bounces": bounces}
    if mode == "atlas":
        settings["render.frames"] = atlas_frames
    return common.render_indirect(path, mode, settings, SIZE, out_png=png).image


def fmt(x):
    return f"{x:.3f}"


def write_strip(name, pngs):
    """The PNGs side by side, 2x enlarged, as docs/images/bounces_<name>.png."""
    from PIL import Image
    images = [Image.open(p) for p in pngs]
    w, h = images[0].size
    strip = Image.new("RGB", (w * len(images), h))
    for i, image in enumerate(images):
        strip.paste(image, (i * w, 0))
    strip = strip.resize((2 * w * len(images), 2 * h), Image.NEAREST)
    strip.save(os.path.join(common.IMAGES, f"bounces_{name}.png"))


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    parser.add_argument("--scenes", default=",".join(SCENES + ["cornell_box"]))
    parser.add_argument("--bounces", default="1,2")
    parser.add_argument("--modes", default="voxel,atlas")
    parser.add_argument("--atlas-frames", type=int, default=11)
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a further setting for the techniques (not the path tracer)")
    parser.add_argument("--page", action="store_true", help=f"write docs/{PAGE}'s table")
    args = parser.parse_args()
    if any("=" not in item for item in args.set):
        parser.error("--set takes KEY=VALUE")
    extra = dict(item.split("=", 1) for item in args.set)
    common.use_binary(args.bin)
    bounce_counts = [int(b) for b in args.bounces.split(",")]
    modes = args.modes.split(",")
    images = tempfile.mkdtemp()

    header = ("| scene | technique | gi.bounces | rel. RMSE vs same bounces | energy vs same "
              "bounces | rel. RMSE vs all bounces | energy vs all bounces |")
    rows = [header, "|---|---|---:|---:|---:|---:|---:|"]
    print(header, flush=True)
    for name in args.scenes.split(","):
        path = scene_path(name)
        pngs = [os.path.join(images, f"{name}_reference_{b}.png")
                for b in bounce_counts + [ALL_BOUNCES]]
        all_bounce = reference(path, ALL_BOUNCES, pngs[-1])
        for mode in modes:
            for i, bounces in enumerate(bounce_counts):
                same = reference(path, bounces, pngs[i])
                png = os.path.join(images, f"{name}_{mode}_{bounces}.png")
                pngs.append(png)
                image = technique(path, mode, bounces, args.atlas_frames, extra, png)
                rmse, energy = common.errors(image, same[0], same[1])
                rmse_all, energy_all = common.errors(image, all_bounce[0], all_bounce[1])
                row = (f"| {name} | {mode} | {bounces} | {fmt(rmse)} | {fmt(energy)} | "
                       f"{fmt(rmse_all)} | {fmt(energy_all)} |")
                rows.append(row)
                print(row, flush=True)
        if args.page and name in STRIPS:
            write_strip(name, pngs)
    if args.page:
        page = os.path.join(common.DOCS, PAGE)
        text = open(page).read() if os.path.exists(page) else f"{BEGIN}\n{END}\n"
        head, rest = text.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        open(page, "w").write(head + BEGIN + "\n" + "\n".join(rows) + "\n" + END + tail)


if __name__ == "__main__":
    main()
