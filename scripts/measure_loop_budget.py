#!/usr/bin/env python3
"""The gathers against llvmpipe's loop budget (docs/architecture.md, "The loop budget"): the
Cornell box's indirect term, scored against the path tracer (one bounce), as one gather is
given more work per shader invocation: the atlas' area estimator with voxel visibility and N
samples in one set (one frame), and the VPL gather with cascade visibility, every VPL at every
pixel or interleaved, at growing vpl.count. Each estimator's expectation does not depend on
N; an energy that falls as N grows is light the gather did not compute.

    /usr/bin/python3 scripts/measure_loop_budget.py [--size 64] [--bin build/voxatlas]

Prints the Markdown tables docs/accuracy-analysis.md quotes. The default plan is used
throughout; the reference (reference.spp=1024) is rendered once and cached on disk.
"""
import argparse
import os

import measure_common as mc

ATLAS_SAMPLES = [100, 1000, 2000, 4000]
VPL_COUNTS = [256, 1024, 4096, 16384]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mc.add_bin_argument(parser)
    parser.add_argument("--size", type=int, default=64)
    args = parser.parse_args()
    mc.use_binary(args.bin)
    scene = os.path.join(mc.ROOT, "assets", "scene_suite", "cornell_classic.gltf")
    base = {"material.specular": 0, "render.plan": "adaptive"}
    truth = mc.render_indirect(scene, "reference", {**base, "reference.spp": 1024},
                               args.size).image
    mask = mc.reference_mask(truth)

    def score(mode, settings):
        mc.progress(f"{mode} {settings}")
        image = mc.render_indirect(scene, mode, {**base, **settings}, args.size).image
        return "%.3f / %.3f" % mc.errors(image, truth, mask)

    print("| atlas.samples (one set) | area + voxel visibility | area, no visibility |")
    print("| --- | --- | --- |")
    for n in ATLAS_SAMPLES:
        one_set = {"atlas.samples": n, "atlas.target_samples": n, "render.frames": 1}
        print(f"| {n} | {score('atlas', {**one_set, 'atlas.visibility': 'voxel'})} | "
              f"{score('atlas', {**one_set, 'atlas.visibility': 'none'})} |")
    print()
    print("| vpl.count | every VPL at every pixel | interleaved 4x4 |")
    print("| --- | --- | --- |")
    for n in VPL_COUNTS:
        print(f"| {n} | {score('vpl', {'vpl.count': n, 'vpl.interleave': 0})} | "
              f"{score('vpl', {'vpl.count': n, 'vpl.interleave': 1})} |")
    print(f"\nCells: relative RMSE / energy against the path tracer, {args.size}x{args.size}.")


if __name__ == "__main__":
    main()
