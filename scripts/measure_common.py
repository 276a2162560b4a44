"""What the scripts/measure_*.py pages share: the repository's paths, running
`voxatlas render` and reading what it writes (timings JSON, PFM images, the peak memory of
the process), the error metrics of src/reference/ImageMetrics.h, the reference cache's
coverage masks, progress on stderr and writing a docs/ page.

The scripts run as `/usr/bin/python3 scripts/measure_X.py` and import this module from
their own folder.
"""
import glob
import json
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass

import numpy

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORNELL = os.path.join(ROOT, "assets", "cornell_box", "cornell_box.gltf")
SPONZA_CAMERA = "0,2,14,0,4,-10,60"
DOCS = os.path.join(ROOT, "docs")
IMAGES = os.path.join(DOCS, "images")
GEOMETRY_COVERAGE = 0.999              # reference::kGeometryCoverage
# The cascade's textures (VoxelTextures) in the memory report.
VOXEL_CASCADE = ("voxel/albedo", "voxel/normal", "voxel/irradiance", "voxel/helper",
                 "voxel/lock", "voxel/pyramid", "voxel/directional")
# The pages these scripts write measure the thesis' allocation, so every render starts from
# render.plan=fixed (the program's default is the adaptive plan); a script's own render.plan
# setting comes later on the command line and wins.
THESIS_PLAN = ["--set", "render.plan=fixed"]
START = time.time()

BIN = os.path.join(ROOT, "build", "voxatlas")   # set from --bin by use_binary()


def progress(message):
    print(f"[{time.time() - START:6.0f} s] {message}", file=sys.stderr, flush=True)


def add_bin_argument(parser):
    parser.add_argument("--bin", default=BIN, help="voxatlas executable (default build/voxatlas)")


def add_sponza_argument(parser):
    parser.add_argument("--sponza", default=os.environ.get(
        "VOXATLAS_SPONZA", os.path.join(ROOT, "..", "shared", "assets", "sponza", "Sponza.gltf")))


def require_sponza(path):
    """Exits with one line saying how to provide Sponza when it is not at `path`."""
    if not os.path.exists(path):
        print(f"Sponza not found at {path}: pass --sponza PATH or set VOXATLAS_SPONZA",
              file=sys.stderr)
        sys.exit(2)


def sponza_picture_arguments(doc, picture, flags=()):
    """The command line of a script that measures Sponza and draws one picture (--bin,
    --sponza, --picture, default docs/images/`picture`, and the boolean `flags`: (name, help)
    pairs), parsed; the binary taken into use and Sponza required."""
    import argparse
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    add_bin_argument(parser)
    add_sponza_argument(parser)
    parser.add_argument("--picture", default=os.path.join(IMAGES, picture))
    for name, text in flags:
        parser.add_argument(name, action="store_true", help=text)
    args = parser.parse_args()
    use_binary(args.bin)
    require_sponza(args.sponza)
    return args


def use_binary(path):
    """Makes `path` the voxatlas that run() starts; exits when it is missing."""
    global BIN
    BIN = os.path.abspath(path)
    if not os.path.exists(BIN):
        sys.exit(f"{BIN} not found (bash scripts/build.sh, or --bin)")


def run(cmd, env=None):
    """Runs voxatlas; returns (stderr text, peak resident set of the process in bytes)."""
    progress(" ".join(os.path.basename(c) if i == 0 else c for i, c in enumerate(cmd)))
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            env=env)
    err = proc.stderr.read()
    proc.stderr.close()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        sys.exit(f"voxatlas failed ({proc.returncode}):\n{err}")
    return err, usage.ru_maxrss * 1024


def settings_args(settings):
    out = []
    for key, value in settings.items():
        out += ["--set", f"{key}={value}"]
    return out


def size_args(size):
    """--width/--height of a square `size` or a (width, height) pair."""
    width, height = (size, size) if isinstance(size, int) else size
    return ["--width", str(width), "--height", str(height)]


@dataclass
class Render:
    log: str                # voxatlas' stderr
    rss: int                # peak resident set of the process, bytes
    image: object = None    # the --hdr image (linear, float64 rows top-down), if asked for
    report: dict = None     # the --timings report, if asked for


