#!/usr/bin/env python3
"""Compares what two `voxatlas bench` runs measured, configuration by configuration.

A change that should not alter any image (a restructuring, a faster pass) must leave every
accuracy figure where it was; frame times move with the machine's load, so they are shown as
the ratio of the two runs next to each other, never as a pass/fail.

usage: compare_bench.py BEFORE/bench.csv AFTER/bench.csv [--tolerance T]

Prints a markdown table per scene (relative RMSE of the indirect and final image, indirect
energy ratio, before and after, and the frame-time ratio after/before) and a last line saying
whether every accuracy figure agrees within T (absolute, default 0.002: the run-to-run spread
of voxel GI on llvmpipe, whose voxelization averages under atomics in no fixed order). Exits 1
when one does not, or when a configuration is missing from either run.
"""
import argparse
import csv
import sys

ACCURACY = ("rel_rmse_indirect", "rel_rmse_final", "energy_ratio_indirect")


def read_rows(path):
    with open(path, newline="") as stream:
        return {(row["scene"], row["mode"], row["config"]): row for row in csv.DictReader(stream)}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--tolerance", type=float, default=0.002)
    args = parser.parse_args(argv[1:])
    try:
        before, after = read_rows(args.before), read_rows(args.after)
    except (OSError, KeyError, csv.Error) as error:
        print(f"compare_bench: {error}", file=sys.stderr)
        return 2

    missing = sorted(set(before) ^ set(after))
    worst = 0.0
    scenes = sorted({key[0] for key in before if key in after})
    for scene in scenes:
        print(f"\n### {scene}\n")
        print("| mode | configuration | indirect RMSE before / after | final RMSE before / after "
              "| indirect energy before / after | frame time after / before |")
        print("|---|---|---|---|---|---|")
        for key in sorted(k for k in before if k[0] == scene and k in after):
            old, new = before[key], after[key]
            cells = []
            for column in ACCURACY:
                a, b = float(old[column]), float(new[column])
                worst = max(worst, abs(a - b))
                cells.append(f"{a:.4f} / {b:.4f}")
            ratio = float(new["frame_ms"]) / max(float(old["frame_ms"]), 1e-9)
            print(f"| {key[1]} | {key[2]} | " + " | ".join(cells) + f" | ×{ratio:.2f} |")
    print()
    for key in missing:
        side = "before" if key in before else "after"
        print(f"only {side}: {' / '.join(key)}")
    agrees = worst <= args.tolerance and not missing
    print(f"largest accuracy difference {worst:.4g} over {sum(1 for k in before if k in after)} "
          f"configurations: {'within' if agrees else 'OUTSIDE'} {args.tolerance:g}")
    return 0 if agrees else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
