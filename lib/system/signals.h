// SPDX-License-Identifier: GPL-2.0-or-later
/** @file signals.h
 *  What SIGINT and SIGTERM leave behind: nothing. Temporary files and folders, and the
 *  process groups of running children (cc, gnuplot, pdflatex), are registered here while
 *  they exist; the handlers remove the files, kill the children and exit with 128 + the
 *  signal (130, 143). The registry is a fixed table that a handler can read without locks. */
#pragma once

#include <string>
#include <sys/types.h>

namespace lagrange {

/// Installs the handlers of SIGINT and SIGTERM (once; later calls do nothing).
void install_signal_cleanup();

/// Removes everything registered now: a process that must end at once (the budget
/// watchdog) calls it before `_exit`. Async-signal-safe.
void clean_up_registered();

/// While it lives, `path` is removed if a signal ends the process: a file, or a folder
/// with files only (one level, as private_directory makes).
class removed_on_signal {
public:
    removed_on_signal() = default;
    removed_on_signal(const std::string& path, bool folder);
    ~removed_on_signal();
    removed_on_signal(const removed_on_signal&) = delete;
    removed_on_signal& operator=(const removed_on_signal&) = delete;
    removed_on_signal(removed_on_signal&& other) noexcept;
    removed_on_signal& operator=(removed_on_signal&& other) noexcept;

private:
    int slot_ = -1; ///< -1: nothing registered (no free slot, or a path too long to keep)
};

/// While it lives, the process group `group` is killed if a signal ends the process.
class killed_on_signal {
public:
    explicit killed_on_signal(pid_t group);
    ~killed_on_signal();
    killed_on_signal(const killed_on_signal&) = delete;
    killed_on_signal& operator=(const killed_on_signal&) = delete;

private:
    int slot_ = -1;
};

} // namespace lagrange
