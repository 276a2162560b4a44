#!/usr/bin/python3
"""The line space's N x depth sweep (shadow.method=linespace, linespace.n, linespace.depth),
written to docs/results-linespace-sweep.md: for each shape, on the emissive Cornell box
(assets/cornell_box/cornell_box_emissive.gltf, lit only by its ceiling panel) at 25 rays per
pixel, 96x96 with render.supersample=4:
- the direct light's error against the path tracer at 1024 spp (relative RMSE, energy) on the
  surfaces the panel lights, as scripts/measure_shadows.py measures it;
- the build time and the memory of the line space (the --timings report's `shadows`);
- the forward pass (where the rays are cast) against the BVH's, rendered right after it, as a
  ratio within the pair.
Shapes over the resource budget are refused by voxatlas (exit 2) and listed with its line;
builds that take longer than --timeout seconds are stopped and listed as such.

Usage: /usr/bin/python3 scripts/measure_linespace_sweep.py [--bin build/voxatlas]
       [--n 4,5,6,8,10] [--depth 2,3,4] [--timeout 600]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_common as common  # noqa: E402

EMISSIVE = os.path.join(common.ROOT, "assets", "cornell_box", "cornell_box_emissive.gltf")
BASE = {"material.specular": 0, "shadow.rays": 25}
SIZE = 96


def reference_and_mask():
    size = common.size_args(SIZE)
    settings = common.settings_args({**BASE, "reference.spp": 1024})
    direct = common.render(EMISSIVE, ["--mode", "reference", "--output", "direct"] + size + settings,
                           hdr=True).image
    indirect = common.render(EMISSIVE, ["--mode", "reference", "--output", "indirect"] + size +
                             settings, hdr=True).image
    return direct, common.reference_mask(indirect) & (direct.max(axis=2) < 2.0)


def render_method(settings, timeout):
    """(image, timings report) or (None, reason) for a refused or stopped render."""
    with tempfile.TemporaryDirectory() as tmp:
        pfm, report = os.path.join(tmp, "o.pfm"), os.path.join(tmp, "t.json")
        cmd = [common.BIN, "render", EMISSIVE, "--out", os.path.join(tmp, "o.png"), "--hdr", pfm,
               "--timings", report, "--output", "direct"] + common.THESIS_PLAN
        cmd += common.size_args(SIZE) + common.settings_args(
            {**BASE, "render.supersample": 4, "render.frames": 3, "render.warmup": 1, **settings})
        common.progress(" ".join(cmd[1:]))
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, f"stopped after {timeout} s"
        if proc.returncode == 2:
            return None, "refused: " + proc.stderr.strip().splitlines()[-1]
        if proc.returncode != 0:
            sys.exit(f"voxatlas failed ({proc.returncode}):\n{proc.stderr}")
        return common.read_pfm(pfm), json.load(open(report))


def forward_ms(report):
    return next(p["gpu_ms_median"] for p in report["passes"] if p["name"] == "render/forward")


def main():
    parser = argparse.ArgumentParser()
    common.add_bin_argument(parser)
    parser.add_argument("--n", default="4,5,6,8,10")
    parser.add_argument("--depth", default="2,3,4")
    parser.add_argument("--timeout", type=int, default=600)
    args = parser.parse_args()
    common.use_binary(args.bin)
    load = open("/proc/loadavg").read().split()[0]
    reference, lit = reference_and_mask()
    lines = ["# Line space: the N x depth sweep", "",
             "Made by `/usr/bin/python3 scripts/measure_linespace_sweep.py` "
             f"({time.strftime('%Y-%m-%d %H:%M')}, load average {load} at the start; llvmpipe "
             "on a shared 2-core machine). The emissive Cornell box at 25 rays per pixel, "
             f"{SIZE}x{SIZE} with render.supersample=4, against the path tracer at 1024 spp over "
             f"the {int(lit.sum())} pixels the panel lights. The forward pass (median of 3 frames "
             "after 1) is compared with the BVH's in a render made right after it. N-tree "
             "nodes hold 15 N^4 shafts; the paper's choice is LS(6,3) (SEEDS.md section 3).", "",
             "| N | depth | leaf cells per axis | relative RMSE | energy | build (ms) | memory | "
             "forward / bvh |", "|---|---|---|---|---|---|---|---|"]
    for n in [int(v) for v in args.n.split(",")]:
        for depth in [int(v) for v in args.depth.split(",")]:
            image, report = render_method({"shadow.method": "linespace", "linespace.n": n,
                                           "linespace.depth": depth}, args.timeout)
            cells = f"{n ** depth:,}"
            if image is None:
                lines.append(f"| {n} | {depth} | {cells} | {report} | | | | |")
                continue
            _, bvh = render_method({"shadow.method": "bvh"}, args.timeout)
            rmse, energy = common.errors(image, reference, lit)
            shadows = report["shadows"]
            lines.append(f"| {n} | {depth} | {cells} | {rmse:.3f} | {energy:.3f} | "
                         f"{shadows['build_ms']:.0f} | {common.mib(shadows['bytes'])} | "
                         f"x{forward_ms(report) / forward_ms(bvh):.2f} |")
            print(lines[-1], flush=True)
    lines += ["", f"Load average at the end: {open('/proc/loadavg').read().split()[0]}."]
    common.write_page("results-linespace-sweep.md", lines)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
