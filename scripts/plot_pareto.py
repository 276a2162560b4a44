#!/usr/bin/python3
"""Draws the speed/accuracy trade of `voxatlas bench`: relative RMSE of the indirect component
against frame time (log x), one subplot per scene, one marker set per series (voxel, atlas,
atlas progressive, vpl), each series' Pareto frontier (the CSV's `pareto` column) as a step line with
its points labelled, and the reference's own noise as a dashed floor line.

usage: plot_pareto.py bench.csv pareto.png
Exit status 0 when the PNG was written, 3 when matplotlib is missing, 2 on bad input.
"""
import csv
import math
import os
import sys

SERIES_STYLE = {
    "direct": ("dimgray", "X"),
    "voxel": ("tab:blue", "o"),
    "atlas": ("tab:orange", "s"),
    "atlas progressive": ("tab:green", "^"),
    "vpl": ("tab:purple", "P"),
}


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        for key in ("frame_ms", "rel_rmse_indirect", "reference_noise_indirect"):
            row[key] = float(row[key])
        row["pareto"] = row["pareto"] == "1"
        row["frames_accumulated"] = int(row["frames_accumulated"])
    return rows


def main():
    if len(sys.argv) != 3:
        print("usage: plot_pareto.py bench.csv pareto.png", file=sys.stderr)
        return 2
    csv_path, png_path = sys.argv[1], sys.argv[2]
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.ticker
    except ImportError:
        print(f"plot_pareto.py: matplotlib is not installed for {sys.executable}", file=sys.stderr)
        return 3
    try:
        rows = read_rows(csv_path)
    except (OSError, KeyError, ValueError) as e:
        print(f"plot_pareto.py: {csv_path}: {e}", file=sys.stderr)
        return 2
    if not rows:
        print(f"plot_pareto.py: {csv_path}: no measured configuration", file=sys.stderr)
        return 2

    scenes = list(dict.fromkeys(row["scene"] for row in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(7.5 * len(scenes), 6.4), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        scene_rows = [r for r in rows if r["scene"] == scene]
        noise = 100 * scene_rows[0]["reference_noise_indirect"]
        errors = sorted(100 * r["rel_rmse_indirect"] for r in scene_rows)
        # Linear error axis to well above the typical point and above 100 % (no GI); worse
        # points are drawn at the top edge and listed, so one broken setting does not
        # flatten everything else.
        y_max = max(min(2.5 * errors[len(errors) // 2], 1.05 * errors[-1]), 120.0, 3.0 * noise)
        off_scale = []
        labelled = []
        series_names = list(dict.fromkeys(r["series"] for r in scene_rows))
        for series in series_names:
            color, marker = SERIES_STYLE.get(series, ("tab:gray", "D"))
            points = [r for r in scene_rows if r["series"] == series]
            inside = [r for r in points if 100 * r["rel_rmse_indirect"] <= y_max]
            ax.scatter([r["frame_ms"] for r in inside],
                       [100 * r["rel_rmse_indirect"] for r in inside],
                       color=color, marker=marker, alpha=0.45, s=30, label=series)
            above = [r for r in points if 100 * r["rel_rmse_indirect"] > y_max]
            ax.scatter([r["frame_ms"] for r in above], [y_max] * len(above), color=color,
                       marker="^", s=40, clip_on=False, zorder=3)
            off_scale += [f"{series} {r['config']}: {100 * r['rel_rmse_indirect']:.0f} %"
                          for r in above]
            frontier = sorted((r for r in points if r["pareto"]), key=lambda r: r["frame_ms"])
            if not frontier:
                continue
            xs = [r["frame_ms"] for r in frontier]
            ys = [100 * r["rel_rmse_indirect"] for r in frontier]
            ax.step(xs, ys, where="post", color=color, linewidth=1.6)
            ax.scatter(xs, ys, color=color, marker=marker, s=55, edgecolors="black",
                       linewidths=0.8, zorder=3)
            labelled.append((series, color, frontier))
        if off_scale:
            ax.text(0.99, 0.02, "off scale (drawn at the top edge):\n" + "\n".join(off_scale),
                    transform=ax.transAxes, ha="right", va="bottom", fontsize=6.5,
                    bbox=dict(boxstyle="round", facecolor="white", alpha=0.85, edgecolor="0.8"))
        ax.set_xscale("log")
        plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
        ax.xaxis.set_major_formatter(plain)
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_ylim(0, y_max)
        # Labels after the axis limits are known: points in the right third of the (log) axis
        # get their label on the left, so it stays inside the plot.
        x_lo, x_hi = (math.log(v) for v in ax.get_xlim())
        for series, color, frontier in labelled:
            if series == "direct":
                continue
            for i, r in enumerate(frontier):
                # Alternate label sides so neighbouring frontier points do not overprint.
                dy = 8 if i % 2 == 0 else -12
                right = (math.log(r["frame_ms"]) - x_lo) / (x_hi - x_lo) > 0.67
                ax.annotate(r["config"], (r["frame_ms"], 100 * r["rel_rmse_indirect"]),
                            textcoords="offset points", xytext=(-5 if right else 5, dy),
                            ha="right" if right else "left", fontsize=7, color=color)
        ax.axhline(100.0, color="dimgray", linestyle=":", linewidth=1)
        ax.text(0.99, 100.0, "100 %: no indirect light at all ", color="dimgray", fontsize=7,
                va="top", ha="right", transform=ax.get_yaxis_transform())
        ax.axhline(noise, color="gray", linestyle="--", linewidth=1)
        ax.text(0.01, noise, f" reference noise {noise:.1f} %", color="gray", fontsize=7,
                va="bottom", transform=ax.get_yaxis_transform())
        width, height = scene_rows[0]["width"], scene_rows[0]["height"]
        ax.set_title(f"{scene} ({width}x{height})")
        ax.set_xlabel("frame time, ms (log; llvmpipe: compare ratios)")
        ax.set_ylabel("relative RMSE of the indirect component, %")
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=8, loc="best",
                  title="outlined + step line: Pareto frontier\nprogressive: error after N frames",
                  title_fontsize=7)
    fig.suptitle("voxatlas bench: indirect-light error against frame time", fontsize=12)
    fig.tight_layout()
    temporary = png_path + ".tmp"
    fig.savefig(temporary, dpi=110, format="png")
    os.replace(temporary, png_path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
