// SPDX-License-Identifier: GPL-2.0-or-later
/** @file external.cpp
 *  Private folders and posix_spawnp for cc, gnuplot, pdflatex and ffmpeg. */
#include "system/external.h"

#include "core/errors.h"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace lagrange {

std::string temporary_folder()
{
    const char* base = std::getenv("TMPDIR");
    return base && *base ? base : "/tmp";
}

private_directory::private_directory(const std::string& prefix)
{
    const std::string base = temporary_folder();
    std::string pattern = base + "/" + prefix + "-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (!mkdtemp(buffer.data())) {
        int error = errno;
        throw temporary_error("cannot create a temporary folder (" + std::string(std::strerror(error)) + ")", error,
                              base);
    }
    path_ = buffer.data();
    guard_ = removed_on_signal(path_, true);
}

private_directory::~private_directory()
{
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
}

void private_directory::write(const std::string& name, const std::string& bytes) const
{
    // POSIX calls rather than a stream: the errno (a full disc) reaches the message.
    int fd = open((path_ + "/" + name).c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    int error = fd < 0 ? errno : 0;
    for (std::size_t done = 0; fd >= 0 && !error && done < bytes.size();) {
        ssize_t put = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (put < 0 && errno == EINTR)
            continue;
        if (put <= 0)
            error = put < 0 ? errno : EIO;
        else
            done += static_cast<std::size_t>(put);
    }
    if (fd >= 0 && close(fd) != 0 && !error)
        error = errno;
    if (error)
        throw temporary_error("cannot write the temporary file `" + name + "` (" + std::strerror(error) + ")", error,
                              temporary_folder());
}

std::string private_directory::read(const std::string& name) const
{
    std::ifstream in(path_ + "/" + name, std::ios::binary);
    if (!in)
        throw computation_error("cannot read the temporary file `" + name + "`");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

bool program_available(const std::string& program)
{
    const char* path = std::getenv("PATH");
    std::string folders = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= folders.size()) {
        std::size_t end = folders.find(':', start);
        if (end == std::string::npos)
            end = folders.size();
        std::string folder = folders.substr(start, end - start);
        std::string candidate = (folder.empty() ? "." : folder) + "/" + program;
        struct stat info {};
        if (stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) && access(candidate.c_str(), X_OK) == 0)
            return true;
        start = end + 1;
    }
    return false;
}

