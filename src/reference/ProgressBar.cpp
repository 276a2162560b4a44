#include "reference/ProgressBar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace gi::reference {
namespace {

constexpr int kBarWidth = 30;
constexpr double kRedrawInterval = 0.1;   // seconds

std::string formatSeconds(double seconds) {
    char text[32];
    if (!std::isfinite(seconds)) return "?";
    if (seconds < 60.0) {
        std::snprintf(text, sizeof text, "%.1f s", seconds);
    } else {
        const long total = std::lround(seconds);
        std::snprintf(text, sizeof text, "%ldm%02lds", total / 60, total % 60);
    }
    return text;
}

} // namespace

ProgressBar::ProgressBar(std::string label, std::FILE* out, Style style)
    : mLabel(std::move(label)), mOut(out), mStart(std::chrono::steady_clock::now()) {
    mTerminal = style == Style::Terminal ||
                (style == Style::Auto && out && ::isatty(::fileno(out)) == 1);
}

ProgressBar::~ProgressBar() { finish(); }

ProgressCallback ProgressBar::callback() {
    return [this](double fraction) { update(fraction); };
}

void ProgressBar::update(double fraction) {
    const std::lock_guard<std::mutex> lock(mMutex);
    if (mFinished || !mOut) return;
    fraction = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
    mLastFraction = std::max(mLastFraction, fraction);
    const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    if (mTerminal) {
        if (mLastFraction < 1.0 && mLastDraw >= 0.0 && elapsed - mLastDraw < kRedrawInterval) {
            return;
        }
        mLastDraw = elapsed;
        draw(mLastFraction, elapsed);
        mFinished = mLastFraction >= 1.0;
        return;
    }
    const int decile = int(std::floor(mLastFraction * 10.0 + 1e-9));
    if (decile <= mLastDecile) return;
    mLastDecile = decile;
    draw(mLastFraction, elapsed);
}

void ProgressBar::draw(double fraction, double elapsed) {
    const int percent = int(std::floor(fraction * 100.0 + 1e-9));
    const std::string timing = fraction >= 1.0
            ? "done in " + formatSeconds(elapsed)
            : "ETA " + (fraction > 0.0 ? formatSeconds(elapsed * (1.0 - fraction) / fraction)
                                       : std::string("?"));
    if (mTerminal) {
        const int filled = int(std::lround(fraction * kBarWidth));
        const std::string bar = std::string(std::size_t(filled), '#') +
                                std::string(std::size_t(kBarWidth - filled), '.');
        std::fprintf(mOut, "\r%s [%s] %3d%%  %-16s", mLabel.c_str(), bar.c_str(), percent,
                timing.c_str());
        mDrawn = true;
        if (fraction >= 1.0) {
            std::fputc('\n', mOut);
            mDrawn = false;
        }
    } else {
        std::fprintf(mOut, "%s: %3d%%  %s\n", mLabel.c_str(), percent, timing.c_str());
    }
    std::fflush(mOut);
}

void ProgressBar::finish() {
    const std::lock_guard<std::mutex> lock(mMutex);
    if (mFinished || !mOut) return;
    mFinished = true;
    if (mTerminal && mDrawn) {
        std::fputc('\n', mOut);
        std::fflush(mOut);
    }
}

} // namespace gi::reference
