"""Section (b) of docs/results-atlas.md: how long the texture atlas takes to build, cold and
from the disk cache, and the memory it takes, for the Cornell box and Sponza."""
import glob
import os
import re
import shutil
import sys
import tempfile

import numpy

import measure_common as common
from measure_common import mib


def atlas_line(log):
    m = re.search(r"atlas: (\d+) charts for (\d+) triangles in (\d+)\^2 texels, "
                  r"texel ([\d.e+-]+) m, (loaded from the cache in|built in) ([\d.]+) s", log)
    if not m:
        sys.exit("no atlas build line in:\n" + log)
    return {"charts": int(m[1]), "triangles": int(m[2]), "texel": float(m[4]),
            "hit": m[5].startswith("loaded"), "seconds": float(m[6])}


def atlas_memory(memory):
    """Bytes: (atlas-sized layers and G-buffer depth, atlas geometry, screen-sized resolve)."""
    geometry = sum(v for k, v in memory.items() if k in ("atlas/vertices", "atlas/indices"))
    screen = sum(v for k, v in memory.items() if k in ("atlas/indirect", "atlas/resolve_depth"))
    total = sum(v for k, v in memory.items() if k.startswith("atlas/"))
    return total - geometry - screen, geometry, screen


def build_run(path, settings, extra, env=None):
    """One frame at 64x64: enough to build or load the atlas and report its memory."""
    return common.render_timed(path, settings, 1, 0, 64, extra, mode="atlas", env=env)


def measure_build(say, sponza, repeats):
    """(b) atlas build (cold, atlas.cache=0), build + store, and load from a fresh cache."""
    scenes = [("Cornell box", common.CORNELL, [])]
    if os.path.exists(sponza):
        scenes.append(("Sponza", sponza, ["--camera", common.SPONZA_CAMERA]))
    say("## (b) Atlas build time and memory\n")
    say(f"Atlas 1024^2 (the default), gutter 2. 'cold' = `atlas.cache=0`, median of {repeats}")
    say("runs; 'build + store' = the first run against an empty cache directory; 'cached' = the")
    say(f"following runs loading that entry, median of {repeats}. Times are the builder's own")
    say("wall clock (AtlasBuildInfo::seconds). GPU memory is what the atlas allocates")
    say("(memory report); peak RSS is the whole voxatlas process (scene, llvmpipe, builder).\n")
    say("| scene | triangles | charts | texel (m) | cold build s | build + store s | cached load s "
        "| cache file | atlas layers (GPU) | atlas geometry (GPU) | peak RSS cold "
        "| peak RSS cached |")
    say("|---|---|---|---|---|---|---|---|---|---|---|---|")
    atlas = {"atlas.resolution": 1024, "atlas.samples": 1}
    for name, path, extra in scenes:
        cold = [build_run(path, {**atlas, "atlas.cache": 0}, extra) for _ in range(repeats)]
        cache_root = tempfile.mkdtemp(prefix="voxatlas-measure-")
        try:
            env = {**os.environ, "VOXATLAS_CACHE_DIR": cache_root}
            store = build_run(path, {**atlas, "atlas.cache": 1}, extra, env)
            hits = [build_run(path, {**atlas, "atlas.cache": 1}, extra, env)
                    for _ in range(repeats)]
            files = glob.glob(os.path.join(cache_root, "atlas", "*.atlas"))
            file_bytes = sum(os.path.getsize(f) for f in files)
        finally:
            shutil.rmtree(cache_root)
        info = [atlas_line(r.log) for r in cold]
        store_info = atlas_line(store.log)
        hit_info = [atlas_line(r.log) for r in hits]
        if any(i["hit"] for i in info) or store_info["hit"] or not all(i["hit"] for i in hit_info):
            sys.exit(f"{name}: unexpected cache behaviour")
        layers, geometry, _ = atlas_memory(cold[0].report["memory_bytes"])
        say(f"| {name} | {info[0]['triangles']:,} | {info[0]['charts']:,} | {info[0]['texel']:.4g} "
            f"| {numpy.median([i['seconds'] for i in info]):.3f} | {store_info['seconds']:.3f} "
            f"| {numpy.median([i['seconds'] for i in hit_info]):.3f} | {mib(file_bytes)} "
            f"| {mib(layers)} | {mib(geometry)} | {mib(numpy.median([r.rss for r in cold]))} "
            f"| {mib(numpy.median([r.rss for r in hits]))} |")
    say("")
    say("The atlas layers are direct, normal, albedo and lit (RGBA16F) plus position and running")
    say("sums (RGBA32F), 64 B per texel, and a 32-bit depth buffer for the G-buffer draw. The")
    say("geometry is the atlas mesh (vertices split at chart seams). The resolve target scales")
    say("with the output size and is not counted here.\n")
