#!/usr/bin/python3
"""The diffuse cone sets of voxel GI (voxel.cones, voxel.cone_interleave, voxel.cone_angle;
src/gi/voxel/ConeSet.h) on the scoreboard and in time:

- accuracy: `voxatlas bench --suite full` on the Cornell box, its low light, its spot and its
  open front, voxel GI at the defaults and the quality preset, for each cone configuration
  (relative RMSE / energy of the indirect term against the path tracer);
- cost: the cone trace pass (median ms over 3 frames) of each configuration at 1280x720 and
  the program's defaults, inside the Cornell box and in Sponza's sun view, in interleaved
  rounds; ratios to the thesis' 9 cones within each round, their median quoted.

Usage: /usr/bin/python3 scripts/measure_cones.py [--bin build/voxatlas] [--sponza PATH]
       [--rounds 3] [--parts accuracy,cost]
Prints markdown tables (docs/accuracy-analysis.md, "Nineteen cones"); about 10 minutes.
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
CONFIGURATIONS = {
    "9 cones, 45 degrees (the thesis')": {"voxel.cones": 9},
    "19 cones at 45 degrees": {"voxel.cone_angle": 45},
    "19 cones, 37.3 degrees (default)": {},
    "19 cones, 37.3 degrees, 10 at each pixel (voxel.cone_interleave=1)":
        {"voxel.cone_interleave": 1},
}
SPONZA_SUN = ["--camera", "-1.2,1.7,-8,0.8,3.5,10,60", "--light", "none",
              "--light", "dir:0.2,-1,0.3:1,1,1:4"]


def suite_scores(settings):
    """(scene, configuration) -> (relative RMSE, energy) of voxel GI from the full suite."""
    with tempfile.TemporaryDirectory() as out:
        cmd = [common.BIN, "bench", "--suite", "full", "--scene", ",".join(SCENES),
               "--out-dir", out] + common.settings_args(settings)
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(out, "accuracy.csv")) as f:
            return {(row["scene"], row["configuration"]):
                    (float(row["rel_rmse_indirect"]), float(row["energy_indirect"]))
                    for row in csv.DictReader(f) if row["configuration"].startswith("voxel")}


def accuracy():
    scores = {}
    for name, settings in CONFIGURATIONS.items():
        common.progress(f"suite: {name}")
        scores[name] = suite_scores(settings)
    for configuration in ("voxel", "voxel quality"):
        print(f"\n{configuration} (relative RMSE / energy)\n")
        print("| cones | " + " | ".join(SCENES) + " |")
        print("|---|" + "---|" * len(SCENES))
        for name in CONFIGURATIONS:
            cells = [f"{scores[name][(s, configuration)][0]:.3f} / "
                     f"{scores[name][(s, configuration)][1]:.3f}" for s in SCENES]
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
    names = list(CONFIGURATIONS)
    thesis = names[0]
    start = interleaved.load_average()
    print("\ncone trace pass at 1280x720, the program's defaults: median ms, and the median of "
          f"the rounds' ratios to the thesis' 9 cones ({rounds} interleaved rounds)\n")
    print("| view | " + " | ".join(names) + " |")
    print("|---|" + "---|" * len(names))
    for view, (scene, camera_args) in views.items():
        configs = {name: (lambda s=settings: trace_ms(scene, camera_args, s))
                   for name, settings in CONFIGURATIONS.items()}
        results = interleaved.run_rounds(configs, rounds)
        cells = []
        for name in names:
            ms = interleaved.median(results, name, "voxel/trace")
            ratio, values = interleaved.ratio_median(results, name, thesis, "voxel/trace")
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
