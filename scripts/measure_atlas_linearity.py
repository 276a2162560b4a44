"""Section (a) of docs/results-atlas.md, second half: fits the table's gather and frame times
to a * samples * texels + b (and with a per-texel term), judges them against the issue's 10%
linearity target next to the thesis' own frame times, and draws docs/images/atlas_timing.png."""
import math
import os

import numpy

import measure_common as common
from measure_atlas_table import OTHERS_TOLERANCE, SEED_FPS, TABLE_SAMPLES

LINEARITY_TOLERANCE = 0.10             # the issue: cost linear in samples and texels within 10%


def relative_fit(x, y):
    """a, b minimising sum ((a x + b - y) / y)^2: the fit whose relative residuals we judge."""
    x, y = numpy.asarray(x, float), numpy.asarray(y, float)
    design = numpy.stack([x / y, 1.0 / y], axis=1)
    (a, b), *_ = numpy.linalg.lstsq(design, numpy.ones_like(y), rcond=None)
    return a, b, (a * x + b - y) / y


def over_tolerance(residuals):
    return int((abs(residuals) > LINEARITY_TOLERANCE).sum())


def say_linear_fits(say, work, gather, frame):
    """ms = a * samples * texels + b for ours and the thesis' frame times; returns our
    residuals per series, and the thesis' fixed part b with its residuals per row."""
    say("### Linearity: ms = a * samples * texels + b\n")
    say("Fitted by least squares on relative residuals (the target is a relative one) over the")
    say("12 rows; texels = resolution^2 (every atlas texel runs the gather fragment; empty ones")
    say("discard after one fetch). The thesis' frame times (1000 / fps, 11 rows) are fitted the")
    say("same way for comparison.\n")
    say("| series | a (ns per sample-texel) | b (ms) | largest residual | rows over 10% |")
    say("|---|---|---|---|---|")
    fits = {}
    for name, values in (("gather (ours)", gather), ("frame (ours)", frame)):
        fa, fb, res = relative_fit(work, values)
        fits[name] = res
        say(f"| {name} | {fa * 1e6:.3f} | {fb:.1f} | {100 * abs(res).max():.1f}% "
            f"| {over_tolerance(res)} of {len(res)} |")
    seed_keys = [(r, s) for r in SEED_FPS for s in SEED_FPS[r]]
    sa, sb, sres = relative_fit([s * r * r for r, s in seed_keys],
                                [1000.0 / SEED_FPS[r][s] for r, s in seed_keys])
    say(f"| frame (thesis, 8800 GT) | {sa * 1e6:.3f} | {sb:.1f} | {100 * abs(sres).max():.1f}% "
        f"| {over_tolerance(sres)} of {len(sres)} |")
    say("")
    return fits, sb, dict(zip(seed_keys, sres))


def say_per_texel_fits(say, work, texels, gather, frame):
    """A per-texel term as well (the gather's fetch-and-discard of every texel, the G-buffer,
    dilation): ms = a * samples * texels + c * texels + b. Returns the residuals per series."""
    design = numpy.stack([numpy.array(work, float), numpy.array(texels, float),
                          numpy.ones(len(work))], axis=1)
    extra = {}
    for name, values in (("gather", gather), ("frame", frame)):
        y = numpy.array(values, float)
        coef, *_ = numpy.linalg.lstsq(design / y[:, None], numpy.ones_like(y), rcond=None)
        extra[name] = (coef, (design @ coef - y) / y)
    say("With a per-texel term, ms = a * samples * texels + c * texels + b (not the issue's")
    say("model; shown to separate what grows with texels alone):\n")
    say("| series | a (ns per sample-texel) | c (ns per texel) | b (ms) | largest residual "
        "| rows over 10% |")
    say("|---|---|---|---|---|---|")
    for name, (coef, res) in extra.items():
        say(f"| {name} | {coef[0] * 1e6:.3f} | {coef[1] * 1e6:.1f} | {coef[2]:.1f} "
            f"| {100 * abs(res).max():.1f}% | {over_tolerance(res)} of 12 |")
    say("")
    return {name: res for name, (_, res) in extra.items()}


def say_residuals(say, keys, fits, extra, seed_res):
    say("Residuals (fit - measured) / measured per row:\n")
    say("| atlas | samples | gather | frame | gather, with c | frame, with c | thesis frame |")
    say("|---|---|---|---|---|---|---|")
    for i, (r, s) in enumerate(keys):
        t = f"{100 * seed_res[r, s]:+.1f}%" if (r, s) in seed_res else "-"
        say(f"| {r}^2 | {s} | {100 * fits['gather (ours)'][i]:+.1f}% "
            f"| {100 * fits['frame (ours)'][i]:+.1f}% | {100 * extra['gather'][i]:+.1f}% "
            f"| {100 * extra['frame'][i]:+.1f}% | {t} |")
    say("")


