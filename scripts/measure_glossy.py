#!/usr/bin/python3
"""The glossy model (material.model=gltf) in voxel GI against the path tracer with the same
BRDF, on the scene suite's glossy Cornell box (assets/scene_suite/cornell_glossy.gltf: the
tall block a grey metal, roughness 0.3), written to docs/results-glossy.md with images
docs/images/glossy_*.png.

The specular component of a renderer is its image with the glossy model minus the same
with material.specular=0 (Lambertian), for the direct and the indirect output and their
sum. It is a difference: light the specular lobes add minus the diffuse light metallic
surfaces and Fresnel take away, so it is scored three ways: over every geometry pixel (the
issue's figure), over its positive and negative parts, and as the metal block's own glossy
radiance (no diffuse term there, so it is specular light alone). 96x96, render.plan=fixed,
the path tracer at 1024 spp.

Usage: /usr/bin/python3 scripts/measure_glossy.py [--bin build/voxatlas]
       /usr/bin/python3 scripts/measure_glossy.py --figures [--set KEY=VALUE ...]
--figures prints only the two figures gpu.*.GlossyGpuTest.* hold (the metal block's indirect
light and the indirect specular component, voxel / path tracer), with the default plan and
the --set settings on the voxel side, and writes nothing.
"""
import argparse
import json
import os
import sys
import tempfile
import time

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

SCENE = os.path.join(common.ROOT, "assets", "scene_suite", "cornell_glossy.gltf")
SIZE = 96
GLOSSY = {"material.model": "gltf"}
LAMBERT = {"material.specular": 0}
REFERENCE = {"reference.spp": 1024}
TARGET = "energy 0.85-1.15"


def image(mode, output, settings, scene=SCENE, extra=()):
    options = ["--mode", mode, "--output", output] + common.size_args(SIZE)
    options += common.settings_args({**REFERENCE, **settings}) + list(extra)
    return common.render(scene, options, hdr=True).image


def erode(mask):
    """The pixels of mask whose eight neighbours are in it too."""
    inner = mask.copy()
    padded = numpy.pad(mask, 1)
    for dy in (0, 1, 2):
        for dx in (0, 1, 2):
            inner &= padded[dy:dy + mask.shape[0], dx:dx + mask.shape[1]]
    return inner


