#!/usr/bin/python3
"""What the cone rings' dither is worth at a quarter of the resolution on the thesis'
allocation (docs/results/README.md, the sweep's *preset fast*): voxel GI's indirect term with
the shaders as they are, where every pixel of a quarter-resolution trace turns its ring by the
16 turns' mean, against a copy of the shaders whose one-turn branch turns the ring in 2x2 turns
of single pixels, as the trace did before (results-performance.md, "No dither where the
filter's window is 3x3"). Relative RMSE and energy against the path tracer (1 bounce,
256 spp, cached), Cornell box, camera 0, render.plan=fixed.

Usage: /usr/bin/python3 scripts/measure_quarter_dither.py [--bin build/voxatlas]
       [--size 256] [--set KEY=VALUE ...]
The --set changes go on top of the sweep's *preset fast* (voxel.resolution=16,
voxel.trace_scale=0.25, voxel.multiplier=4).
"""
import argparse
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

FAST = {"material.specular": 0, "voxel.resolution": 16, "voxel.trace_scale": 0.25,
        "voxel.multiplier": 4, "render.frames": 6}
ONE_TURN = ("        ivec2 cell = (pixel / cellPixels) & (turns - 1);\n"
            "        float step = turns == 1 ? 7.5 : bayer[cell.y * 4 + cell.x];")
PIXEL_TURNS = ("        ivec2 cell = turns == 1 ? (pixel & 1) : ((pixel / cellPixels) & (turns - 1));\n"
               "        float step = bayer[cell.y * 4 + cell.x];")


def shaders_with_pixel_turns(folder):
    """A copy of shaders/ in `folder` whose one-turn branch dithers over 2x2 single pixels."""
    copy = os.path.join(folder, "shaders")
    shutil.copytree(os.path.join(common.ROOT, "shaders"), copy)
    trace = os.path.join(copy, "voxel", "cone_trace.frag")
    text = open(trace).read()
    if ONE_TURN not in text:
        sys.exit("measure_quarter_dither: cone_trace.frag no longer holds the one-turn branch "
                 "this script replaces; update ONE_TURN")
    open(trace, "w").write(text.replace(ONE_TURN, PIXEL_TURNS))
    return copy


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    common.add_bin_argument(parser)
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    args = parser.parse_args()
    common.use_binary(args.bin)
    settings = dict(FAST, **dict(change.split("=", 1) for change in args.set))
    size = (args.size, args.size)
    reference = common.render_indirect(common.CORNELL, "reference",
                                       {"material.specular": 0, "reference.spp": 256,
                                        "reference.bounces": 1}, size).image
    mask = common.reference_mask(reference)
    print("| ring turns at a quarter of the resolution | rel. RMSE | energy |")
    print("|---|---:|---:|")
    with tempfile.TemporaryDirectory() as folder:
        for label, shaders in (("one, the 16 turns' mean (the shaders as they are)", None),
                               ("2x2 turns of single pixels (before)",
                                shaders_with_pixel_turns(folder))):
            if shaders:
                os.environ["VOXATLAS_SHADER_DIR"] = shaders
            image = common.render_indirect(common.CORNELL, "voxel", settings, size).image
            error, energy = common.errors(image, reference, mask)
            print(f"| {label} | {error:.3f} | {energy:.3f} |", flush=True)


if __name__ == "__main__":
    main()
