// SPDX-License-Identifier: GPL-2.0-or-later
/** @file files.cpp
 *  Bounded reads (poll with a deadline, chunked read) and replacing writes (mkstemp in
 *  the target's folder, fchmod/fchown to the replaced file, rename). */
#include "system/files.h"

#include "core/errors.h"

#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lagrange {

namespace {

bool standard_output_closed = false;

std::string quoted(const std::string& path) { return "`" + path + "`"; }

/// Closes the descriptor unless it is standard input.
struct descriptor {
    int fd = -1;
    ~descriptor()
    {
        if (fd > 0)
            close(fd);
    }
};

} // namespace

std::string read_bounded(const std::string& path, std::size_t limit, double wait_seconds)
{
    descriptor in;
    bool regular = false;
    if (path == "-") {
        in.fd = 0;
    } else {
        // O_NONBLOCK: opening a named pipe does not wait for a writer.
        in.fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
        if (in.fd < 0) {
            int error = errno;
            if (error == ENOENT || error == ENOTDIR)
                throw file_error(quoted(path) + ": no such file");
            throw file_error(quoted(path) + ": " + std::strerror(error));
        }
        struct stat info {};
        if (fstat(in.fd, &info) != 0)
            throw file_error("cannot read " + quoted(path) + ": " + std::strerror(errno));
        if (S_ISDIR(info.st_mode))
            throw file_error(quoted(path) + " is a folder, not a file");
        regular = S_ISREG(info.st_mode);
        if (regular)
            fcntl(in.fd, F_SETFL, fcntl(in.fd, F_GETFL) & ~O_NONBLOCK);
    }
    const bool waits = !regular && path != "-";
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(std::isfinite(wait_seconds) ? wait_seconds : 0.0));
    std::string text;
    std::vector<char> chunk(1 << 16);
    for (;;) {
        if (waits) {
            // A pipe with no writer yet gives no event: wait for data, or end of file, until the deadline.
            auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
            pollfd request{in.fd, POLLIN, 0};
            int ready = left.count() > 0 ? poll(&request, 1, static_cast<int>(std::min<long long>(left.count(), INT_MAX)))
                                         : 0;
            if (ready < 0 && errno == EINTR)
                continue;
            if (ready == 0)
                throw file_error(quoted(path) + " gave no data for " +
                                      std::to_string(static_cast<long long>(std::ceil(wait_seconds))) +
                                      " s: a scene is read from a file, or from a pipe that is written");
            if (ready < 0)
                throw file_error("cannot read " + quoted(path) + ": " + std::strerror(errno));
        }
        ssize_t got = read(in.fd, chunk.data(), chunk.size());
        if (got < 0) {
            if (errno == EINTR || errno == EAGAIN)
                continue;
            throw file_error("cannot read " + quoted(path) + ": " + std::strerror(errno));
        }
        if (got == 0)
            return text;
        if (text.size() + static_cast<std::size_t>(got) > limit)
            throw file_error(quoted(path) + " is larger than " + std::to_string(limit >> 20) +
                                  " MB: not a scene or rules file");
        text.append(chunk.data(), static_cast<std::size_t>(got));
    }
}

output_file::output_file(const std::string& path) : path_(path)
{
    if (path.empty() || path == "-") {
        standard_output_ = true;
        return;
    }
    target_ = path;
    struct stat info {};
    if (lstat(path.c_str(), &info) == 0 && S_ISLNK(info.st_mode)) {
        // Replace the file the link names, not the link.
        char* resolved = realpath(path.c_str(), nullptr);
        if (resolved) {
            target_ = resolved;
            std::free(resolved);
        }
    }
    bool exists = stat(target_.c_str(), &info) == 0;
    if (exists && S_ISDIR(info.st_mode))
        throw file_error("cannot write " + quoted(path) + ": it is a folder");
    if (exists && !S_ISREG(info.st_mode)) {
        // A device or a pipe: written in place, never replaced by a regular file.
        file_.open(target_, std::ios::binary | std::ios::out);
        if (!file_)
            throw file_error("cannot write " + quoted(path) + ": " + std::strerror(errno));
        return;
    }
    std::vector<char> name(target_.begin(), target_.end());
    const std::string suffix = ".XXXXXX";
    name.insert(name.end(), suffix.begin(), suffix.end());
    name.push_back('\0');
    int fd = mkstemp(name.data());
    if (fd < 0)
        throw file_error("cannot write " + quoted(path) + ": " + std::strerror(errno));
    temporary_ = name.data();
    guard_ = removed_on_signal(temporary_, false);
    // The mode of the file replaced (with its owner, where this process may set it), or the
    // usual mode of a new file: 0666 less the umask. mkstemp made it 0600.
    mode_t mode;
    if (exists) {
        mode = info.st_mode & 07777;
        if (fchown(fd, info.st_uid, info.st_gid) != 0) {
            // not root: the file is ours, as when it is created anew
        }
    } else {
        mode_t mask = umask(0);
        umask(mask);
        mode = 0666 & ~mask;
    }
    fchmod(fd, mode);
    ::close(fd);
    file_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (!file_) {
        std::remove(temporary_.c_str());
        temporary_.clear();
        throw file_error("cannot write " + quoted(path));
    }
}

