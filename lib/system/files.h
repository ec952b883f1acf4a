// SPDX-License-Identifier: GPL-2.0-or-later
/** @file files.h
 *  Reading and writing the user's files safely: reads bounded in size and in waiting
 *  time, and writes that never destroy what they replace. Used by the command line
 *  (scenes, -o, --csv, --plot) and by `use` (rules files). */
#pragma once

#include "system/signals.h"

#include <cstddef>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// A file named by the user that cannot be read or written as asked (bad input, exit code
/// 2): its message names the file and says why, and never quotes its content.
class file_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The largest scene the front ends read (the command line, the Python module): 64 MiB.
constexpr std::size_t max_scene_bytes = 64u << 20;

/// The whole content of `path` (`-`: standard input), read in chunks and refused as soon as
/// it passes `limit` bytes. Folders are refused. A named pipe or a device that gives no
/// data for `wait_seconds` is refused too (standard input waits as long as it takes).
std::string read_bounded(const std::string& path, std::size_t limit, double wait_seconds);

/// Output to standard output (path empty or `-`) or to a file.
/// - A regular file, or a new one, is written to a private temporary file in the same
///   folder and renamed over `path` by commit(): a failure never truncates or half-writes
///   the file it replaces, and the replacement keeps that file's mode and (as root) owner.
///   A symbolic link is followed: the file it names is replaced, the link stays.
/// - Anything else that exists (a device such as /dev/null, a named pipe) is written
///   directly, never replaced.
/// The temporary file goes when the object does without commit(), and on SIGINT/SIGTERM.
/// A path that cannot be written throws file_error; a write that fails on the way (a full
/// disc, a closed standard output) throws computation_error (exit code 1).
class output_file {
public:
    explicit output_file(const std::string& path);
    ~output_file();
    output_file(const output_file&) = delete;
    output_file& operator=(const output_file&) = delete;

    std::ostream& stream();
    /// Flushes and checks every byte was written, then renames the temporary file.
    void commit();

private:
    std::string path_;      ///< as given
    std::string target_;    ///< the file replaced (the link's target for a symbolic link)
    std::string temporary_; ///< empty: writing directly (standard output or not a regular file)
    bool standard_output_ = false;
    std::ofstream file_;
    removed_on_signal guard_;
};

/// Writes `bytes` to `path` through an output_file.
void write_output(const std::string& path, const std::string& bytes);

/// Writes the files (name, content) into `folder`, nothing half-written: all are written
/// into a private temporary folder first. A folder that does not exist is created by renaming
/// the temporary one (all or nothing; the folders above it are made as by mkdir -p); in one that exists, each file replaces its namesake by
/// a rename once every file is written. A folder that cannot be made or written throws
/// file_error naming it and why.
void write_files(const std::string& folder, const std::vector<std::pair<std::string, std::string>>& files);

/// Makes sure file descriptors 0, 1 and 2 are open, so that no file this process opens
/// becomes its standard output; a standard output that was closed is remembered, and
/// output_file and finish_standard_output then fail instead of losing the output.
void guard_standard_streams();

/// Flushes standard output; throws computation_error if any write to it failed.
void finish_standard_output();

} // namespace lagrange
