// SPDX-License-Identifier: GPL-2.0-or-later
/** @file cache.cpp
 *  The file cache: POSIX calls, so that links, owners and modes are checked on the
 *  descriptor that is read (no check-then-open race). */
#include "system/cache.h"

#include "system/signals.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <dirent.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

namespace lagrange {

namespace {

/// A folder that only this user can write and that is not a link; made (mode 0700) when missing.
bool safe_folder(const std::string& path, bool make)
{
    if (make && mkdir(path.c_str(), 0700) != 0 && errno != EEXIST)
        return false;
    struct stat info {};
    return lstat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode) && info.st_uid == geteuid() &&
           (info.st_mode & (S_IWGRP | S_IWOTH)) == 0;
}

/// 64-bit FNV-1a, as 16 hex digits: only an index, since the key itself is compared.
std::string hash_name(const std::string& key)
{
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : key) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

/// A regular file of this user (not a link) opened for reading, or -1.
int open_own_file(const std::string& path)
{
    int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return -1;
    struct stat info {};
    if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode) || info.st_uid != geteuid()) {
        close(fd);
        return -1;
    }
    return fd;
}

/// Whether the file at `path` holds exactly `bytes`.
bool holds(const std::string& path, const std::string& bytes)
{
    int fd = open_own_file(path);
    if (fd < 0)
        return false;
    struct stat info {};
    bool same = fstat(fd, &info) == 0 && static_cast<std::size_t>(info.st_size) == bytes.size();
    std::string content(same ? bytes.size() : 0, '\0');
    for (std::size_t done = 0; same && done < content.size();) {
        ssize_t got = read(fd, &content[done], content.size() - done);
        if (got <= 0)
            same = false;
        else
            done += static_cast<std::size_t>(got);
    }
    close(fd);
    return same && content == bytes;
}

/// Writes `bytes` to `path` through a private temporary file renamed over it.
bool write_atomically(const std::string& path, const std::string& bytes)
{
    std::string temporary = path + ".XXXXXX";
    int fd = mkstemp(&temporary[0]);
    if (fd < 0)
        return false;
    removed_on_signal guard(temporary, false);
    bool written = true;
    for (std::size_t done = 0; written && done < bytes.size();) {
        ssize_t put = write(fd, bytes.data() + done, bytes.size() - done);
        if (put <= 0)
            written = false;
        else
            done += static_cast<std::size_t>(put);
    }
    written = close(fd) == 0 && written;
    if (!written || rename(temporary.c_str(), path.c_str()) != 0) {
        unlink(temporary.c_str());
        return false;
    }
    return true;
}

bool read_whole(const std::string& path, std::string& bytes)
{
    int fd = open_own_file(path);
    if (fd < 0)
        return false;
    char buffer[1 << 16];
    ssize_t got;
    while ((got = read(fd, buffer, sizeof buffer)) > 0)
        bytes.append(buffer, static_cast<std::size_t>(got));
    close(fd);
    return got == 0;
}

} // namespace

file_cache::file_cache(const std::string& name, std::size_t max_entries) : max_entries_(max_entries)
{
    const char* setting = std::getenv("LAGRANGE_CACHE");
    if (setting && std::string(setting) == "0")
        return;
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    std::string base;
    if (xdg && xdg[0] == '/')
        base = xdg;
    else if (home && home[0] == '/')
        base = std::string(home) + "/.cache";
    else
        return;
    // The base folder may be shared (it is the user's, or /tmp in a test); ours must be private.
    if (mkdir(base.c_str(), 0700) != 0 && errno != EEXIST)
        return;
    const std::string ours = base + "/lagrange", folder = ours + "/" + name;
    if (safe_folder(ours, true) && safe_folder(folder, true))
        folder_ = folder;
}

std::string file_cache::find(const std::string& key) const
{
    if (!enabled())
        return "";
    const std::string stem = folder_ + "/" + hash_name(key);
    if (!holds(stem + ".key", key))
        return "";
    int fd = open_own_file(stem + ".file");
    if (fd < 0)
        return "";
    close(fd);
    utimensat(AT_FDCWD, (stem + ".key").c_str(), nullptr, AT_SYMLINK_NOFOLLOW); // now: recently used
    return stem + ".file";
}

void file_cache::store(const std::string& key, const std::string& path) const
{
    std::string bytes;
    if (!enabled() || !read_whole(path, bytes))
        return;
    const std::string stem = folder_ + "/" + hash_name(key);
    // The file before its key: a key on disc always has its whole file beside it.
    if (!write_atomically(stem + ".file", bytes) || !write_atomically(stem + ".key", key))
        return;

    std::vector<std::pair<struct timespec, std::string>> entries;
    if (DIR* listing = opendir(folder_.c_str())) {
        while (const dirent* entry = readdir(listing)) {
            const std::string name = entry->d_name;
            struct stat info {};
            if (name.size() == 20 && name.compare(16, 4, ".key") == 0 &&
                lstat((folder_ + "/" + name).c_str(), &info) == 0)
                entries.emplace_back(info.st_mtim, name.substr(0, 16));
        }
        closedir(listing);
    }
    if (entries.size() <= max_entries_)
        return;
    std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
        return a.first.tv_sec != b.first.tv_sec ? a.first.tv_sec < b.first.tv_sec
               : a.first.tv_nsec != b.first.tv_nsec ? a.first.tv_nsec < b.first.tv_nsec
                                                    : a.second < b.second;
    });
    for (std::size_t k = 0; k + max_entries_ < entries.size(); ++k) {
        unlink((folder_ + "/" + entries[k].second + ".key").c_str());
        unlink((folder_ + "/" + entries[k].second + ".file").c_str());
    }
}

} // namespace lagrange
