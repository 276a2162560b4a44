#!/usr/bin/python3
"""The diffuse cone sets of voxel GI (voxel.cones, voxel.jitter_elevation, voxel.cone_interleave,
voxel.cone_angle; src/gi/voxel/ConeSet.h) on the scoreboard and in time:

- accuracy: `voxatlas bench --suite full` on the Cornell box, its low light, its spot and its
  open front, voxel GI for each cone configuration at the defaults and at the quality
  preset's other settings (v=64, full-resolution trace, injection at 4v), relative RMSE /
  energy of the indirect term against the path tracer;
- cost: the cone trace pass (median ms over 3 frames) of each configuration at 1280x720,
  inside the Cornell box and in Sponza's sun view, in interleaved rounds, at the program's
  defaults (ratios to the thesis' 9 cones) and at the quality preset's settings (ratios to 19
  cones), the ratios taken within each round and their median quoted.

Usage: /usr/bin/python3 scripts/measure_cones.py [--bin build/voxatlas] [--sponza PATH]
       [--rounds 3] [--parts accuracy,cost]
Prints markdown tables (docs/accuracy-analysis.md, "Nineteen cones" and "Thirty-seven cones
moved in elevation"); about 40 minutes.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import interleaved  # noqa: E402
import measure_common as common  # noqa: E402

SCENES = ["cornell_classic", "cornell_low_light", "cornell_spot", "cornell_open_front_sun"]
# Each names its cone settings in full: the quality preset brings its own.
CONFIGURATIONS = {
    "9 cones, 45 degrees (the thesis')": {"voxel.cones": 9},
    "19 cones at 45 degrees": {"voxel.cones": 19, "voxel.cone_angle": 45},
    "19 cones, 37.3 degrees (default)": {"voxel.cones": 19},
    "19 cones, 10 at each pixel (voxel.cone_interleave=1)":
        {"voxel.cones": 19, "voxel.cone_interleave": 1},
    "19 cones moved in elevation (voxel.jitter_elevation=1)":
        {"voxel.cones": 19, "voxel.jitter_elevation": 1},
    "37 cones, 26.6 degrees": {"voxel.cones": 37},
    "37 cones moved in elevation (the quality preset's)":
        {"voxel.cones": 37, "voxel.jitter_elevation": 1},
}
# The quality preset's settings besides its cones (src/bench/BenchSweep.cpp).
QUALITY = {"voxel.resolution": 64, "voxel.trace_scale": 1, "voxel.inject_resolution": 256}
COST_CONFIGURATIONS = {
    "the defaults": ["9 cones, 45 degrees (the thesis')", "19 cones, 37.3 degrees (default)",
                 "19 cones moved in elevation (voxel.jitter_elevation=1)",
                 "37 cones, 26.6 degrees",
                 "37 cones moved in elevation (the quality preset's)"],
    "the quality preset's settings": ["19 cones, 37.3 degrees (default)",
                "37 cones moved in elevation (the quality preset's)"],
}
SPONZA_SUN = ["--camera", "-1.2,1.7,-8,0.8,3.5,10,60", "--light", "none",
              "--light", "dir:0.2,-1,0.3:1,1,1:4"]


def suite_scores(settings):
    """scene -> (relative RMSE, energy) of voxel GI under `settings` from the full suite (its
    "voxel" configuration: the base settings, which `settings` replace)."""
    with tempfile.TemporaryDirectory() as out:
        cmd = [common.BIN, "bench", "--suite", "full", "--scene", ",".join(SCENES),
               "--out-dir", out] + common.settings_args(settings)
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(out, "accuracy.csv")) as f:
            return {row["scene"]: (float(row["rel_rmse_indirect"]),
                                   float(row["energy_indirect"]))
                    for row in csv.DictReader(f) if row["configuration"] == "voxel"}


def accuracy():
    for column, base in (("the defaults", {}), ("the quality preset's settings", QUALITY)):
        scores = {}
        for name, settings in CONFIGURATIONS.items():
            common.progress(f"suite, {column}: {name}")
            scores[name] = suite_scores({**base, **settings})
        print(f"\nvoxel GI, {column} (relative RMSE / energy)\n")
        print("| cones | " + " | ".join(SCENES) + " |")
        print("|---|" + "---|" * len(SCENES))
        for name in CONFIGURATIONS:
            cells = [f"{scores[name][s][0]:.3f} / {scores[name][s][1]:.3f}" for s in SCENES]
            print(f"| {name} | " + " | ".join(cells) + " |")


def trace_ms(scene, camera_args, settings):
    report = common.render_timed(scene, {"render.plan": "adaptive", **settings}, 3, 1,
                                 (interleaved.WIDTH, interleaved.HEIGHT), camera_args,
                                 mode="voxel").report
    return common.pass_medians(report)


def cost(sponza, rounds):
    views = {"Cornell box, inside": (common.CORNELL, ["--camera", interleaved.INSIDE_CAMERA])}
    if os.path.exists(sponza):
        views["Sponza, sun view"] = (sponza, SPONZA_SUN)
    else:
        print(f"(Sponza not found at {sponza}: its row is left out; pass --sponza PATH or set "
              "VOXATLAS_SPONZA)")
    start = interleaved.load_average()
    for column, base in (("the defaults", {}), ("the quality preset's settings", QUALITY)):
        names = COST_CONFIGURATIONS[column]
        reference = names[0]
        print(f"\ncone trace pass at 1280x720, {column}: median ms, and the median of the "
              f"rounds' ratios to {reference} ({rounds} interleaved rounds)\n")
        print("| view | " + " | ".join(names) + " |")
        print("|---|" + "---|" * len(names))
        for view, (scene, camera_args) in views.items():
            configs = {name: (lambda s={**base, **CONFIGURATIONS[name]}:
                              trace_ms(scene, camera_args, s)) for name in names}
            results = interleaved.run_rounds(configs, rounds)
            cells = []
            for name in names:
                ms = interleaved.median(results, name, "voxel/trace")
                ratio, values = interleaved.ratio_median(results, name, reference, "voxel/trace")
                cells.append(f"{ms:.1f} ms, x{ratio:.2f} ({interleaved.spread(values)})")
            print(f"| {view} | " + " | ".join(cells) + " |")
    print(f"\nload average {start} at the start, {interleaved.load_average()} at the end")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    common.add_bin_argument(parser)
    common.add_sponza_argument(parser)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--parts", default="accuracy,cost")
    args = parser.parse_args()
    common.use_binary(args.bin)
    parts = args.parts.split(",")
    if "accuracy" in parts:
        accuracy()
    if "cost" in parts:
        cost(args.sponza, args.rounds)


if __name__ == "__main__":
    main()
