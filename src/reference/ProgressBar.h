// Terminal progress for long reference renders: a bar with percentage and estimated time left,
// redrawn in place with '\r' when the stream is a terminal, or (logs, CI) one line per 10 %,
// so redirected output stays readable. The ETA assumes the remaining work proceeds at the
// average rate so far (elapsed x (1 - f) / f).
#pragma once

#include "reference/ReferenceRenderer.h"

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace gi::reference {

class ProgressBar {
public:
    enum class Style { Auto, Terminal, Lines };   // Auto: Terminal when `out` is a TTY

    explicit ProgressBar(std::string label, std::FILE* out = stderr, Style style = Style::Auto);
    ~ProgressBar();   // finish()
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    // Thread-safe; fraction in [0, 1]. Terminal redraws are limited to ten per second.
    void update(double fraction);
    // Ends the bar (a final 100 % line with the total time if it reached 1); idempotent.
    void finish();
    // A ProgressCallback forwarding to update(); the bar must outlive its use.
    ProgressCallback callback();

private:
    void draw(double fraction, double elapsed);

    std::string mLabel;
    std::FILE* mOut;
    bool mTerminal;
    std::chrono::steady_clock::time_point mStart;
    std::mutex mMutex;
    double mLastFraction = 0.0;
    double mLastDraw = -1.0;   // seconds since start of the last terminal redraw
    int mLastDecile = 0;       // Lines: the last 10 % step printed
    bool mDrawn = false;       // Terminal: a partial line is on screen
    bool mFinished = false;
};

} // namespace gi::reference
