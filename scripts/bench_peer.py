#!/usr/bin/python3
"""Times voxatlas against the simplest widely used voxel cone tracer, Friduric's demo
(github.com/Friduric/voxel-cone-tracing: one 64^3 volume, 9 diffuse cones and 1 shadow
cone per pixel at full resolution, every pass every frame), interleaved in one run, and
writes the ratios to docs/results-performance.md (its "Against the peer" section).

Both run at 1280x720 with the camera inside the Cornell box, so every pixel traces cones.
- The peer runs under Xvfb and logs "delta: S, frame count: N" every 5 frames; its frame
  time is the wall time between two logs over the frames between them (the first log,
  holding start-up, is skipped).
- voxatlas runs `render --timings` (per-pass times with glFinish on llvmpipe) and its frame
  is the sum of the passes' medians.
Per pixel-cone: a frame over (traced pixels x cones): the peer 1280x720 x 10, voxatlas
(1280 s x 720 s) x 9 at trace scale s.

Usage: /usr/bin/python3 scripts/bench_peer.py [--peer DIR] [--peer-build DIR] [--rounds N]
       [--bin build/voxatlas]
"""
import argparse
import os
import queue
import re
import signal
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import interleaved as il  # noqa: E402
import measure_common as common  # noqa: E402

PEER_CONES = 10     # 9 diffuse + 1 shadow cone per pixel
# The default 19 diffuse cones at every traced pixel (src/gi/voxel/ConeSet.h).
OUR_CONES = 19
LOG_LINE = re.compile(r"delta: ([0-9.]+), frame count: (\d+)")
SECTION_BEGIN = "<!-- bench_peer.py: begin -->"
SECTION_END = "<!-- bench_peer.py: end -->"


def default_peer_source():
    """$VOXATLAS_PEER, else shared/peers/friduric beside the checkout or one level up."""
    candidates = [os.path.join(common.ROOT, *up, "shared", "peers", "friduric")
                  for up in (("..",), ("..", ".."))]
    found = [c for c in candidates if os.path.exists(os.path.join(c, "build.sh"))]
    return os.environ.get("VOXATLAS_PEER", found[0] if found else candidates[0])


def build_peer(source, out):
    vct = os.path.join(out, "vct")
    if not os.path.exists(vct):
        common.progress(f"building the peer into {out}")
        subprocess.run(["bash", os.path.join(source, "build.sh"), out], check=True)
    return vct