def render(scene, options, out_png=None, hdr=False, timings=False, env=None):
    """`voxatlas render scene options`, its PNG to out_png (else thrown away), with the HDR
    image and the timings report read back when asked for."""
    with tempfile.TemporaryDirectory() as tmp:
        pfm = os.path.join(tmp, "o.pfm")
        report = os.path.join(tmp, "t.json")
        cmd = [BIN, "render", scene, "--out", out_png or os.path.join(tmp, "o.png")] + THESIS_PLAN
        cmd += ["--hdr", pfm] if hdr else []
        cmd += ["--timings", report] if timings else []
        log, rss = run(cmd + list(options), env)
        return Render(log, rss, read_pfm(pfm) if hdr else None,
                      json.load(open(report)) if timings else None)


def render_indirect(scene, mode, settings, size, out_png=None, extra=(), timings=False):
    """The indirect component in `mode` as a linear HDR image (Render.image)."""
    return render(scene, ["--mode", mode, "--output", "indirect"] + size_args(size) +
                  settings_args(settings) + list(extra), out_png, hdr=True, timings=timings)


def render_timed(scene, settings, frames, warmup, size, extra=(), mode=None, out_png=None,
                 env=None):
    """A render timed over `frames` frames after `warmup` ones (Render.report)."""
    options = (["--mode", mode] if mode else []) + size_args(size) + [
        "--set", f"render.frames={frames}", "--set", f"render.warmup={warmup}"]
    return render(scene, options + settings_args(settings) + list(extra), out_png,
                  timings=True, env=env)


def pass_medians(report):
    """Median ms per pass of a timings report, and 'frame' = their sum."""
    times = {p["name"]: p["gpu_ms_median"] for p in report["passes"]}
    times["frame"] = sum(times.values())
    return times


def voxel_cascade_bytes(memory):
    return sum(v for k, v in memory.items() if k in VOXEL_CASCADE)


def read_pfm(path):
    with open(path, "rb") as f:
        f.readline()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = numpy.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(h, w, 3)[::-1].astype(numpy.float64)


def reference_cache_dir():
    """ReferenceCache::defaultDirectory()."""
    if os.environ.get("VOXATLAS_CACHE_DIR"):
        return os.environ["VOXATLAS_CACHE_DIR"]
    if os.environ.get("XDG_CACHE_HOME"):
        return os.path.join(os.environ["XDG_CACHE_HOME"], "voxatlas", "reference")
    return os.path.join(os.path.expanduser("~"), ".cache", "voxatlas", "reference")


def reference_mask(indirect):
    """Geometry pixels (coverage > 0.999, as ImageMetrics.h) of the cached reference whose
    indirect image equals `indirect`; the CLI writes no coverage image, the cache does."""
    h, w, _ = indirect.shape
    for meta in glob.glob(os.path.join(reference_cache_dir(), "*.json")):
        info = json.load(open(meta))
        stem = meta[:-len(".json")]
        if info.get("width") != w or info.get("height") != h:
            continue
        if not os.path.exists(stem + ".coverage.pfm"):
            continue
        if numpy.array_equal(read_pfm(stem + ".indirect.pfm"), indirect):
            return read_pfm(stem + ".coverage.pfm")[..., 0] > GEOMETRY_COVERAGE
    progress("reference coverage not found in the cache: counting every pixel")
    return numpy.ones((h, w), dtype=bool)


def errors(image, reference, mask=None):
    """Relative RMSE and mean-energy ratio over the mask's pixels, all of them without one
    (ImageMetrics.h)."""
    if mask is None:
        mask = numpy.ones(reference.shape[:2], dtype=bool)
    a, b = image[mask], reference[mask]
    return (float(((a - b) ** 2).sum() / (b ** 2).sum()) ** 0.5, float(a.sum() / b.sum()))


def write_png(path, rgb, scale=1):
    """rgb: float rows top-down in [0, 1], written as an 8-bit PNG, each pixel `scale` x
    `scale` (nearest) so small error images stay readable."""
    from PIL import Image
    pixels = (numpy.clip(rgb, 0.0, 1.0) * 255.0 + 0.5).astype(numpy.uint8)
    pixels = pixels.repeat(scale, axis=0).repeat(scale, axis=1)
    Image.fromarray(pixels, "RGB").save(path)


def mib(n):
    return f"{n / 2**20:.1f} MiB" if n >= 2**20 else f"{n / 2**10:.1f} KiB"


def pyplot():
    """matplotlib.pyplot drawing to files only (no display on this machine)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def write_page(name, lines):
    """Writes docs/<name> from its lines."""
    with open(os.path.join(DOCS, name), "w") as out:
        out.write("\n".join(lines) + "\n")
