"""Timing several configurations of `voxatlas render` (and other programs) in interleaved
rounds, A B C A B C ..., so that a machine shared with other jobs slows every configuration
of a round alike: ratios are taken within a round, and their median over the rounds is
quoted, with the load average when the run started and ended.

Used by scripts/bench_peer.py and scripts/bench_trace.py; run those with /usr/bin/python3.
"""
import os
import statistics

import measure_common as common

# Both cameras inside the Cornell box: every pixel is a surface that traces cones.
INSIDE_CAMERA = "0.278,0.273,-0.02,0.278,0.273,-0.559,75"
WIDTH, HEIGHT = 1280, 720


def load_average():
    with open("/proc/loadavg") as f:
        return f.read().split()[0]


def voxatlas_frame(settings, frames, warmup, size=(WIDTH, HEIGHT), shader_dir=None,
                   camera=INSIDE_CAMERA, binary=None):
    """Median ms per pass of the Cornell box in voxel mode ('frame' = the passes' sum);
    settings start from the program's defaults (the adaptive plan), not the thesis plan;
    `binary` replaces the voxatlas that runs from here on."""
    env = dict(os.environ)
    if shader_dir:
        env["VOXATLAS_SHADER_DIR"] = shader_dir
    extra = ["--camera", camera, "--set", "render.plan=adaptive"]
    extra += common.settings_args(settings)
    if binary:
        common.BIN = binary
    report = common.render_timed(common.CORNELL, {}, frames, warmup, size, extra, mode="voxel",
                                 env=env).report
    return common.pass_medians(report)


def run_rounds(configs, rounds):
    """configs: name -> function returning a dict of figures. Returns name -> list (one
    dict per round), run in the order given within each round."""
    results = {name: [] for name in configs}
    for r in range(rounds):
        common.progress(f"round {r + 1}/{rounds}, load {load_average()}")
        for name, measure in configs.items():
            results[name].append(measure())
    return results


def ratio_median(results, a, b, figure_a, figure_b=None, scale=1.0):
    """Median over rounds of scale * results[a][figure_a] / results[b][figure_b], and the
    per-round values."""
    figure_b = figure_b or figure_a
    values = [scale * ra[figure_a] / rb[figure_b] for ra, rb in zip(results[a], results[b])]
    return statistics.median(values), values


def median(results, name, figure):
    return statistics.median(r[figure] for r in results[name])


def spread(values):
    return f"{min(values):.3f}-{max(values):.3f}" if len(values) > 1 else "-"
