// SPDX-License-Identifier: GPL-2.0-or-later
/** @file cache.h
 *  A cache of files in the user's cache folder, keyed by text: the compiled native code
 *  of equations of motion, so that running the same scene again does not compile again.
 *  The trust model is in docs/reliability.md ("The cache of compiled code"). */
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace lagrange {

/// Whether the folder `path` (links resolved) and every folder above it up to / are owned
/// by root or by this user and writable by no one else — a folder that group or others may
/// write counts only with the sticky bit (as /tmp), where no one renames another's entries.
/// Only then can no other user swap a file or folder below it. When not, `why` (if given)
/// says which folder and what is wrong with it.
bool trusted_folder(const std::string& path, std::string* why = nullptr);

/// Files kept under a key text in `$XDG_CACHE_HOME/lagrange/NAME` (`~/.cache/lagrange/NAME`
/// when XDG_CACHE_HOME is unset or not an absolute path).
/// - An entry is one file, named by the SHA-256 of its key (Nettle), that holds the key
///   and the stored bytes; it is written to a temporary file and renamed, so no process
///   ever sees half an entry. A hit reads the whole entry through one descriptor whose
///   type and owner were checked, and is a hit only when the key stored in it is
///   byte-identical: a hash collision or a swapped entry is a miss, never a wrong file.
/// - The cache is used only when every folder above it passes trusted_folder, and its own
///   two folders (made with mode 0700) are real folders (not links) of this user that no
///   one else can write. The folder is opened once, then used through its descriptor.
/// - At most `max_entries` are kept; storing one more removes the least recently used.
///   Storing also sweeps temporary files older than 10 minutes (a run killed between
///   creating one and renaming it).
/// - Off (every lookup misses, nothing is stored) with `LAGRANGE_CACHE=0`, without a home
///   folder, or when the folder is unsafe. A cache never fails a run: errors are misses.
class file_cache {
public:
    explicit file_cache(const std::string& name, std::size_t max_entries = 64);
    ~file_cache();
    file_cache(const file_cache&) = delete;
    file_cache& operator=(const file_cache&) = delete;

    bool enabled() const { return descriptor_ >= 0; }
    const std::string& folder() const { return folder_; }

    /// The bytes stored under `key`, or nothing on a miss. A hit counts as a use. The bytes
    /// are those checked: a caller that must open them by path writes them into a private
    /// folder of its own (never opens the entry's path, which could change meanwhile).
    std::optional<std::string> find(const std::string& key) const;

    /// Keeps a copy of the file `path` under `key`, replacing what was stored under it.
    void store(const std::string& key, const std::string& path) const;

    /// Removes what is stored under `key` (an entry that turned out to be unusable).
    void remove(const std::string& key) const;

    /// The file name of the entry of `key` in folder(): the SHA-256 of the key, 64 hex digits.
    static std::string entry_name(const std::string& key);

private:
    std::string folder_;   ///< the folder's path, for messages and tests
    int descriptor_ = -1;  ///< the folder, opened through trusted folders; -1: the cache is off
    std::size_t max_entries_;
};

/// For tests only: a function called between the check of what the cache found and its
/// load (native_code calls it after find() and before dlopen), with the cache's folder, so
/// that a test can swap files and folders there as a hostile user might.
namespace cache_testing {
using race_hook = void (*)(const std::string& cache_folder);
void set_race_hook(race_hook hook);
void run_race_hook(const std::string& cache_folder);
} // namespace cache_testing

} // namespace lagrange
