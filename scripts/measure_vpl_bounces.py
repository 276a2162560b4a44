#!/usr/bin/env python3
"""Scores --mode vpl with vpl.bounces=1 and 2 against the path tracer at the same number of
bounces (reference.bounces, as scripts/measure_bounces.py scores gi.bounces) on the Cornell
variants of the scene suite and the closed white box: relative RMSE and energy ratio of the
indirect term, the gather's time, and the second bounce's share of the light (the energy of
vpl.bounces=2 over vpl.bounces=1, against the path tracer's same ratio).

    /usr/bin/python3 scripts/measure_vpl_bounces.py [--size 96] [--bin build/voxatlas]
        [--scenes a,b] [--counts 1024] [--images DIR]

Prints the Markdown table docs/results-vpl.md quotes; with --counts 1024,2048 one row per
vpl.count (vpl.bounces=2 at 2048 draws the default 1024 first-generation VPLs and as many
bounce rays). Writes, per scene, DIR/bounces-<scene>.png: the path tracer with 1 and 2
bounces, then vpl.bounces=1 and 2 (exposure auto, filmic). References at reference.spp=1024
are rendered once and cached on disk; the default plan is used throughout.
"""
import argparse
import os
import tempfile

import measure_common as mc
import measure_vpl as mv

SCENES = ["cornell_classic", "cornell_double_sided", "cornell_low_light",
          "cornell_open_front_sun", "cornell_spot", "cornell_x10", "closed_white_box"]


def reference(scene, size, bounces, png):
    image, _ = mv.render(scene, "reference", size,
                         {"reference.spp": 1024, "reference.bounces": bounces}, out_png=png)
    return image, mc.reference_mask(image)


def gather_ms(report):
    return sum(v for k, v in mc.pass_medians(report).items()
               if k.startswith("vpl/gather") or k == "vpl/filter")


def write_strip(path, pngs):
    """The PNGs side by side, 2x enlarged."""
    from PIL import Image
    images = [Image.open(p).convert("RGB") for p in pngs]
    w, h = images[0].size
    strip = Image.new("RGB", (w * len(images), h))
    for i, image in enumerate(images):
        strip.paste(image, (i * w, 0))
    strip.resize((2 * w * len(images), 2 * h), Image.NEAREST).save(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mc.add_bin_argument(parser)
    parser.add_argument("--size", type=int, default=96)
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--counts", default="1024")
    parser.add_argument("--frames", type=int, default=3, help="frames timed per render")
    parser.add_argument("--images", default=os.path.join(mc.IMAGES, "vpl"),
                        help="where the strips are written ('' = nowhere)")
    args = parser.parse_args()
    mc.use_binary(args.bin)
    if args.images:
        os.makedirs(args.images, exist_ok=True)
    tmp = tempfile.mkdtemp()

    lines = ["| scene | vpl.count | vpl.bounces | relative RMSE vs same bounces | energy vs same "
             "bounces | 2 bounces / 1 (path tracer) | gather + filter ms |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    print("\n".join(lines), flush=True)
    for name in args.scenes.split(","):
        scene = os.path.join(mc.ROOT, "assets", "scene_suite", name + ".gltf")
        pngs = [os.path.join(tmp, f"{name}-reference-{b}.png") for b in (1, 2)]
        truths = {b: reference(scene, args.size, b, pngs[b - 1]) for b in (1, 2)}
        truth_ratio = truths[2][0][truths[2][1]].sum() / truths[1][0][truths[1][1]].sum()
        for count in [int(c) for c in args.counts.split(",")]:
            energy = {}
            for bounces in (1, 2):
                png = os.path.join(tmp, f"{name}-vpl-{count}-{bounces}.png")
                image, report = mv.render(scene, "vpl", args.size,
                                          {"vpl.count": count, "vpl.bounces": bounces},
                                          out_png=png, frames=args.frames)
                if count == int(args.counts.split(",")[0]):
                    pngs.append(png)
                truth, mask = truths[bounces]
                rmse, energy[bounces] = mc.errors(image, truth, mask)
                ratio = ""
                if bounces == 2:
                    ratio = f"{energy[2] / energy[1] * truth_ratio:.3f} ({truth_ratio:.3f})"
                row = (f"| {name} | {count} | {bounces} | {rmse:.3f} | {energy[bounces]:.3f} | "
                       f"{ratio} | {gather_ms(report):.1f} |")
                lines.append(row)
                print(row, flush=True)
        if args.images:
            write_strip(os.path.join(args.images, f"bounces-{name}.png"), pngs)


if __name__ == "__main__":
    main()