def say_verdict(say, timings, fits, fixed_part, seed_fixed_part):
    """The target's verdict and how far to trust it; returns the gather's rows over 10%."""
    gather_over = over_tolerance(fits["gather (ours)"])
    frame_over = over_tolerance(fits["frame (ours)"])
    ours = 100 * fixed_part / timings.base["frame"]
    thesis = 100 * seed_fixed_part / (1000.0 / SEED_FPS[512][25])
    say(f"The fixed part b is {ours:.0f}% of our 512^2 / 25-sample "
        f"frame and {thesis:.0f}% of the thesis' (its shadow map,")
    say("scene and G-buffer passes on a GPU against ours on llvmpipe), so our frame-time ratios "
        "grow")
    say("more slowly with samples than the thesis'; the gather ratios alone grow faster.\n")
    say(f"**Target (cost linear in samples and in texels within 10%): "
        f"{'met' if gather_over == 0 else 'NOT met'} for the gather pass** "
        f"({gather_over} of 12 rows outside 10% of a * samples * texels + b); the whole frame: "
        f"{frame_over} of 12 rows outside.\n")
    worst_spread = max(max(v) / min(v) for v in timings.spread.values())
    if worst_spread > 1.0 + LINEARITY_TOLERANCE:
        say(f"Resolution of this verdict: the same row's gather varied by up to "
            f"{100 * (worst_spread - 1):.0f}% between rounds")
        say("(last-but-one column) even with the machine otherwise idle, which is comparable to")
        say("the 10% tolerance; the smallest of the rounds is kept, but a re-run can move a")
        say("borderline row across the line.\n")
    disturbed = timings.disturbed
    if disturbed:
        say(f"**This verdict is not reliable: for {len(disturbed)} of 12 rows every round ran "
            "while")
        say(f"other processes took more than {100 * OTHERS_TOLERANCE:.0f}% of the CPU.** Re-run "
            "on an")
        say("idle machine.\n")
    return gather_over


def plot_timing(timings, work, gather, frame):
    """docs/images/atlas_timing.png: ms against samples x texels, and ratios to the thesis'."""
    rows, keys, base = timings.rows, timings.keys, timings.base
    plt = common.pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    fa, fb, _ = relative_fit(work, gather)
    x = numpy.logspace(math.log10(min(work)), math.log10(max(work)), 100)
    for r, marker, colour in ((512, "o", "C0"), (1024, "s", "C1")):
        idx = [i for i, k in enumerate(keys) if k[0] == r]
        ax[0].loglog([work[i] for i in idx], [gather[i] for i in idx], marker, color=colour,
                     label=f"gather, {r}^2")
        ax[0].loglog([work[i] for i in idx], [frame[i] for i in idx], marker, color=colour,
                     mfc="none", label=f"frame, {r}^2")
        ax[1].semilogy(TABLE_SAMPLES, [rows[r, s]["ms"]["frame"] / base["frame"]
                                       for s in TABLE_SAMPLES], marker + "-", color=colour,
                       label=f"ours, frame, {r}^2")
        seed_s = sorted(SEED_FPS[r])
        ax[1].semilogy(seed_s, [SEED_FPS[512][25] / SEED_FPS[r][s] for s in seed_s], marker + ":",
                       color=colour, mfc="none", label=f"thesis, frame, {r}^2")
    ax[0].loglog(x, fa * x + fb, "k--", lw=1, label="fit a*S*T + b (gather)")
    ax[0].set_xlabel("samples x texels")
    ax[0].set_ylabel("ms (llvmpipe)")
    ax[0].legend(fontsize=8)
    ax[0].set_title("Cornell box, atlas.progressive=0")
    ax[1].set_xlabel("samples per texel")
    ax[1].set_ylabel("frame time / (512^2, 25 samples)")
    ax[1].legend(fontsize=8)
    ax[1].set_title("frame-time ratios, ours vs thesis")
    fig.tight_layout()
    fig.savefig(os.path.join(common.IMAGES, "atlas_timing.png"), dpi=90)
    plt.close(fig)


def measure_linearity(say, timings):
    """Writes the linearity part of (a); returns (target met, a one-line summary)."""
    keys = timings.keys
    work = [s * r * r for r, s in keys]
    texels = [r * r for r, s in keys]
    gather = [timings.rows[k]["ms"]["atlas/gather"] for k in keys]
    frame = [timings.rows[k]["ms"]["frame"] for k in keys]
    fits, seed_fixed_part, seed_res = say_linear_fits(say, work, gather, frame)
    extra = say_per_texel_fits(say, work, texels, gather, frame)
    say_residuals(say, keys, fits, extra, seed_res)
    fixed_part = relative_fit(work, frame)[1]
    gather_over = say_verdict(say, timings, fits, fixed_part, seed_fixed_part)
    plot_timing(timings, work, gather, frame)
    say("![gather and frame time against samples x texels; ratios against the thesis]"
        "(images/atlas_timing.png)\n")
    worst = 100 * abs(fits["gather (ours)"]).max()
    disturbed = timings.disturbed
    return gather_over == 0, (
        f"{gather_over} of 12 rows outside 10%, largest residual {worst:.0f}%" +
        (f"; {len(disturbed)} rows measured only while other processes used the CPU, so "
         f"not reliable" if disturbed else ""))
