// SPDX-License-Identifier: GPL-2.0-or-later
/** @file external.h
 *  Running external programs — the C compiler for native equations of motion,
 *  gnuplot and pdflatex for plots and reports — the one way the library does: in a
 *  private temporary folder, by posix_spawnp without a shell, so no scene text ever
 *  reaches a command line. Below the other modules: numeric/ and output/ both use it. */
#pragma once

#include "core/errors.h"
#include "system/signals.h"

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// A temporary folder or file that cannot be made or written: `error` is the errno (ENOSPC
/// for a full disc, EACCES for a folder we may not write, ...) and `folder` the folder.
class temporary_error : public computation_error {
public:
    temporary_error(const std::string& message, int error, std::string folder)
        : computation_error(message), error(error), folder(std::move(folder)) {}
    int error;
    std::string folder;
};

/// The folder temporary folders are made in: $TMPDIR, or /tmp when it is unset or empty.
std::string temporary_folder();

/// A folder only this process can use (mkdtemp, mode 0700), removed with all its
/// content when the object goes away.
class private_directory {
public:
    /// Named `PREFIX-XXXXXX` in $TMPDIR (or /tmp); throws temporary_error if it cannot be made.
    explicit private_directory(const std::string& prefix = "lagrange");
    ~private_directory();
    private_directory(const private_directory&) = delete;
    private_directory& operator=(const private_directory&) = delete;
    const std::string& path() const { return path_; }
    /// Writes `bytes` to `name` inside the folder; throws temporary_error on failure.
    void write(const std::string& name, const std::string& bytes) const;
    /// The content of `name` inside the folder; throws computation_error if it cannot be read.
    std::string read(const std::string& name) const;

private:
    std::string path_;
    removed_on_signal guard_;
};

/// Whether `program` is an executable file in one of the folders of $PATH.
bool program_available(const std::string& program);

struct program_result {
    int exit_code = -1;  ///< -1 if it could not be started, was killed, or timed out
    bool timed_out = false;
    int start_error = 0; ///< the errno when it could not be started (ENOENT: no such program)
    int signal = 0;      ///< the signal that ended it, if one did (not the timeout's)
};

/// Runs `arguments` (arguments[0] found through $PATH, no shell) in `directory`,
/// with standard input from /dev/null and its output into `log_name` in that
/// folder, `environment` entries (NAME=value) added to ours. It runs in a process group
/// of its own, which is killed (with everything it started) after `timeout_seconds`, or
/// when SIGINT or SIGTERM ends this process.
program_result run_program(const std::vector<std::string>& arguments, const std::string& directory,
                           const std::string& log_name, const std::vector<std::string>& environment = {},
                           double timeout_seconds = 120);

/// What feeds a program's standard input: called once with a writer, which writes bytes into
/// the pipe and returns false once the program has stopped reading (or the timeout passed).
using program_feed = std::function<void(const std::function<bool(const char* bytes, std::size_t size)>& write)>;

/// run_program with standard input from a pipe that `feed` writes (frames to ffmpeg), then
/// closes; the timeout counts from the start, writing included.
program_result run_program_fed(const std::vector<std::string>& arguments, const std::string& directory,
                               const std::string& log_name, const program_feed& feed, double timeout_seconds = 120);

} // namespace lagrange
