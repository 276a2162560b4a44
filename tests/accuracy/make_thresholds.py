#!/usr/bin/env python3
"""Writes tests/accuracy/AccuracyThresholds.inc from the accuracy.csv of a
`voxatlas bench --suite quick` run: each score's threshold is the measured distance from the
truth plus a margin for the run-to-run spread (10 % of the value, plus 0.01).

Run it after a change that improves scores, to hold the suite to them (a score that still
passes its threshold keeps it or tightens it):

    build/voxatlas bench --suite quick --out-dir /tmp/suite
    python3 tests/accuracy/make_thresholds.py /tmp/suite/accuracy.csv

Given the accuracy.csv of several runs it takes each score's worst: voxel GI's stochastic
rounding (voxelize.frag) moves the quick form's energies by up to 0.006 from run to run, and
a threshold tightened on one run's luck fails the next.

It refuses to loosen a threshold (a score that got worse is a regression to fix, not a new
threshold) unless --accept-worse names the reason, which goes into the file.
"""
import argparse
import csv
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "AccuracyThresholds.inc")
CONFIGURATIONS = ("voxel", "voxel quality", "atlas", "atlas converged", "vpl")


def margin(value):
    return round(value * 1.10 + 0.01, 3)


def read_accepted():
    """The reasons earlier runs gave for thresholds they let get worse: they stay with them."""
    if not os.path.exists(OUT):
        return []
    return [line for line in open(OUT).read().splitlines() if line.startswith("// Accepted worse:")]


def read_existing():
    if not os.path.exists(OUT):
        return {}
    existing = {}
    pattern = re.compile(r'\{"([^"]+)", "([^"]+)", ([0-9.]+), ([0-9.]+)(?:, ([0-9.]+))?\}')
    for match in pattern.finditer(open(OUT).read()):
        scene, configuration, rmse, energy, leak = match.groups()
        existing[(scene, configuration)] = (float(rmse), float(energy),
                                            float(leak) if leak else None)
    return existing


def worst_over_runs(paths):
    """{(scene, configuration): (rel. RMSE, |energy - 1|, leak)}, each the worst of the runs."""
    worst = {}
    for path in paths:
        for row in csv.DictReader(open(path)):
            if row["configuration"] not in CONFIGURATIONS or row["available"] != "1":
                continue
            key = (row["scene"], row["configuration"])
            if row["kind"] == "leak-dark":
                measured = (0.0, 0.0, float(row["leak"]))
            else:
                measured = (float(row["rel_rmse_indirect"]),
                            abs(float(row["energy_indirect"]) - 1.0), None)
            if key in worst:
                measured = tuple(None if m is None else max(m, w)
                                 for m, w in zip(measured, worst[key]))
            worst[key] = measured
    return worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("csv", nargs="+", help="accuracy.csv of one or more quick runs")
    parser.add_argument("--accept-worse", metavar="REASON")
    args = parser.parse_args()
    existing = read_existing()
    accepted = read_accepted()
    rows, looser = [], []
    for key, measured in worst_over_runs(args.csv).items():
        new = tuple(None if m is None else margin(m) for m in measured)
        old = existing.get(key)
        if old:
            # A score that still passes keeps its threshold, or tightens it; one that fails
            # it got worse, and only that score takes the new margin.
            if any(m is not None and o is not None and m > o for m, o in zip(measured, old)):
                looser.append(f"{key[0]} / {key[1]}: measured {measured}, thresholds {old}")
            new = tuple(n if o is None or (m is not None and m > o) else min(n, o)
                        for n, o, m in zip(new, old, measured))
        rows.append((key, new))
    if looser and not args.accept_worse:
        sys.exit("worse than the current thresholds (fix the regression, or "
                 "--accept-worse REASON):\n  " + "\n  ".join(looser))
    lines = ["// Written by tests/accuracy/make_thresholds.py from a `voxatlas bench --suite quick`",
             "// run; do not edit by hand. {scene, configuration, max rel. RMSE, max |energy - 1|",
             "// [, max leak]}"] + accepted
    if looser:
        lines.append(f"// Accepted worse: {args.accept_worse}")
    lines.append("const Threshold kThresholds[] = {")
    for (scene, configuration), (rmse, energy, leak) in rows:
        tail = f", {leak}" if leak is not None else ""
        lines.append(f'        {{"{scene}", "{configuration}", {rmse}, {energy}{tail}}},')
    lines.append("};")
    open(OUT, "w").write("\n".join(lines) + "\n")
    print(f"wrote {OUT}: {len(rows)} thresholds")


if __name__ == "__main__":
    main()
