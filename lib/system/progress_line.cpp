// SPDX-License-Identifier: GPL-2.0-or-later
/** @file progress_line.cpp
 *  The progress line (see progress_line.h). */
#include "system/progress_line.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

namespace lagrange {

progress_line::progress_line(std::ostream& out, bool enabled, double delay_seconds)
    : out_(out), enabled_(enabled), delay_(delay_seconds), start_(clock::now())
{
}

progress_line& progress_line::standard_error()
{
    static progress_line* line = [] {
        double delay = 1;
        if (const char* text = std::getenv("LAGRANGE_PROGRESS_DELAY")) {
            char* end = nullptr;
            const double seconds = std::strtod(text, &end);
            if (end != text && *end == '\0' && std::isfinite(seconds) && seconds >= 0)
                delay = seconds;
        }
        return new progress_line(std::cerr, isatty(STDERR_FILENO) == 1, delay);
    }();
    return *line;
}

void progress_line::show(const std::string& what, double fraction)
{
    if (!enabled_)
        return;
    std::lock_guard<std::mutex> guard(lock_);
    if (what.empty()) {
        clear_locked();
        return;
    }
    const auto now = clock::now();
    if (std::chrono::duration<double>(now - start_).count() < delay_)
        return;
    if (what != what_) {
        what_ = what;
        what_since_ = now;
    } else if (now - drawn_at_ < std::chrono::milliseconds(100)) {
        return;
    }
    drawn_at_ = now;
    std::string text = "lagrange: " + what;
    if (fraction >= 0) {
        const int percent = static_cast<int>(std::min(fraction, 1.0) * 100);
        text += " [" + std::string(percent / 5, '#') + std::string(20 - percent / 5, ' ') + "] " +
                std::to_string(percent) + "%";
    } else {
        const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(now - what_since_).count();
        text += ", " + std::to_string(seconds) + " s";
    }
    // At most 79 columns, counted as code points, cut between them.
    std::size_t columns = 0, cut = 0;
    for (; cut < text.size(); ++cut) {
        const bool starts_code_point = (static_cast<unsigned char>(text[cut]) & 0xC0) != 0x80;
        if (starts_code_point && columns == 79)
            break;
        columns += starts_code_point ? 1 : 0;
    }
    text.resize(cut);
    out_ << '\r' << text << std::string(width_ > columns ? width_ - columns : 0, ' ') << std::flush;
    width_ = std::max(width_, columns);
}

void progress_line::clear()
{
    std::lock_guard<std::mutex> guard(lock_);
    clear_locked();
}

void progress_line::clear_locked()
{
    if (width_ > 0)
        out_ << '\r' << std::string(width_, ' ') << '\r' << std::flush;
    width_ = 0;
    what_.clear();
}

progress_callback progress_line::callback()
{
    if (!enabled_)
        return nullptr;
    return [this](const std::string& what, double fraction) { show(what, fraction); };
}

} // namespace lagrange
