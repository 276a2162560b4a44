#!/usr/bin/python3
"""Where three of the scoreboard's misses come from (docs/accuracy-analysis.md, "Missed, and
why"), measured at the full form's 128x128 from camera 0 against the path tracer at 4096 spp
(one bounce, indirect term, material.specular=0, the default plan):

- voxel GI on the Cornell box: the share of the squared error and the energy in each band of
  16 image rows, which places the error the relative RMSE sums up;

On the open-front Cornell box:

- the converged atlas (atlas.visibility=voxel) at atlas.target_samples 1024 and 4096: a
  Monte Carlo error falls as 1/sqrt(samples), a bias does not, so the two relative RMSEs
  split the error at 1024 samples into noise and bias;
- VPL GI at vpl.count 1024 to 16384, without the 4x4 interleaving, and at 4096 VPLs with the
  clamp held at 1024 VPLs' B: what falls with the VPL count, and whether the clamp (its
  default B shrinks with the count) or the count itself moves it. Each row also gives the
  share of the squared error and the energy in the image's lowest quarter (the floor in
  front of the blocks).

Usage: /usr/bin/python3 scripts/measure_misses.py [--bin build/voxatlas] [--parts voxel,atlas,vpl]
       [--set key=value ...]
--set changes the settings of every GPU render (after the table's own: --set
atlas.visibility=bvh splits the converged atlas' error with rays, --set atlas.importance=power
with the draw by power alone). Prints markdown tables; about 7 minutes on llvmpipe.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

SUITE = os.path.join(common.ROOT, "assets", "scene_suite")
SCENE = os.path.join(SUITE, "cornell_open_front_sun.gltf")
CORNELL = os.path.join(SUITE, "cornell_classic.gltf")
BAND_ROWS = 16
SIZE = 128
BASE = {"material.specular": 0, "render.plan": "adaptive"}
ATLAS_SAMPLES_PER_FRAME = 100   # atlas.samples' default: frames = target / this, rounded up


OVERRIDES = {}   # --set: over every GPU render's settings


def render(mode, settings, scene=SCENE):
    overrides = OVERRIDES if mode != "reference" else {}
    return common.render_indirect(scene, mode, {**BASE, **settings, **overrides}, SIZE).image


def lowest_quarter(shape):
    mask = common.numpy.zeros(shape[:2], dtype=bool)
    mask[shape[0] * 3 // 4:] = True
    return mask


def scored(image, reference, mask):
    rmse, energy = common.errors(image, reference, mask)
    low = mask & lowest_quarter(reference.shape)
    squared = ((image - reference) ** 2).sum(axis=-1)
    share = float(squared[low].sum() / squared[mask].sum())
    low_energy = float(image[low].sum() / reference[low].sum())
    return rmse, energy, share, low_energy


def voxel_bands():
    common.progress("Cornell box: path tracer, 4096 spp")
    reference = render("reference", {"reference.spp": 4096}, CORNELL)
    mask = common.reference_mask(reference)
    image = render("voxel", {}, CORNELL)
    rmse, energy = common.errors(image, reference, mask)
    print(f"Voxel GI, Cornell box: relative RMSE {rmse:.3f}, energy {energy:.3f}\n")
    print("| image rows | share of squared error | energy |")
    print("|---|---:|---:|")
    squared = ((image - reference) ** 2).sum(axis=-1)
    for top in range(0, SIZE, BAND_ROWS):
        band = mask.copy()
        band[:top] = False
        band[top + BAND_ROWS:] = False
        share = squared[band].sum() / squared[mask].sum()
        print(f"| {top}-{top + BAND_ROWS - 1} | {share:.2f} | "
              f"{image[band].sum() / reference[band].sum():.3f} |")
    print()


def atlas_table(reference, mask):
    print("| converged atlas | relative RMSE | energy |")
    print("|---|---:|---:|")
    rmse = {}
    for target in (1024, 4096):
        frames = -(-target // ATLAS_SAMPLES_PER_FRAME)
        common.progress(f"atlas, {target} samples")
        image = render("atlas", {"atlas.visibility": "voxel", "atlas.target_samples": target,
                                 "render.frames": frames})
        rmse[target], energy, _, _ = scored(image, reference, mask)
        print(f"| {target} samples | {rmse[target]:.3f} | {energy:.3f} |")
    bias2 = max((4.0 * rmse[4096] ** 2 - rmse[1024] ** 2) / 3.0, 0.0)
    noise = max(rmse[1024] ** 2 - bias2, 0.0) ** 0.5
    print(f"\nAt 1024 samples: bias {bias2 ** 0.5:.3f}, noise {noise:.3f} "
          "(relative RMSE, squares adding up).\n")


def vpl_table(reference, mask):
    print("| VPL GI | relative RMSE | energy | lowest quarter: share of squared error | "
          "lowest quarter: energy |")
    print("|---|---:|---:|---:|---:|")
    rows = [("1024 VPLs (default)", {}), ("2048 VPLs", {"vpl.count": 2048}),
            ("4096 VPLs", {"vpl.count": 4096}), ("16384 VPLs", {"vpl.count": 16384}),
            ("1024 VPLs, no interleaving", {"vpl.interleave": 0})]
    clamp_1024 = None
    for label, settings in rows:
        common.progress(f"vpl, {label}")
        rendered = common.render_indirect(SCENE, "vpl", {**BASE, **settings, **OVERRIDES}, SIZE)
        if not settings:
            clamp_1024 = clamp_area(rendered.log)
        print("| {} | {:.3f} | {:.3f} | {:.2f} | {:.3f} |".format(
            label, *scored(rendered.image, reference, mask)))
    if clamp_1024:
        common.progress("vpl, 4096 VPLs at 1024's clamp")
        image = render("vpl", {"vpl.count": 4096, "vpl.clamp": clamp_1024})
        print("| 4096 VPLs, clamp B held at 1024 VPLs' {} m^2 | {:.3f} | {:.3f} | {:.2f} | "
              "{:.3f} |".format(clamp_1024, *scored(image, reference, mask)))


def clamp_area(log):
    """B from the VPL line of voxatlas' log ("..., clamp B 0.001668 m^2")."""
    for line in log.splitlines():
        if "clamp B" in line:
            return line.split("clamp B")[1].split()[0]
    return None


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    parser.add_argument("--parts", default="voxel,atlas,vpl", help="which tables (comma-separated)")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a setting for every GPU render, after the table's own")
    args = parser.parse_args()
    common.use_binary(args.bin)
    for item in args.set:
        if "=" not in item:
            parser.error(f"--set {item}: expected key=value")
        key, value = item.split("=", 1)
        OVERRIDES[key] = value
    parts = args.parts.split(",")
    if "voxel" in parts:
        voxel_bands()
    if "atlas" not in parts and "vpl" not in parts:
        return
    common.progress("open-front box: path tracer, 4096 spp")
    reference = render("reference", {"reference.spp": 4096})
    mask = common.reference_mask(reference)
    if "atlas" in parts:
        atlas_table(reference, mask)
    if "vpl" in parts:
        vpl_table(reference, mask)


if __name__ == "__main__":
    main()
