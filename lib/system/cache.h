// SPDX-License-Identifier: GPL-2.0-or-later
/** @file cache.h
 *  A cache of files in the user's cache folder, keyed by text: the compiled native code
 *  of equations of motion, so that running the same scene again does not compile again. */
#pragma once

#include <cstddef>
#include <string>

namespace lagrange {

/// Files kept under a key text in `$XDG_CACHE_HOME/lagrange/NAME` (`~/.cache/lagrange/NAME`
/// when XDG_CACHE_HOME is unset or not an absolute path).
/// - An entry is found by a hash of its key and used only when the key stored beside it is
///   byte-identical: a hash collision is a miss, never a wrong file.
/// - The folders are made with mode 0700, and the cache is used only when its folder is a
///   real folder (not a link) owned by this user that no one else can write; entries are
///   regular files owned by this user, written to a private temporary file and renamed, so
///   no process ever sees half an entry.
/// - At most `max_entries` are kept; storing one more removes the least recently used.
/// - Off (every lookup misses, nothing is stored) with `LAGRANGE_CACHE=0`, without a home
///   folder, or when the folder is unsafe. A cache never fails a run: errors are misses.
class file_cache {
public:
    explicit file_cache(const std::string& name, std::size_t max_entries = 64);

    bool enabled() const { return !folder_.empty(); }
    const std::string& folder() const { return folder_; }

    /// The path of the file stored under `key`, or "" on a miss. A hit counts as a use.
    std::string find(const std::string& key) const;

    /// Keeps a copy of the file `path` under `key`.
    void store(const std::string& key, const std::string& path) const;

private:
    std::string folder_; ///< empty: the cache is off
    std::size_t max_entries_;
};

} // namespace lagrange