def peer_frame(build_dir, logs, timeout=600.0):
    """Median seconds per frame of the peer over `logs` intervals between its logs."""
    cmd = ["xvfb-run", "-a", "-s", f"-screen 0 {il.WIDTH}x{il.HEIGHT}x24", "./vct"]
    common.progress("peer: " + " ".join(cmd))
    proc = subprocess.Popen(cmd, cwd=build_dir, stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True, start_new_session=True)
    lines = queue.Queue()
    threading.Thread(target=lambda: [lines.put(line) for line in proc.stdout],
                     daemon=True).start()
    marks = []   # (wall time, frame count) per log
    deadline = time.time() + timeout
    try:
        while len(marks) < logs + 1 and time.time() < deadline:
            try:
                line = lines.get(timeout=5.0)
            except queue.Empty:
                if proc.poll() is not None:
                    break
                continue
            match = LOG_LINE.search(line)
            if match:
                marks.append((time.time(), int(match.group(2))))
    finally:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait()
    if len(marks) < 2:
        sys.exit("the peer logged fewer than two frame counts")
    per_frame = [(t1 - t0) / (n1 - n0) for (t0, n0), (t1, n1) in zip(marks, marks[1:])]
    return {"frame": 1000.0 * sorted(per_frame)[len(per_frame) // 2]}


def configurations(args, peer_dir):
    # The resolution ratios trace every pixel of their trace each frame (no trace reuse); the
    # default frame is a still camera's steady state (trace reuse traces a quarter).
    full = {"voxel.trace_scale": 1, "voxel.cache": 0, "voxel.trace_reuse": 0}
    return {
        "peer": lambda: peer_frame(peer_dir, args.peer_logs),
        "full": lambda: il.voxatlas_frame(full, args.frames, 1),
        "default": lambda: il.voxatlas_frame({}, args.frames, 2),
        "half": lambda: il.voxatlas_frame({"voxel.trace_reuse": 0}, args.frames, 2),
        "quarter": lambda: il.voxatlas_frame({"voxel.trace_scale": 0.25,
                                              "voxel.trace_reuse": 0}, args.frames, 2),
    }


def traced_pixels(scale):
    return round(il.WIDTH * scale) * round(il.HEIGHT * scale)


def report(results, args, load_start, load_end):
    peer_cones = il.WIDTH * il.HEIGHT * PEER_CONES
    full_cones = traced_pixels(1.0) * OUR_CONES
    cone_scale = peer_cones / full_cones
    rows = []

    def row(label, value, values, target):
        rows.append(f"| {label} | **x{value:.3f}** | {il.spread(values)} | {target} |")

    row("per pixel-cone: full-resolution frame, every pass every frame / peer frame",
        *il.ratio_median(results, "full", "peer", "frame", scale=cone_scale), "<= x0.67")
    row("per pixel-cone: full-resolution trace pass alone / peer frame",
        *il.ratio_median(results, "full", "peer", "voxel/trace", "frame", scale=cone_scale), "-")
    row("default frame / peer frame (whole frames)",
        *il.ratio_median(results, "default", "peer", "frame"), "<= x0.25")
    row("trace pass: scale 1/2 (default scale, every pixel traced) / full",
        *il.ratio_median(results, "half", "full", "voxel/trace"), "<= x0.27")
    row("default frame's trace pass (a quarter of the 1/2 scale traced) / full",
        *il.ratio_median(results, "default", "full", "voxel/trace"), "-")
    row("trace pass: scale 1/4 / full",
        *il.ratio_median(results, "quarter", "full", "voxel/trace"), "<= x0.07")
    ms = {name: il.median(results, name, "frame") for name in results}
    trace = {name: il.median(results, name, "voxel/trace") for name in results if name != "peer"}
    lines = [
        SECTION_BEGIN,
        "## Against the peer (Friduric's voxel cone tracing demo)\n",
        "Written by `/usr/bin/python3 scripts/bench_peer.py "
        f"--rounds {args.rounds} --frames {args.frames}` "
        f"(after `bash scripts/build.sh`); {args.rounds} interleaved rounds, each: the peer "
        f"({args.peer_logs} x 5 frames after its first log), voxatlas at full trace "
        "resolution with voxel.cache=0 and no trace reuse (every pass and every pixel every "
        "frame), at the defaults (trace scale 1/2, static cache on, trace reuse: a still "
        "camera's frame traces one pixel of each 2x2 block), at trace scale 1/2 and 1/4 with "
        f"every pixel traced, {args.frames} frames each after 1-2 warm-up frames. "
        "1280x720, both cameras inside the Cornell box "
        f"(voxatlas `--camera {il.INSIDE_CAMERA}`, render.plan=adaptive, the default). "
        f"Load average (2 cores) at the start {load_start}, at the end {load_end}.\n",
        "Ratios within a round, median over the rounds (min-max beside it). Per pixel-cone "
        f"divides each frame by its traced pixels x cones: the peer {PEER_CONES} cones "
        f"(9 diffuse + 1 shadow) at every pixel, voxatlas {OUR_CONES} at every traced pixel.\n",
        "| ratio | median | rounds | target |",
        "|---|---|---|---|",
        *rows,
        "",
        "Medians in ms (absolute times depend on the load; only the ratios above count): "
        f"peer frame {ms['peer']:.0f}; voxatlas full-resolution frame {ms['full']:.0f} "
        f"(trace {trace['full']:.0f}), default frame {ms['default']:.0f} "
        f"(trace {trace['default']:.0f}), trace at 1/2 {trace['half']:.0f}, "
        f"at 1/4 {trace['quarter']:.0f}.",
        SECTION_END,
    ]
    return lines


def write_section(lines):
    path = os.path.join(common.DOCS, "results-performance.md")
    text = open(path).read() if os.path.exists(path) else "# Performance\n\n"
    section = "\n".join(lines)
    if SECTION_BEGIN in text and SECTION_END in text:
        head, rest = text.split(SECTION_BEGIN, 1)
        text = head + section + rest.split(SECTION_END, 1)[1]
    else:
        text = text.rstrip("\n") + "\n\n" + section + "\n"
    with open(path, "w") as out:
        out.write(text)
    common.progress(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    common.add_bin_argument(parser)
    parser.add_argument("--peer", default=default_peer_source(),
                        help="the prepared peer's source (holds build.sh)")
    parser.add_argument("--peer-build", default=os.path.join(common.ROOT, "build", "peer"))
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--frames", type=int, default=3, help="timed voxatlas frames per run")
    parser.add_argument("--peer-logs", type=int, default=2,
                        help="intervals of 5 peer frames per run")
    parser.add_argument("--print-only", action="store_true", help="do not write the page")
    args = parser.parse_args()
    common.use_binary(args.bin)
    peer_dir = os.path.dirname(build_peer(os.path.abspath(args.peer),
                                          os.path.abspath(args.peer_build)))
    load_start = il.load_average()
    results = il.run_rounds(configurations(args, peer_dir), args.rounds)
    lines = report(results, args, load_start, il.load_average())
    print("\n".join(lines))
    if not args.print_only:
        write_section(lines)


if __name__ == "__main__":
    main()
