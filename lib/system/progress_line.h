// SPDX-License-Identifier: GPL-2.0-or-later
/** @file progress_line.h
 *  One line of progress on a terminal: rewritten in place with a carriage return while a
 *  long step runs, and cleared at the end. The command line shows the library's progress
 *  reports (core/progress.h) on it. */
#pragma once

#include "core/progress.h"

#include <chrono>
#include <cstddef>
#include <mutex>
#include <ostream>
#include <string>

namespace lagrange {

class progress_line {
public:
    /// A line written to `out` when `enabled`, once `delay_seconds` have passed since it
    /// was made (quick commands show nothing).
    progress_line(std::ostream& out, bool enabled, double delay_seconds);

    /// The process's line on standard error: enabled only when standard error is a
    /// terminal; shown after one second, or LAGRANGE_PROGRESS_DELAY seconds. Made on the
    /// first call and never destroyed (another thread may report to it until the end).
    static progress_line& standard_error();

    bool enabled() const { return enabled_; }

    /// Shows `what` with its share done (a bar and a percentage), or, for a negative
    /// `fraction`, the seconds since `what` was first shown. Redrawn at most ten times a
    /// second; at most 79 columns. An empty `what` clears the line. Thread-safe.
    void show(const std::string& what, double fraction);

    /// Blanks what was shown and puts the cursor back at the start of the line.
    void clear();

    /// A callback that shows on this line, or an empty one when the line is not enabled.
    progress_callback callback();

private:
    using clock = std::chrono::steady_clock;
    void clear_locked();

    std::ostream& out_;
    const bool enabled_;
    const double delay_;
    const clock::time_point start_;
    std::mutex lock_;
    std::string what_;             ///< the step shown
    clock::time_point what_since_; ///< when it was first shown
    clock::time_point drawn_at_;
    std::size_t width_ = 0;        ///< columns written on the line (0: nothing shown)
};

} // namespace lagrange
