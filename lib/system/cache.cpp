// SPDX-License-Identifier: GPL-2.0-or-later
/** @file cache.cpp
 *  The file cache: POSIX calls relative to the descriptor of the checked folder, so that
 *  links, owners and modes are checked on the descriptor that is read, and what was read is
 *  what the caller gets (no check-then-open race). Keys are hashed with Nettle's SHA-256. */
#include "system/cache.h"

#include "system/signals.h"

#include <dirent.h>
#include <fcntl.h>
#include <nettle/sha2.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <utility>
#include <vector>

namespace lagrange {

namespace {

/// The first line of every entry; the key's size in decimal and a newline follow, then the
/// key, then the stored bytes. A new format gets a new first line (old entries then miss).
const std::string entry_magic = "lagrange cache entry 1\n";
/// Entries larger than this are not read (a native library is a few hundred KB at most).
constexpr off_t max_entry_bytes = off_t(256) << 20;
/// Temporary files of store(): this prefix, and swept when older than this.
const std::string temporary_prefix = "tmp-";
constexpr time_t stale_seconds = 10 * 60;

/// Whether a folder may be trusted: root's or ours, and writable by no one else, or sticky.
bool trusted_owner_and_mode(const struct stat& info, std::string* why, const std::string& path)
{
    if (!S_ISDIR(info.st_mode)) {
        if (why)
            *why = path + " is not a folder";
        return false;
    }
    if (info.st_uid != 0 && info.st_uid != geteuid()) {
        if (why)
            *why = path + " belongs to another user (uid " + std::to_string(info.st_uid) + ")";
        return false;
    }
    if ((info.st_mode & (S_IWGRP | S_IWOTH)) != 0 && (info.st_mode & S_ISVTX) == 0) {
        if (why)
            *why = path + " is writable by " + ((info.st_mode & S_IWOTH) ? "others" : "its group") +
                   " without the sticky bit";
        return false;
    }
    return true;
}

/// Opens the folder `path` (links resolved first), checking it and every folder above it
/// on the descriptor that is then opened below it (O_NOFOLLOW): -1 when one is not trusted.
int open_trusted_folder(const std::string& path, std::string* why)
{
    char resolved[PATH_MAX];
    if (!realpath(path.c_str(), resolved)) {
        if (why)
            *why = path + " cannot be opened (" + std::strerror(errno) + ")";
        return -1;
    }
    int fd = open("/", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    std::string walked;
    const std::string full = resolved;
    for (std::size_t start = 1; fd >= 0;) {
        struct stat info {};
        if (fstat(fd, &info) != 0 || !trusted_owner_and_mode(info, why, walked.empty() ? "/" : walked)) {
            close(fd);
            return -1;
        }
        if (start >= full.size())
            return fd;
        std::size_t end = full.find('/', start);
        if (end == std::string::npos)
            end = full.size();
        const std::string part = full.substr(start, end - start);
        walked += "/" + part;
        start = end + 1;
        int next = openat(fd, part.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (next < 0 && why)
            *why = walked + " cannot be opened as a folder (" + std::strerror(errno) + ")";
        close(fd);
        fd = next;
    }
    return -1;
}

/// The folder `name` in `parent`, made with mode 0700 when missing, and opened: a real
/// folder (not a link) of this user that no one else can write, else -1.
int open_private_folder(int parent, const std::string& name)
{
    if (mkdirat(parent, name.c_str(), 0700) != 0 && errno != EEXIST)
        return -1;
    int fd = openat(parent, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return -1;
    struct stat info {};
    if (fstat(fd, &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != geteuid() ||
        (info.st_mode & (S_IWGRP | S_IWOTH)) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

/// The whole content of the open file `fd`, at most `limit` bytes; false on a read error
/// or a larger file.
bool read_descriptor(int fd, std::string& bytes, off_t limit)
{
    struct stat info {};
    if (fstat(fd, &info) != 0 || info.st_size > limit)
        return false;
    bytes.resize(static_cast<std::size_t>(info.st_size));
    std::size_t done = 0;
    for (;;) {
        if (done == bytes.size())
            bytes.resize(done + 4096); // it grew since fstat: read on, to the end
        ssize_t got = read(fd, &bytes[done], bytes.size() - done);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            return false;
        if (got == 0)
            break;
        done += static_cast<std::size_t>(got);
        if (static_cast<off_t>(done) > limit)
            return false;
    }
    bytes.resize(done);
    return true;
}

bool write_descriptor(int fd, const std::string& bytes)
{
    for (std::size_t done = 0; done < bytes.size();) {
        ssize_t put = write(fd, bytes.data() + done, bytes.size() - done);
        if (put < 0 && errno == EINTR)
            continue;
        if (put <= 0)
            return false;
        done += static_cast<std::size_t>(put);
    }
    return true;
}

/// 12 random hex digits for a temporary file's name.
std::string random_suffix()
{
    unsigned char random[6] = {};
    if (getrandom(random, sizeof random, 0) != static_cast<ssize_t>(sizeof random)) {
        static std::atomic<unsigned> counter{0};
        unsigned long long mixed = static_cast<unsigned long long>(getpid()) * 1000003ull ^
                                   static_cast<unsigned long long>(std::time(nullptr)) ^ (++counter * 7919ull);
        std::memcpy(random, &mixed, sizeof random);
    }
    char text[13];
    for (int k = 0; k < 6; ++k)
        std::snprintf(text + 2 * k, 3, "%02x", random[k]);
    return text;
}

bool is_entry_name(const std::string& name)
{
    return name.size() == 64 &&
           std::all_of(name.begin(), name.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

/// Files of the first format (`<16 hex>.key` beside `<16 hex>.file`): no longer read, swept.
bool is_old_format_name(const std::string& name)
{
    return (name.size() == 20 && name.compare(16, 4, ".key") == 0) ||
           (name.size() == 21 && name.compare(16, 5, ".file") == 0);
}

std::atomic<cache_testing::race_hook> race_hook{nullptr};

} // namespace

bool trusted_folder(const std::string& path, std::string* why)
{
    int fd = open_trusted_folder(path, why);
    if (fd < 0)
        return false;
    close(fd);
    return true;
}

std::string file_cache::entry_name(const std::string& key)
{
    struct sha256_ctx context;
    sha256_init(&context);
    sha256_update(&context, key.size(), reinterpret_cast<const std::uint8_t*>(key.data()));
    std::uint8_t digest[SHA256_DIGEST_SIZE];
    sha256_digest(&context, SHA256_DIGEST_SIZE, digest);
    char text[2 * SHA256_DIGEST_SIZE + 1];
    for (int k = 0; k < SHA256_DIGEST_SIZE; ++k)
        std::snprintf(text + 2 * k, 3, "%02x", digest[k]);
    return text;
}

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
    // The base folder may be shared (it is the user's, or /tmp in a test); ours must be private,
    // and no one but root or this user may be able to swap a folder above them.
    if (mkdir(base.c_str(), 0700) != 0 && errno != EEXIST)
        return;
    int base_fd = open_trusted_folder(base, nullptr);
    if (base_fd < 0)
        return;
    int ours = open_private_folder(base_fd, "lagrange");
    close(base_fd);
    if (ours < 0)
        return;
    descriptor_ = open_private_folder(ours, name);
    close(ours);
    if (descriptor_ >= 0)
        folder_ = base + "/lagrange/" + name;
}

file_cache::~file_cache()
{
    if (descriptor_ >= 0)
        close(descriptor_);
}

std::optional<std::string> file_cache::find(const std::string& key) const
{
    if (!enabled())
        return std::nullopt;
    // O_NONBLOCK: a named pipe put there would not hang the open (it then fails the type check).
    int fd = openat(descriptor_, entry_name(key).c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return std::nullopt;
    struct stat info {};
    std::string bytes;
    bool ours = fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_uid == geteuid() &&
                (info.st_mode & (S_IWGRP | S_IWOTH)) == 0;
    bool read = ours && read_descriptor(fd, bytes, max_entry_bytes);
    // The key stored in the entry, byte for byte.
    const std::string size = std::to_string(key.size()) + "\n";
    const std::size_t header = entry_magic.size() + size.size();
    bool hit = read && bytes.size() >= header + key.size() && bytes.compare(0, entry_magic.size(), entry_magic) == 0 &&
               bytes.compare(entry_magic.size(), size.size(), size) == 0 && bytes.compare(header, key.size(), key) == 0;
    if (hit)
        futimens(fd, nullptr); // now: recently used
    close(fd);
    if (!hit)
        return std::nullopt;
    bytes.erase(0, header + key.size());
    return bytes;
}

void file_cache::store(const std::string& key, const std::string& path) const
{
    if (!enabled())
        return;
    std::string bytes = entry_magic + std::to_string(key.size()) + "\n" + key;
    {
        int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0)
            return;
        std::string content;
        struct stat info {};
        bool read = fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && read_descriptor(fd, content, max_entry_bytes);
        close(fd);
        if (!read)
            return;
        bytes += content;
    }
    // One file, through a private temporary file renamed over the entry: key and bytes together.
    std::string temporary;
    int fd = -1;
    for (int attempt = 0; attempt < 16 && fd < 0; ++attempt) {
        temporary = temporary_prefix + random_suffix();
        fd = openat(descriptor_, temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd < 0 && errno != EEXIST)
            return;
    }
    if (fd < 0)
        return;
    removed_on_signal guard(folder_ + "/" + temporary, false);
    bool written = write_descriptor(fd, bytes);
    written = close(fd) == 0 && written;
    if (!written || renameat(descriptor_, temporary.c_str(), descriptor_, entry_name(key).c_str()) != 0) {
        unlinkat(descriptor_, temporary.c_str(), 0);
        return;
    }

    // The least recently used entries past the limit go, and so do stale temporary files
    // (a run killed between creating one and renaming it) and entries of the old format.
    std::vector<std::pair<struct timespec, std::string>> entries;
    // A new open of the folder (not dup, which would share the read position between listings).
    int listing_fd = openat(descriptor_, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR* listing = listing_fd >= 0 ? fdopendir(listing_fd) : nullptr;
    if (!listing) {
        if (listing_fd >= 0)
            close(listing_fd);
        return;
    }
    const time_t now = std::time(nullptr);
    while (const dirent* entry = readdir(listing)) {
        const std::string name = entry->d_name;
        struct stat info {};
        if (fstatat(descriptor_, name.c_str(), &info, AT_SYMLINK_NOFOLLOW) != 0)
            continue;
        if (is_entry_name(name))
            entries.emplace_back(info.st_mtim, name);
        else if ((name.compare(0, temporary_prefix.size(), temporary_prefix) == 0 &&
                  info.st_mtim.tv_sec + stale_seconds < now) ||
                 is_old_format_name(name))
            unlinkat(descriptor_, name.c_str(), 0);
    }
    closedir(listing);
    if (entries.size() <= max_entries_)
        return;
    std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
        return a.first.tv_sec != b.first.tv_sec ? a.first.tv_sec < b.first.tv_sec
               : a.first.tv_nsec != b.first.tv_nsec ? a.first.tv_nsec < b.first.tv_nsec
                                                    : a.second < b.second;
    });
    for (std::size_t k = 0; k + max_entries_ < entries.size(); ++k)
        unlinkat(descriptor_, entries[k].second.c_str(), 0);
}

void file_cache::remove(const std::string& key) const
{
    if (enabled())
        unlinkat(descriptor_, entry_name(key).c_str(), 0);
}

namespace cache_testing {

void set_race_hook(race_hook hook) { lagrange::race_hook = hook; }

void run_race_hook(const std::string& cache_folder)
{
    if (race_hook hook = lagrange::race_hook.load())
        hook(cache_folder);
}

} // namespace cache_testing

} // namespace lagrange
