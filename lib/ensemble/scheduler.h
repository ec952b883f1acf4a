// SPDX-License-Identifier: GPL-2.0-or-later
/** @file scheduler.h
 *  Internal to the ensemble runners (run.cpp, mpi.cpp): chunks handed out
 *  on demand, and their results written in index order from a bounded reorder buffer. */
#pragma once

#include "ensemble/run.h"

#include <condition_variable>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace lagrange {

struct ensemble_chunk {
    std::size_t first = 0, count = 0;
};

struct ensemble_chunk_result {
    ensemble_chunk chunk;
    std::vector<double> rows; ///< count × columns, row after row
    ensemble_summary stats;
};

/// Computes the points of one chunk with this thread's workspace.
ensemble_chunk_result compute_chunk(const ensemble_problem& problem, ensemble_workspace& work, ensemble_chunk chunk);

/// Threads' share of the cores: hardware threads ÷ processes on this machine, at least 1.
std::size_t default_ensemble_threads();

/// Hands out chunks of [first, points) and writes completed chunks to the sink in order. A
/// chunk is handed out only while it lies within `window` chunks of the oldest one not yet
/// written, which bounds the reorder buffer. Thread-safe.
class ensemble_scheduler {
public:
    ensemble_scheduler(const ensemble_problem& problem, const ensemble_run_options& options, const ensemble_sink& sink,
                       std::size_t workers);

    enum class offer { chunk, wait, none };
    /// A chunk if one may be handed out now, else `wait` (the window is full) or `none` (all handed out).
    offer try_take(ensemble_chunk& chunk);
    /// Waits for a chunk; false when none is left or the run was aborted.
    bool take(ensemble_chunk& chunk);
    /// Stores a completed chunk and writes every chunk that is now next in order.
    void complete(ensemble_chunk_result&& result);
    /// Every point has been written.
    bool finished();
    /// Stops the run: take() returns false from now on; rethrow() throws `error`.
    void abort(std::exception_ptr error);
    void rethrow();
    /// The totals of the chunks written.
    ensemble_summary summary();

private:
    const ensemble_problem& problem_;
    const ensemble_run_options& options_;
    const ensemble_sink& sink_;
    std::size_t chunk_size_ = 1, window_ = 1;
    std::size_t next_ = 0;          ///< first point not yet handed out
    std::size_t written_ = 0;       ///< first point not yet written
    std::map<std::size_t, ensemble_chunk_result> done_; ///< completed, not yet written, by first point
    ensemble_summary summary_;
    std::exception_ptr error_;
    std::mutex mutex_;
    std::condition_variable changed_;
    bool may_hand_out(std::size_t first) const;
};

/// One worker thread: takes chunks from the scheduler and completes them until none is
/// left; an exception aborts the run (the scheduler's rethrow() gives it).
void compute_until_done(const ensemble_problem& problem, ensemble_scheduler& scheduler);

/// Starts up to `count` threads running `work`. A thread the system refuses (EAGAIN under a
/// memory or process limit) ends the starting, not the run: the pool is what could start.
std::vector<std::thread> start_threads(std::size_t count, const std::function<void()>& work);

} // namespace lagrange
