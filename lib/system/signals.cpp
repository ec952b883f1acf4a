// SPDX-License-Identifier: GPL-2.0-or-later
/** @file signals.cpp
 *  The registry of temporaries and children, and the SIGINT/SIGTERM handlers.
 *  Hand-written: removing files from a signal handler allows only async-signal-safe
 *  calls (no allocation, no locks, no opendir), which no library offers for this. */
#include "system/signals.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

namespace lagrange {

namespace {

constexpr int path_slots = 64;
constexpr int child_slots = 16;
constexpr std::size_t max_path = 4096;

enum slot_state : int { free_slot = 0, being_written = 1, registered = 2 };

struct path_slot {
    std::atomic<int> state{free_slot};
    bool folder = false;
    char path[max_path] = {};
};

path_slot paths[path_slots];
std::atomic<pid_t> children[child_slots];

int claim_path(const std::string& path, bool folder)
{
    if (path.empty() || path.size() >= max_path)
        return -1;
    for (int k = 0; k < path_slots; ++k) {
        int expected = free_slot;
        if (paths[k].state.compare_exchange_strong(expected, being_written)) {
            std::memcpy(paths[k].path, path.c_str(), path.size() + 1);
            paths[k].folder = folder;
            paths[k].state.store(registered);
            return k;
        }
    }
    return -1;
}

/// Removes the files of a one-level folder, then the folder: getdents64 and unlinkat are
/// plain system calls, safe in a handler where opendir/readdir are not.
void remove_flat_folder(const char* path)
{
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        alignas(8) char buffer[4096];
        for (;;) {
            long bytes = syscall(SYS_getdents64, fd, buffer, sizeof buffer);
            if (bytes <= 0)
                break;
            for (long offset = 0; offset < bytes;) {
                // struct linux_dirent64: ino (8), off (8), reclen (2), type (1), name
                unsigned short length;
                std::memcpy(&length, buffer + offset + 16, sizeof length);
                const char* name = buffer + offset + 19;
                if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0)
                    unlinkat(fd, name, 0);
                offset += length;
            }
        }
        close(fd);
    }
    rmdir(path);
}

void handle(int signal_number)
{
    clean_up_registered();
    _exit(128 + signal_number);
}

} // namespace

void clean_up_registered()
{
    for (std::atomic<pid_t>& child : children) {
        pid_t group = child.load();
        if (group > 0) {
            // reaped before we exit: a killed child left to init stays a zombie (and so
            // seems alive) for as long as init takes to collect it
            kill(-group, SIGKILL);
            while (waitpid(group, nullptr, 0) < 0 && errno == EINTR) {
            }
        }
    }
    for (path_slot& slot : paths) {
        if (slot.state.load() != registered)
            continue;
        if (slot.folder)
            remove_flat_folder(slot.path);
        else
            unlink(slot.path);
    }
}

void install_signal_cleanup()
{
    static std::once_flag once;
    std::call_once(once, [] {
        struct sigaction action {};
        action.sa_handler = handle;
        sigemptyset(&action.sa_mask);
        sigaddset(&action.sa_mask, SIGINT);
        sigaddset(&action.sa_mask, SIGTERM);
        sigaction(SIGINT, &action, nullptr);
        sigaction(SIGTERM, &action, nullptr);
    });
}

removed_on_signal::removed_on_signal(const std::string& path, bool folder) : slot_(claim_path(path, folder)) {}

removed_on_signal::~removed_on_signal()
{
    if (slot_ >= 0)
        paths[slot_].state.store(free_slot);
}

removed_on_signal::removed_on_signal(removed_on_signal&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }

removed_on_signal& removed_on_signal::operator=(removed_on_signal&& other) noexcept
{
    if (this != &other) {
        if (slot_ >= 0)
            paths[slot_].state.store(free_slot);
        slot_ = other.slot_;
        other.slot_ = -1;
    }
    return *this;
}

killed_on_signal::killed_on_signal(pid_t group)
{
    for (int k = 0; k < child_slots; ++k) {
        pid_t expected = 0;
        if (children[k].compare_exchange_strong(expected, group)) {
            slot_ = k;
            return;
        }
    }
}

killed_on_signal::~killed_on_signal()
{
    if (slot_ >= 0)
        children[slot_].store(0);
}

} // namespace lagrange
