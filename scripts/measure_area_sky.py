#!/usr/bin/python3
"""Area and sky light in every mode against the path tracer, written to
docs/results-area-sky.md:
- the emissive Cornell box (assets/cornell_box/cornell_box_emissive.gltf, lit only by its
  ceiling panel): the direct component by each shadow method (shadow maps from the panel's
  centre, and shadow.rays rays through the GPU BVH) and the indirect component of voxel and
  atlas GI, against the path tracer at 1024 spp;
- a sky over the scene suite's Cornell box open at the front (`--light none --light
  sky:1,1,1:1`): the sky's direct light (reference.bounces = 0, no bounce of it) against what
  each GPU mode shows of it; the GPU modes put it in the indirect output, the path tracer in
  the direct one, so their final images are compared.
96x96 pixels, material.specular = 0, render.plan = fixed.

Usage: /usr/bin/python3 scripts/measure_area_sky.py [--bin build/voxatlas]
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

EMISSIVE = os.path.join(common.ROOT, "assets", "cornell_box", "cornell_box_emissive.gltf")
OPEN_BOX = os.path.join(common.ROOT, "assets", "scene_suite", "cornell_open_front_sun.gltf")
SKY = ["--light", "none", "--light", "sky:1,1,1:1"]
SIZE = 96
BASE = {"material.specular": 0}


def image(scene, mode, output, settings, extra=(), png=None):
    options = ["--mode", mode, "--output", output] + common.size_args(SIZE)
    options += common.settings_args({**BASE, **settings}) + list(extra)
    return common.render(scene, options, png, hdr=True).image


def row(label, result, reference, mask, target=""):
    rmse, energy = common.errors(result, reference, mask)
    return f"| {label} | {rmse:.3f} | {energy:.3f} | {target} |"


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    args = parser.parse_args()
    common.use_binary(args.bin)
    images = common.IMAGES
    reference = {"reference.spp": 1024}

    lines = ["# Area and sky light against the path tracer", "",
             "Made by `/usr/bin/python3 scripts/measure_area_sky.py` "
             f"({time.strftime('%Y-%m-%d %H:%M')}, load average "
             f"{open('/proc/loadavg').read().split()[0]}). 96x96, material.specular=0, "
             "render.plan=fixed, the path tracer at 1024 spp. Relative RMSE and energy "
             "ratio over the pixels that show geometry (src/reference/ImageMetrics.h).", ""]

    direct_ref = image(EMISSIVE, "reference", "direct", reference)
    mask = common.reference_mask(image(EMISSIVE, "reference", "indirect", reference))
    # The panel itself (radiance 22, every mode shows it alike) would outweigh the light it
    # sends: the direct light is scored on the surfaces it lights.
    lit = mask & (direct_ref.max(axis=2) < 2.0)
    lines += ["## The emissive Cornell box", "",
              "Lit only by its ceiling panel (an area light of 2 triangles). Direct light on "
              f"the surfaces it lights ({int(lit.sum())} pixels; the panel's own pixels, "
              "radiance 22 in every mode, left out):", "",
              "| shadow method | relative RMSE | energy | target |", "|---|---|---|---|"]
    for method, settings in (("shadowmap (from the panel's centre)", {"shadow.method": "shadowmap"}),
                             ("bvh, 25 rays", {"shadow.method": "bvh", "shadow.rays": 25}),
                             ("bvh, 100 rays", {"shadow.method": "bvh", "shadow.rays": 100})):
        png = os.path.join(images, "area_direct_" + settings["shadow.method"] +
                           str(settings.get("shadow.rays", "")) + ".png")
        lines.append(row(method, image(EMISSIVE, "direct", "direct", settings, png=png),
                         direct_ref, lit, "energy 0.95-1.05"))
    indirect_ref = image(EMISSIVE, "reference", "indirect", reference)
    lines += ["", "Indirect light (1 bounce):", "",
              "| mode | relative RMSE | energy | target |", "|---|---|---|---|"]
    for mode, settings in (("voxel", {}), ("atlas", {}),
                           ("atlas", {"atlas.visibility": "voxel", "atlas.target_samples": 1024})):
        label = mode + (" converged, voxel visibility" if settings else " defaults")
        lines.append(row(label, image(EMISSIVE, mode, "indirect", settings), indirect_ref, mask))

    sky_ref = image(OPEN_BOX, "reference", "final", {**reference, "reference.bounces": 1}, SKY)
    sky_direct_ref = image(OPEN_BOX, "reference", "direct", reference, SKY)
    sky_mask = sky_direct_ref.sum(axis=2) >= 0   # every pixel: the box fills the view
    lines += ["", "## A sky over the Cornell box open at the front", "",
              "`--light none --light sky:1,1,1:1`. The GPU modes show the sky's direct light "
              "(through their gather) and no bounce of it; the path tracer's direct image is "
              "the same quantity. Final GPU images against it:", "",
              "| mode | relative RMSE | energy | target |", "|---|---|---|---|"]
    for mode in ("direct", "voxel", "atlas"):
        settings = {"atlas.visibility": "voxel", "atlas.target_samples": 1024} if mode == "atlas" else {}
        png = os.path.join(images, f"sky_open_box_{mode}.png")
        result = image(OPEN_BOX, mode, "final", settings, SKY, png=png)
        lines.append(row(mode + (" (voxel visibility, 1024 samples)" if mode == "atlas" else ""),
                         result, sky_direct_ref, sky_mask))
    rmse, energy = common.errors(sky_direct_ref, sky_ref, sky_mask)
    lines += ["", f"For scale: the sky's direct light alone against the path tracer's final "
              f"image with one bounce of it: relative RMSE {rmse:.3f}, energy {energy:.3f} "
              "(the bounce no GPU mode adds yet).", ""]
    lines += ["## Reading the figures", "",
              "- The emissive box's direct light is exact before shadowing in every mode "
              "(tests/gpu/AreaLightGpuTest.cpp holds it to the form factor within 0.5%); what "
              "remains is shadowing and pixel footprint: these images sample each pixel at "
              "its centre while the path tracer averages its square "
              "(`docs/results-linespace.md` compares them at render.supersample=4).",
              "- Without GI (`--mode direct`) nothing tells where the sky is visible: every "
              "surface gets the open-hemisphere term, so the box's inside is lit as if it "
              "had no walls (energy above 2).",
              "- Voxel GI over-counts the sky: a cone that crosses a wall of partial coverage "
              "keeps (1 - opacity) of the sky behind it, and the sky's radiance is about ten "
              "times the walls', so these leaks weigh far more than they do for bounce light "
              "(the thin-wall leak of `docs/results-accuracy.md` is the same effect).",
              "- Atlas GI with voxel visibility blocks sky directions by the occupancy "
              "volume's coverage and comes within 10% of the energy.", ""]
    common.write_page("results-area-sky.md", lines)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