output_file::~output_file()
{
    if (!temporary_.empty()) {
        file_.close();
        std::remove(temporary_.c_str());
    }
}

std::ostream& output_file::stream() { return standard_output_ ? std::cout : file_; }

void output_file::commit()
{
    if (standard_output_) {
        finish_standard_output();
        return;
    }
    file_.flush();
    file_.close();
    if (file_.fail())
        throw computation_error("cannot write " + quoted(path_) + " (the disc may be full)");
    if (temporary_.empty())
        return;
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0)
        throw computation_error("cannot write " + quoted(path_) + ": " + std::strerror(errno));
    temporary_.clear();
}

void write_output(const std::string& path, const std::string& bytes)
{
    output_file out(path);
    out.stream() << bytes;
    out.commit();
}

void guard_standard_streams()
{
    for (int fd = 0; fd <= 2; ++fd) {
        if (fcntl(fd, F_GETFD) != -1 || errno != EBADF)
            continue;
        int opened = open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
        if (opened >= 0 && opened != fd) {
            dup2(opened, fd);
            close(opened);
        }
        if (fd == 1)
            standard_output_closed = true;
    }
}

void finish_standard_output()
{
    std::cout.flush();
    if (standard_output_closed)
        throw computation_error("standard output is closed: the output was not written (use -o FILE)");
    if (!std::cout)
        throw computation_error(std::string("cannot write to standard output") +
                                (errno ? std::string(": ") + std::strerror(errno) : std::string()));
}

void write_files(const std::string& folder, const std::vector<std::pair<std::string, std::string>>& files)
{
    struct stat info {};
    const bool exists = ::stat(folder.c_str(), &info) == 0;
    if (exists && !S_ISDIR(info.st_mode))
        throw file_error("cannot write into " + quoted(folder) + ": it is not a folder");
    // The folders above a missing one are made first (as mkdir -p); the last is made whole below.
    for (std::size_t slash = folder.find('/', 1); !exists && slash != std::string::npos;
         slash = folder.find('/', slash + 1)) {
        const std::string above = folder.substr(0, slash);
        if (::mkdir(above.c_str(), 0777) != 0 && errno != EEXIST)
            throw file_error("cannot write into " + quoted(folder) + ": " + std::strerror(errno));
    }
    // The temporary folder: inside `folder` when it exists, beside it when it does not.
    std::string base = folder;
    while (base.size() > 1 && base.back() == '/')
        base.pop_back();
    std::string pattern = exists ? base + "/.lagrange-XXXXXX" : base + ".lagrange-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!::mkdtemp(name.data()))
        throw file_error("cannot write into " + quoted(folder) + ": " + std::strerror(errno));
    const std::string temporary(name.data());
    removed_on_signal guard(temporary, true);
    auto remove_temporary = [&] {
        for (const auto& file : files)
            ::unlink((temporary + "/" + file.first).c_str());
        ::rmdir(temporary.c_str());
    };
    try {
        for (const auto& [file, text] : files) {
            std::ofstream out(temporary + "/" + file, std::ios::binary);
            out << text;
            out.flush();
            if (!out)
                throw file_error("cannot write into " + quoted(folder) + ": " +
                                 (errno ? std::strerror(errno) : "the disc may be full"));
        }
        if (!exists) {
            const mode_t mask = ::umask(0);
            ::umask(mask);
            ::chmod(temporary.c_str(), 0777 & ~mask);
            if (::rename(temporary.c_str(), folder.c_str()) != 0)
                throw file_error("cannot create " + quoted(folder) + ": " + std::strerror(errno));
            return;
        }
        for (const auto& file : files)
            if (::rename((temporary + "/" + file.first).c_str(), (base + "/" + file.first).c_str()) != 0)
                throw file_error("cannot write " + quoted(base + "/" + file.first) + ": " + std::strerror(errno));
        ::rmdir(temporary.c_str());
    } catch (...) {
        remove_temporary();
        throw;
    }
}

} // namespace lagrange
