#!/usr/bin/python3
"""Measures the texture-atlas GI (SEEDS.md section 2) as ratios in one run on this machine.

(a) the thesis' performance table (Cornell box, atlas 512^2 and 1024^2 x 10..400 samples,
    every pass each frame) as ratios next to the thesis' fps ratios, and a fit of the gather
    time to a * samples * texels + b against the issue's linearity target;
(b) atlas build time and memory, Cornell box and Sponza, cold and from the disk cache;
(c) progressive convergence of the Cornell indirect light against the path tracer, for both
    estimators with and without voxel visibility, also with the light moved off the ceiling.
Timings are medians per pass from `voxatlas render --timings` (glFinish around each pass on
llvmpipe, see src/gl/GpuProfiler.h). Writes docs/results-atlas.md and docs/images/atlas_*.png.
This file puts the page together; the sections are measured by measure_atlas_table.py and
measure_atlas_linearity.py (a), measure_atlas_build.py (b) and measure_atlas_convergence.py (c).
Usage: /usr/bin/python3 scripts/measure_atlas.py [--bin build/voxatlas] [--rounds N] [--frames N]
About 6-7 minutes on 2 idle cores; progress goes to stderr.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402
from measure_atlas_build import measure_build  # noqa: E402
from measure_atlas_convergence import measure_convergence  # noqa: E402
from measure_atlas_linearity import measure_linearity  # noqa: E402
from measure_atlas_table import measure_table  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    common.add_bin_argument(parser)
    parser.add_argument("--frames", type=int, default=3, help="timed frames per row of (a)")
    parser.add_argument("--rounds", type=int, default=5,
                        help="interleaved rounds of (a); each pass keeps its smallest median")
    parser.add_argument("--repeats", type=int, default=3, help="runs per build figure in (b)")
    common.add_sponza_argument(parser)
    parser.add_argument("--convergence-atlas", type=int, default=512,
                        help="atlas resolution of (c) (voxel visibility costs ~18x the gather)")
    args = parser.parse_args()
    common.use_binary(args.bin)
    os.makedirs(common.IMAGES, exist_ok=True)

    lines = []
    say = lines.append
    body = []
    sections = []
    timings = measure_table(body.append, args.frames, 1, args.rounds, 512)
    renderer = timings.renderer
    linear, linear_detail = measure_linearity(body.append, timings)
    sections.append(body)
    body = []
    measure_build(body.append, args.sponza, args.repeats)
    sections.append(body)
    body = []
    accurate, accurate_detail, merz_detail = measure_convergence(body.append, 128,
                                                                 args.convergence_atlas, 1024)
    sections.append(body)
    minutes = (time.time() - common.START) / 60.0

    say("# Texture-atlas GI: measured costs and accuracy\n")
    say("Produced by `/usr/bin/python3 scripts/measure_atlas.py` (after `bash scripts/build.sh`)")
    say(f"on {renderer}, in {minutes:.1f} minutes. llvmpipe runs on 2 CPU")
    say("cores: compare ratios measured in this run, not milliseconds, with the thesis'")
    say("GeForce 8800 GT figures (SEEDS.md section 2, thesis 5).\n")
    say("Summary:\n")
    say(f"- Linearity (gather ms = a * samples * texels + b within 10%): "
        f"**{'met' if linear else 'not met'}** ({linear_detail}); see (a).")
    say(f"- Accuracy (area + voxel visibility, 1024 samples: relative RMSE <= 0.10, energy "
        f"0.95-1.05): **{'met' if accurate else 'not met'}** ({accurate_detail}); see (c).")
    say(f"- Bias of the thesis' weighting: {merz_detail}; see (c).\n")
    for section in sections:
        lines.extend(section)
    common.write_page("results-atlas.md", lines)
    common.progress(f"wrote docs/results-atlas.md in {minutes:.1f} min")


if __name__ == "__main__":
    main()
