#!/usr/bin/env python3
"""VPL or converged atlas GI on the open-front box (assets/scene_suite/
cornell_open_front_sun.gltf, camera 0), drawn by power alone and by an importance (VPLs:
vpl.importance, the view's, the default; the atlas: atlas.importance=view and =surfaces, the
default), against the path tracer: prints relative RMSE and energy of the indirect light and
draws the picture (the path tracer, each draw; below, each one's signed error: red too bright,
blue too dark, in units of the path tracer's mean).
  --mode vpl    docs/images/vpl/importance_open_front.png (docs/results-vpl.md, 'VPLs drawn
                where the view receives their light')
  --mode atlas  docs/images/atlas_importance_open_front.png: the scoreboard's converged atlas,
                voxel visibility, atlas.target_samples accumulated (docs/accuracy-analysis.md,
                'The atlas gather's senders drawn where surfaces receive their light')

    /usr/bin/python3 scripts/measure_importance.py --mode vpl|atlas [--size 128] [--spp 1024]
"""
import argparse
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as mc  # noqa: E402

SCENE = os.path.join(mc.ROOT, "assets", "scene_suite", "cornell_open_front_sun.gltf")
LUMINANCE = numpy.array([0.2126, 0.7152, 0.0722])
# The scoreboard's settings: the adaptive plan and Lambertian surfaces.
BASE = {"render.plan": "adaptive", "material.specular": "0"}
# The scoreboard's converged atlas: 1024 samples in sets of atlas.samples (100).
CONVERGED_ATLAS = {"atlas.visibility": "voxel", "render.frames": "11"}
# Per mode: the setting, the settings under every draw, the picture and the draws compared.
MODES = {
    "vpl": ("vpl.importance", {}, os.path.join("vpl", "importance_open_front.png"),
            (("by power alone", "0"), ("by the view's importance", "1"))),
    "atlas": ("atlas.importance", CONVERGED_ATLAS, "atlas_importance_open_front.png",
              (("by power alone", "power"), ("by the view's importance", "view"),
               ("by the surfaces' importance", "surfaces"))),
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", choices=sorted(MODES), default="vpl")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=1024)
    mc.add_bin_argument(parser)
    args = parser.parse_args()
    mc.use_binary(args.bin)
    key, settings, picture, draws = MODES[args.mode]
    reference = mc.render_indirect(SCENE, "reference",
                                   dict(BASE, **{"reference.spp": str(args.spp)}),
                                   args.size).image
    mask = mc.reference_mask(reference)
    images = []
    for name, importance in draws:
        image = mc.render_indirect(SCENE, args.mode,
                                   dict(BASE, **settings, **{key: importance}), args.size).image
        rmse, energy = mc.errors(image, reference, mask)
        print("| %s | %.3f | %.3f |" % (name, rmse, energy))
        images.append(image)
    mean = float((reference @ LUMINANCE)[mask].mean())
    tone = lambda x: numpy.clip(x * (0.4 / mean), 0.0, 1.0) ** (1.0 / 2.2)

    def signed(image):
        d = (image @ LUMINANCE - reference @ LUMINANCE) / mean
        out = numpy.zeros(reference.shape)
        out[..., 0], out[..., 2] = numpy.clip(d, 0.0, 1.0), numpy.clip(-d, 0.0, 1.0)
        return out

    top = numpy.concatenate([tone(reference)] + [tone(i) for i in images], axis=1)
    bottom = numpy.concatenate([numpy.zeros(reference.shape)] + [signed(i) for i in images],
                               axis=1)
    out = os.path.join(mc.IMAGES, picture)
    mc.write_png(out, numpy.concatenate([top, bottom], axis=0), 2)
    mc.progress("wrote " + out)


if __name__ == "__main__":
    main()
