// SPDX-License-Identifier: GPL-2.0-or-later
/** @file run.cpp
 *  Ensembles on threads, and the scheduler that the MPI runner shares (see run.h). */
#include "ensemble/run.h"

#include "ensemble/scheduler.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <system_error>
#include <thread>

namespace lagrange {

// Provided by mpi.cpp, or by no_mpi.cpp in a build without MPI.
ensemble_summary run_ensemble_distributed(const ensemble_problem& problem, const ensemble_run_options& options,
                                          const ensemble_sink& sink);

namespace {

std::size_t environment_count(const char* name)
{
    const char* text = std::getenv(name);
    if (!text || !*text)
        return 0;
    char* end = nullptr;
    unsigned long long value = std::strtoull(text, &end, 10);
    return *end == '\0' ? static_cast<std::size_t>(value) : 0;
}

} // namespace

void ensemble_summary::add(const ensemble_summary& part)
{
    points += part.points;
    steps += part.steps;
    failures += part.failures;
    first_failure = std::min(first_failure, part.first_failure);
    sampled += part.sampled;
    if (part.worst_error > worst_error ||
        (part.worst_error == worst_error && part.worst_error_index < worst_error_index && part.sampled > 0)) {
        worst_error = part.worst_error;
        worst_error_index = part.worst_error_index;
    }
}

std::size_t launched_processes()
{
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (std::size_t n = environment_count(name))
            return n;
    return 1;
}

bool ensemble_root_process()
{
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
        if (const char* text = std::getenv(name))
            return std::string(text) == "0";
    return true;
}

std::size_t default_ensemble_threads()
{
    std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
    std::size_t local = environment_count("OMPI_COMM_WORLD_LOCAL_SIZE");
    if (local == 0)
        local = environment_count("MPI_LOCALNRANKS");
    return std::max<std::size_t>(1, cores / std::max<std::size_t>(1, local));
}

ensemble_chunk_result compute_chunk(const ensemble_problem& problem, ensemble_workspace& work, ensemble_chunk chunk)
{
    const std::size_t width = problem.columns().size();
    ensemble_chunk_result result;
    result.chunk = chunk;
    result.rows.resize(chunk.count * width);
    for (std::size_t k = 0; k < chunk.count; ++k) {
        std::size_t index = chunk.first + k;
        ensemble_point_stats point = problem.compute(index, work, result.rows.data() + k * width);
        ensemble_summary& s = result.stats;
        ++s.points;
        s.steps += point.steps;
        if (point.failed) {
            ++s.failures;
            s.first_failure = std::min(s.first_failure, index);
        }
        if (point.sampled) {
            ++s.sampled;
            if (s.worst_error_index == ensemble_summary::none || point.error > s.worst_error) {
                s.worst_error = point.error;
                s.worst_error_index = index;
            }
        }
    }
    return result;
}

ensemble_scheduler::ensemble_scheduler(const ensemble_problem& problem, const ensemble_run_options& options,
                                       const ensemble_sink& sink, std::size_t workers)
    : problem_(problem), options_(options), sink_(sink), next_(options.first), written_(options.first)
{
    // Chunks small enough to balance the load (about 64 per worker), large enough that handing
    // them out costs nothing next to computing them.
    const std::size_t remaining = problem.points() > options.first ? problem.points() - options.first : 0;
    chunk_size_ = std::clamp<std::size_t>(remaining / (64 * std::max<std::size_t>(1, workers)), 1, 256);
    window_ = std::max<std::size_t>(16, 32 * workers);
}

bool ensemble_scheduler::may_hand_out(std::size_t first) const
{
    return (first - written_) / chunk_size_ < window_;
}

ensemble_scheduler::offer ensemble_scheduler::try_take(ensemble_chunk& chunk)
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_ || next_ >= problem_.points())
        return offer::none;
    if (!may_hand_out(next_))
        return offer::wait;
    chunk.first = next_;
    chunk.count = std::min(chunk_size_, problem_.points() - next_);
    next_ += chunk.count;
    return offer::chunk;
}

bool ensemble_scheduler::take(ensemble_chunk& chunk)
{
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return error_ || next_ >= problem_.points() || may_hand_out(next_); });
    if (error_ || next_ >= problem_.points())
        return false;
    chunk.first = next_;
    chunk.count = std::min(chunk_size_, problem_.points() - next_);
    next_ += chunk.count;
    return true;
}

void ensemble_scheduler::complete(ensemble_chunk_result&& result)
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_)
        return;
    const std::size_t width = problem_.columns().size();
    bool wrote = false;
    try {
        done_.emplace(result.chunk.first, std::move(result));
        for (auto next = done_.find(written_); next != done_.end(); next = done_.find(written_)) {
            if (written_ == options_.first && sink_.begin)
                sink_.begin();
            const ensemble_chunk_result& r = next->second;
            for (std::size_t k = 0; k < r.chunk.count; ++k)
                sink_.row(r.chunk.first + k, r.rows.data() + k * width);
            summary_.add(r.stats);
            written_ += r.chunk.count;
            done_.erase(next);
            wrote = true;
        }
        if (wrote && options_.progress)
            options_.progress(written_ - options_.first, problem_.points() - options_.first);
    } catch (...) {
        error_ = std::current_exception();
    }
    changed_.notify_all();
}

bool ensemble_scheduler::finished()
{
    std::lock_guard<std::mutex> lock(mutex_);
    return written_ >= problem_.points() || error_;
}

void ensemble_scheduler::abort(std::exception_ptr error)
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error_)
        error_ = error;
    changed_.notify_all();
}

void ensemble_scheduler::rethrow()
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_)
        std::rethrow_exception(error_);
}

ensemble_summary ensemble_scheduler::summary()
{
    std::lock_guard<std::mutex> lock(mutex_);
    return summary_;
}

void compute_until_done(const ensemble_problem& problem, ensemble_scheduler& scheduler)
{
    try {
        ensemble_workspace workspace;
        ensemble_chunk chunk;
        while (scheduler.take(chunk))
            scheduler.complete(compute_chunk(problem, workspace, chunk));
    } catch (...) {
        scheduler.abort(std::current_exception());
    }
}

std::vector<std::thread> start_threads(std::size_t count, const std::function<void()>& work)
{
    std::vector<std::thread> pool;
    pool.reserve(count);
    try {
        for (std::size_t k = 0; k < count; ++k)
            pool.emplace_back(work);
    } catch (const std::system_error&) {
    }
    return pool;
}

ensemble_summary run_ensemble(const ensemble_problem& problem, const ensemble_run_options& options,
                              const ensemble_sink& sink)
{
    if (launched_processes() > 1)
        return run_ensemble_distributed(problem, options, sink);
    const auto start = std::chrono::steady_clock::now();
    const std::size_t threads = options.threads ? options.threads : default_ensemble_threads();
    ensemble_scheduler scheduler(problem, options, sink, threads);
    if (options.first >= problem.points() && sink.begin)
        sink.begin(); // nothing left to compute (a finished run resumed)
    std::vector<std::thread> pool = start_threads(threads - 1, [&] { compute_until_done(problem, scheduler); });
    compute_until_done(problem, scheduler); // this thread is one of them
    for (std::thread& t : pool)
        t.join();
    scheduler.rethrow();
    ensemble_summary summary = scheduler.summary();
    summary.threads = pool.size() + 1;
    summary.threads_asked = threads;
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

} // namespace lagrange