namespace {

/// Writes all of `bytes` to the non-blocking `fd` before `deadline`; false when the reader has
/// gone (EPIPE: SIGPIPE is blocked in this thread meanwhile) or the deadline passed.
bool write_before(int fd, const char* bytes, std::size_t size, std::chrono::steady_clock::time_point deadline)
{
    while (size > 0) {
        const ssize_t written = write(fd, bytes, size);
        if (written > 0) {
            bytes += written;
            size -= static_cast<std::size_t>(written);
            continue;
        }
        if (written < 0 && errno != EAGAIN && errno != EINTR)
            return false;
        if (std::chrono::steady_clock::now() > deadline)
            return false;
        pollfd wait{fd, POLLOUT, 0};
        poll(&wait, 1, 50);
    }
    return true;
}

/// run_program, with standard input from a pipe that `feed` writes into when it is given.
program_result spawn_and_wait(const std::vector<std::string>& arguments, const std::string& directory,
                              const std::string& log_name, const std::vector<std::string>& environment,
                              double timeout_seconds, const program_feed* feed)
{
    program_result result;
    if (arguments.empty())
        return result;
    std::vector<char*> argv;
    for (const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::vector<std::string> variables;
    for (char** e = environ; e && *e; ++e) {
        std::string entry = *e;
        bool replaced = false;
        for (const std::string& added : environment)
            if (entry.compare(0, added.find('=') + 1, added, 0, added.find('=') + 1) == 0)
                replaced = true;
        if (!replaced)
            variables.push_back(entry);
    }
    variables.insert(variables.end(), environment.begin(), environment.end());
    std::vector<char*> envp;
    for (const std::string& v : variables)
        envp.push_back(const_cast<char*>(v.c_str()));
    envp.push_back(nullptr);
    std::string log_path = directory + "/" + log_name;

    // posix_spawnp, not fork: no copy of this process's page tables (which a large process
    // may not get under strict overcommit), the working folder and the redirections as
    // file actions in the child (addchdir_np: glibc ≥ 2.29).
    int pipe_ends[2] = {-1, -1};
    if (feed && pipe2(pipe_ends, O_CLOEXEC) != 0)
        return result;
    struct pipe_closer {
        int* ends;
        ~pipe_closer()
        {
            for (int k = 0; k < 2; ++k)
                if (ends[k] >= 0)
                    close(ends[k]);
        }
    } closer{pipe_ends};
    posix_spawn_file_actions_t actions;
    if (posix_spawn_file_actions_init(&actions) != 0)
        return result;
    bool prepared = posix_spawn_file_actions_addchdir_np(&actions, directory.c_str()) == 0 &&
                    (feed ? posix_spawn_file_actions_adddup2(&actions, pipe_ends[0], 0) == 0
                          : posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0) == 0) &&
                    posix_spawn_file_actions_addopen(&actions, 1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                                     0600) == 0 &&
                    posix_spawn_file_actions_adddup2(&actions, 1, 2) == 0;
    // A process group of its own: a timeout or a signal kills the compiler's own children too.
    posix_spawnattr_t attributes;
    if (posix_spawnattr_init(&attributes) != 0) {
        posix_spawn_file_actions_destroy(&actions);
        return result;
    }
    prepared = prepared && posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP) == 0 &&
               posix_spawnattr_setpgroup(&attributes, 0) == 0;
    pid_t child = -1;
    int started = prepared ? posix_spawnp(&child, argv[0], &actions, &attributes, argv.data(), envp.data()) : -1;
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (started != 0) {
        result.start_error = started > 0 ? started : EINVAL;
        return result; // not found, not executable, or no folder or log: it could not be started
    }
    killed_on_signal guard(child);
    auto deadline = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(timeout_seconds));
    int status = 0;
    if (feed) {
        close(pipe_ends[0]);
        pipe_ends[0] = -1;
        fcntl(pipe_ends[1], F_SETFL, fcntl(pipe_ends[1], F_GETFL) | O_NONBLOCK);
        // SIGPIPE held off while writing: a reader that has gone is EPIPE, not the end of this process.
        sigset_t pipe_signal, old_mask;
        sigemptyset(&pipe_signal);
        sigaddset(&pipe_signal, SIGPIPE);
        pthread_sigmask(SIG_BLOCK, &pipe_signal, &old_mask);
        const int fd = pipe_ends[1];
        std::exception_ptr failure;
        try {
            (*feed)([&](const char* bytes, std::size_t size) { return write_before(fd, bytes, size, deadline); });
        } catch (...) {
            failure = std::current_exception();
        }
        close(pipe_ends[1]);
        pipe_ends[1] = -1;
        const timespec no_wait{0, 0};
        while (sigtimedwait(&pipe_signal, nullptr, &no_wait) == SIGPIPE) {
        }
        pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
        if (failure) {
            kill(-child, SIGKILL);
            waitpid(child, &status, 0);
            std::rethrow_exception(failure);
        }
    }
    for (;;) {
        pid_t done = waitpid(child, &status, WNOHANG);
        if (done == child)
            break;
        if (done < 0 && errno != EINTR)
            return result;
        if (std::chrono::steady_clock::now() > deadline) {
            kill(-child, SIGKILL);
            waitpid(child, &status, 0);
            result.timed_out = true;
            return result;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (WIFEXITED(status))
        result.exit_code = WEXITSTATUS(status);
    else if (WIFSIGNALED(status))
        result.signal = WTERMSIG(status);
    return result;
}

} // namespace

program_result run_program(const std::vector<std::string>& arguments, const std::string& directory,
                           const std::string& log_name, const std::vector<std::string>& environment,
                           double timeout_seconds)
{
    return spawn_and_wait(arguments, directory, log_name, environment, timeout_seconds, nullptr);
}

program_result run_program_fed(const std::vector<std::string>& arguments, const std::string& directory,
                               const std::string& log_name, const program_feed& feed, double timeout_seconds)
{
    return spawn_and_wait(arguments, directory, log_name, {}, timeout_seconds, &feed);
}

} // namespace lagrange