def metal_mask():
    """Pixels wholly covered by the metal block: the scene with the metal glowing (radiance
    10) and no light, where only the block itself reaches 9 at the pixel's centre, less the
    pixels next to one it does not cover. The path tracer's pixel integrates its whole area,
    the rasterizer's samples its centre: a pixel on the block's outline holds some wall in the
    one and none in the other, and the wall's diffuse light outweighs the metal's."""
    doc = json.load(open(SCENE))
    for material in doc["materials"]:
        if material["pbrMetallicRoughness"].get("metallicFactor", 1.0) > 0.0:
            material["emissiveFactor"] = [1.0, 1.0, 1.0]
            material["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 10.0}}
    doc.setdefault("extensionsUsed", []).append("KHR_materials_emissive_strength")
    with tempfile.TemporaryDirectory(dir=os.path.dirname(SCENE)) as tmp:
        path = os.path.join(tmp, "glow.gltf")
        json.dump(doc, open(path, "w"))
        glow = image("direct", "direct", LAMBERT, scene=path, extra=["--light", "none"])
    return erode(glow.min(axis=2) > 9.0)


def dilate(mask, pixels):
    """mask grown by `pixels` in every direction (a square neighbourhood)."""
    grown = mask.copy()
    padded = numpy.pad(mask, pixels)
    for dy in range(2 * pixels + 1):
        for dx in range(2 * pixels + 1):
            grown |= padded[dy:dy + mask.shape[0], dx:dx + mask.shape[1]]
    return grown


def signed_png(path, columns, scale):
    """Signed images side by side, grey = 0, white/black = +-scale."""
    gap = numpy.ones((SIZE, 2, 3))
    tiles = []
    for c in columns:
        tiles += [numpy.clip(0.5 + 0.5 * c / scale, 0.0, 1.0), gap]
    common.write_png(path, numpy.concatenate(tiles[:-1], axis=1), 3)


def tonemapped_png(path, columns):
    peak = max(numpy.percentile(c, 99.5) for c in columns)
    gap = numpy.ones((SIZE, 2, 3))
    tiles = []
    for c in columns:
        tiles += [(c / peak) ** (1.0 / 2.2), gap]
    common.write_png(path, numpy.concatenate(tiles[:-1], axis=1), 3)


def metrics_row(label, voxel, reference, mask):
    rmse, energy = common.errors(voxel, reference, mask)
    return (f"| {label} | {reference[mask].sum():.1f} | {voxel[mask].sum():.1f} | {energy:.3f} "
            f"| {rmse:.3f} | {TARGET} |")


def print_figures(assignments):
    """The metal block's indirect light and the indirect specular component over the image,
    voxel with the default plan and `assignments` against the path tracer."""
    sets = dict(a.split("=", 1) for a in assignments)
    reference = {model: image("reference", "indirect", settings)
                 for model, settings in (("glossy", GLOSSY), ("lambert", LAMBERT))}
    voxel = {model: image("voxel", "indirect", {**settings, "render.plan": "adaptive", **sets})
             for model, settings in (("glossy", GLOSSY), ("lambert", LAMBERT))}
    mask = common.reference_mask(reference["glossy"])
    metal = metal_mask() & mask
    block = voxel["glossy"][metal].sum() / reference["glossy"][metal].sum()
    specular = ((voxel["glossy"] - voxel["lambert"])[mask].sum() /
                (reference["glossy"] - reference["lambert"])[mask].sum())
    settings_text = " ".join(assignments) or "defaults"
    print(f"{settings_text}: metal block indirect light x{block:.3f} of the path tracer's "
          f"({int(metal.sum())} pixels), indirect specular component x{specular:.3f}")


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    parser.add_argument("--figures", action="store_true",
                        help="print the tests' two figures only (see the usage above)")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a voxel setting for --figures")
    args = parser.parse_args()
    common.use_binary(args.bin)
    if args.figures:
        print_figures(args.set)
        return

    renders = {}
    for mode in ("reference", "voxel"):
        for output in ("direct", "indirect"):
            for model, settings in (("glossy", GLOSSY), ("lambert", LAMBERT)):
                renders[mode, output, model] = image(mode, output, settings)
    mask = common.reference_mask(renders["reference", "indirect", "glossy"])
    metal = metal_mask() & mask
    specular, glossy = {}, {}
    for mode in ("reference", "voxel"):
        for output in ("direct", "indirect"):
            glossy[mode, output] = renders[mode, output, "glossy"]
            specular[mode, output] = glossy[mode, output] - renders[mode, output, "lambert"]
        specular[mode, "together"] = specular[mode, "direct"] + specular[mode, "indirect"]
        glossy[mode, "together"] = glossy[mode, "direct"] + glossy[mode, "indirect"]

    command = "/usr/bin/python3 scripts/measure_glossy.py"
    lines = ["# The glossy model: voxel GI's specular cone against the path tracer", "",
             f"Made by `{command}` ({time.strftime('%Y-%m-%d %H:%M')}, load average "
             f"{open('/proc/loadavg').read().split()[0]}). Scene: "
             "`assets/scene_suite/cornell_glossy.gltf` (the tall block a grey metal, base colour "
             "0.8, metallic 1, roughness 0.3; every other surface a rough dielectric), camera 0, "
             f"{SIZE}x{SIZE}, render.plan=fixed; the path tracer at 1024 spp, one bounce. Each "
             "renderer's specular component is its image with `--set material.model=gltf` minus "
             "the same with `--set material.specular=0`. Energy ratio = voxel / reference of the "
             "summed values; relative RMSE of voxel against reference (ImageMetrics.h), over "
             f"the reference's geometry pixels ({int(mask.sum())}).", "",
             "## The specular component over the whole image", "",
             "The issue's figure. The difference nets the light the specular lobes add against "
             "the diffuse light the metal block and the Fresnel factor of every other surface "
             "take away, so its sum is small beside either part and its ratio is sensitive "
             "to both.", "",
             "| output | reference sum | voxel sum | energy ratio | relative RMSE | target |",
             "|---|---|---|---|---|---|"]
    for output in ("direct", "indirect", "together"):
        lines.append(metrics_row(output, specular["voxel", output],
                                 specular["reference", output], mask))
    _, together = common.errors(specular["voxel", "together"], specular["reference", "together"],
                                mask)
    verdict = "within" if abs(together - 1.0) <= 0.15 else "outside"
    lines += ["", f"The target (energy within 15% of the path tracer's) on the sum of both: "
              f"{together:.3f}, {verdict} it."]
    lines += ["", "Its parts (pixels where each renderer's difference is positive or negative, "
              "summed separately):", "",
              "| output | part | reference sum | voxel sum | ratio |", "|---|---|---|---|---|"]
    for output in ("direct", "indirect", "together"):
        for part, sign in (("added", 1.0), ("taken away", -1.0)):
            ref = numpy.clip(sign * specular["reference", output], 0.0, None)[mask].sum()
            vox = numpy.clip(sign * specular["voxel", output], 0.0, None)[mask].sum()
            lines.append(f"| {output} | {part} | {ref:.1f} | {vox:.1f} | {vox / ref:.3f} |")
    lines += ["", "## The metal block", "",
              f"Its glossy radiance over the {int(metal.sum())} pixels inside its outline (the "
              "path tracer's pixel integrates its area, the rasterizer's samples its centre, so "
              "a pixel on the outline holds some wall in one and none in the other): a "
              "metal has no diffuse term, so this is specular light alone (direct: the point "
              "light's highlight; indirect: the specular cone against the path tracer's "
              "reflected paths).", "",
              "| output | reference sum | voxel sum | energy ratio | relative RMSE | target |",
              "|---|---|---|---|---|---|"]
    for output in ("direct", "indirect", "together"):
        lines.append(metrics_row(output, glossy["voxel", output], glossy["reference", output],
                                 metal))

    # The same voxel figures with the program's own plan (render.plan=adaptive: one
    # scene-centred level for this box) against the same references.
    default_plan = {"render.plan": "adaptive"}
    adaptive = {}
    for output in ("direct", "indirect"):
        adaptive["glossy", output] = image("voxel", output, {**GLOSSY, **default_plan})
        adaptive["specular", output] = (adaptive["glossy", output] -
                                        image("voxel", output, {**LAMBERT, **default_plan}))
    for kind in ("glossy", "specular"):
        adaptive[kind, "together"] = adaptive[kind, "direct"] + adaptive[kind, "indirect"]
    lines += ["", "## With the program's default plan", "",
              "The pages' scripts measure the thesis' allocation (render.plan=fixed, three "
              "camera-centred levels here); the program's default, render.plan=adaptive, gives "
              "this box one scene-centred level. The same references:", "",
              "| figure | output | reference sum | voxel sum | energy ratio | relative RMSE | "
              "target |", "|---|---|---|---|---|---|---|"]
    for output in ("direct", "indirect", "together"):
        lines.append("| specular component |" + metrics_row(
            output, adaptive["specular", output], specular["reference", output], mask)[1:])
    for output in ("indirect", "together"):
        lines.append("| metal block |" + metrics_row(
            output, adaptive["glossy", output], glossy["reference", output], metal)[1:])
    _, together_default = common.errors(adaptive["specular", "together"],
                                        specular["reference", "together"], mask)
    verdict = "within" if abs(together_default - 1.0) <= 0.15 else "outside"
    lines += ["", f"The target on the sum of both with the default plan: {together_default:.3f}, "
              f"{verdict} it.", "",
              "Before the voxels' light was what the glTF BRDF reflects (commit 9c9c6e1, "
              "where voxelization stored the base colour and injection the irradiance alone, "
              "as for Lambertian surfaces), this script measured with the same references: "
              "the specular component with the default plan 0.755 (indirect) and 0.832 "
              "(together, outside the target), with the fixed plan 0.266 and 0.327; the metal "
              "block 0.981 and 0.979. A rough dielectric (roughness 1) reflects 0.96 of its "
              "base colour plus a specular albedo of about 0.02 under uniform light, and "
              "less of the former and more of the latter at grazing light: the box's walls "
              "sent on 1-2% too much, and that excess was a quarter of the specular component "
              "the path tracer measures."]

    # Every GI mode's indirect light with the default settings: the atlas and VPL GI trace no
    # specular cone, so their glossy surfaces reflect only the diffuse term of what they gather.
    outline = dilate(metal_mask(), 2)
    outside = mask & ~outline
    lines += ["", "## Every mode's indirect light", "",
              "Every mode's surfaces send on what the glTF BRDF reflects of the light they "
              "receive (`shaders/common/reflectance.glsl`: its directional albedo for the "
              "light's direction, as diffuse light), but only voxel GI follows the specular "
              "lobe where the light arrives: the atlas and VPL GI reflect only the diffuse "
              "term of what they gather, so the metal block, which has none, is black in their "
              "indirect light. The indirect light's specular component with the default "
              "settings (render.plan=adaptive), over the whole image, outside the metal block "
              "(its outline grown by two pixels), and the block's glossy indirect light:", "",
              "| mode | whole image: sum (reference " +
              f"{specular['reference', 'indirect'][mask].sum():.1f}) | ratio | outside the "
              f"block (reference {specular['reference', 'indirect'][outside].sum():.1f}) | "
              f"ratio | metal block (reference {glossy['reference', 'indirect'][metal].sum():.1f})"
              " | ratio |", "|---|---|---|---|---|---|---|"]
    for mode in ("voxel", "atlas", "vpl"):
        glossy_mode = (adaptive["glossy", "indirect"] if mode == "voxel"
                       else image(mode, "indirect", {**GLOSSY, **default_plan}))
        specular_mode = (adaptive["specular", "indirect"] if mode == "voxel"
                         else glossy_mode - image(mode, "indirect", {**LAMBERT, **default_plan}))
        cells = []
        for values, truth, where in ((specular_mode, specular["reference", "indirect"], mask),
                                     (specular_mode, specular["reference", "indirect"], outside),
                                     (glossy_mode, glossy["reference", "indirect"], metal)):
            total = values[where].sum()
            cells += [f"{total:.1f}", f"{total / truth[where].sum():.3f}"]
        lines.append(f"| {mode} | " + " | ".join(cells) + " |")

    lines += ["", "## Images", "",
              "Specular components, reference | voxel | voxel - reference (grey = 0, white = "
              "+s, black = -s, s given per row), the fixed plan; then the glossy images "
              "themselves (gamma 2.2, one exposure).", ""]
    for output in ("direct", "indirect", "together"):
        ref, vox = specular["reference", output], specular["voxel", output]
        scale = float(numpy.percentile(numpy.abs(ref[mask]), 99.0))
        name = f"glossy_{output}.png"
        signed_png(os.path.join(common.IMAGES, name), [ref, vox, vox - ref], scale)
        lines += [f"{output} (s = {scale:.3f} W/(m^2 sr)):", "", f"![{output}](images/{name})",
                  ""]
    tonemapped_png(os.path.join(common.IMAGES, "glossy_final.png"),
                   [glossy["reference", "together"], glossy["voxel", "together"],
                    adaptive["glossy", "together"]])
    lines += ["Glossy final images, reference | voxel, fixed plan | voxel, default plan:", "",
              "![final](images/glossy_final.png)", ""]
    common.write_page("results-glossy.md", lines)
    common.progress("wrote docs/results-glossy.md")


if __name__ == "__main__":
    main()
