// SPDX-License-Identifier: GPL-2.0-or-later
/** @file mpi.cpp
 *  Ensembles across processes with MPI (compiled only when CMake finds MPI). Rank 0 hands
 *  out chunks on request (dynamic load balancing), receives every chunk's rows and writes
 *  them in order through the same bounded reorder buffer as threads (scheduler.h);
 *  every rank computes with its own threads. Only the main thread of a process calls MPI
 *  (MPI_THREAD_FUNNELED), and it polls with short sleeps rather than blocking, since Open
 *  MPI's blocking calls spin and would take a core from the computing threads. */
#include "ensemble/run.h"

#include "ensemble/scheduler.h"
#include "numeric/values.h"

#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <deque>
#include <iostream>
#include <thread>

namespace lagrange {

namespace {

constexpr int tag_request = 1; ///< worker → 0: the worker's signature; wants one chunk
constexpr int tag_chunk = 2;   ///< 0 → worker: {first, count}; count 0: no more
constexpr int tag_result = 3;  ///< worker → 0: header then rows (doubles)
constexpr int tag_alive = 4;   ///< worker → 0, each second: still there (no data)
constexpr std::size_t header_size = 9;

void pause() { std::this_thread::sleep_for(std::chrono::microseconds(200)); }

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point then)
{
    return std::chrono::duration<double>(clock_type::now() - then).count();
}

/// The error for a process silent for longer than `limit` seconds (--mpi-timeout).
computation_error silent_rank(int rank, double limit)
{
    return computation_error("MPI rank " + std::to_string(rank) + " has sent nothing for more than " +
                             message_number(limit) + " s (stopped, or its node froze): the run is ended");
}

double index_number(std::size_t index) { return index == ensemble_summary::none ? -1.0 : static_cast<double>(index); }
std::size_t number_index(double x) { return x < 0 ? ensemble_summary::none : static_cast<std::size_t>(x); }

std::vector<double> encode(const ensemble_chunk_result& r)
{
    const ensemble_summary& s = r.stats;
    std::vector<double> message{static_cast<double>(r.chunk.first), static_cast<double>(r.chunk.count),
                                static_cast<double>(s.points), static_cast<double>(s.steps),
                                static_cast<double>(s.failures), index_number(s.first_failure),
                                static_cast<double>(s.sampled), s.worst_error, index_number(s.worst_error_index)};
    message.insert(message.end(), r.rows.begin(), r.rows.end());
    return message;
}

ensemble_chunk_result decode(const std::vector<double>& message)
{
    ensemble_chunk_result r;
    r.chunk.first = static_cast<std::size_t>(message[0]);
    r.chunk.count = static_cast<std::size_t>(message[1]);
    r.stats.points = static_cast<std::size_t>(message[2]);
    r.stats.steps = static_cast<std::size_t>(message[3]);
    r.stats.failures = static_cast<std::size_t>(message[4]);
    r.stats.first_failure = number_index(message[5]);
    r.stats.sampled = static_cast<std::size_t>(message[6]);
    r.stats.worst_error = message[7];
    r.stats.worst_error_index = number_index(message[8]);
    r.rows.assign(message.begin() + header_size, message.end());
    return r;
}

/// Rank 0: its own threads compute through the scheduler; its main thread serves the others.
void serve(const ensemble_problem& problem, ensemble_scheduler& scheduler, int ranks, std::size_t threads,
           double silence_seconds)
{
    // Rank 0's main thread serves; its pool may be smaller than asked (start_threads).
    std::vector<std::thread> pool = start_threads(threads, [&] { compute_until_done(problem, scheduler); });
    const unsigned long long signature = problem.signature();
    std::deque<int> waiting; // ranks whose request is not answered yet
    int stopped = 0;
    std::vector<double> message;
    std::vector<clock_type::time_point> heard(static_cast<std::size_t>(ranks), clock_type::now());
    std::vector<bool> released(static_cast<std::size_t>(ranks), false); // told "no more"
    while (!(scheduler.finished() && stopped == ranks - 1)) {
        bool progressed = false;
        int flag = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
        if (flag)
            heard[static_cast<std::size_t>(status.MPI_SOURCE)] = clock_type::now();
        if (flag && status.MPI_TAG == tag_alive) {
            MPI_Recv(nullptr, 0, MPI_BYTE, status.MPI_SOURCE, tag_alive, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            progressed = true;
        } else if (flag && status.MPI_TAG == tag_request) {
            unsigned long long theirs = 0;
            MPI_Recv(&theirs, 1, MPI_UNSIGNED_LONG_LONG, status.MPI_SOURCE, tag_request, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE);
            if (theirs != signature)
                scheduler.abort(std::make_exception_ptr(computation_error(
                    "MPI rank " + std::to_string(status.MPI_SOURCE) +
                    " computes another ensemble than rank 0 (a different scene, grid, option or build, or native "
                    "code on one and the interpreter on the other)")));
            waiting.push_back(status.MPI_SOURCE);
            progressed = true;
        } else if (flag && status.MPI_TAG == tag_result) {
            int count = 0;
            MPI_Get_count(&status, MPI_DOUBLE, &count);
            message.resize(static_cast<std::size_t>(count));
            MPI_Recv(message.data(), count, MPI_DOUBLE, status.MPI_SOURCE, tag_result, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE);
            scheduler.complete(decode(message));
            progressed = true;
        }
        while (!waiting.empty()) {
            ensemble_chunk chunk;
            ensemble_scheduler::offer offer = scheduler.try_take(chunk);
            if (offer == ensemble_scheduler::offer::wait)
                break;
            unsigned long long reply[2] = {0, 0};
            if (offer == ensemble_scheduler::offer::chunk) {
                reply[0] = chunk.first;
                reply[1] = chunk.count;
            } else {
                ++stopped;
                released[static_cast<std::size_t>(waiting.front())] = true;
            }
            MPI_Send(reply, 2, MPI_UNSIGNED_LONG_LONG, waiting.front(), tag_chunk, MPI_COMM_WORLD);
            waiting.pop_front();
            progressed = true;
        }
        for (int rank = 1; rank < ranks; ++rank) {
            const double silent = seconds_since(heard[static_cast<std::size_t>(rank)]);
            if (!released[static_cast<std::size_t>(rank)] && silent > silence_seconds) {
                scheduler.abort(std::make_exception_ptr(silent_rank(rank, silence_seconds)));
                for (std::thread& t : pool)
                    t.join();
                throw silent_rank(rank, silence_seconds);
            }
        }
        if (!progressed)
            pause();
    }
    for (std::thread& t : pool)
        t.join();
}

/// Ranks 1 …: ask rank 0 for chunks, compute them with `threads` threads, send the rows back.
void work(const ensemble_problem& problem, std::size_t threads, double silence_seconds)
{
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<ensemble_chunk> queue;
    std::deque<ensemble_chunk_result> outbox;
    bool stopped = false;
    std::size_t active = 0;
    std::exception_ptr error;
    std::vector<std::thread> pool = start_threads(threads, [&] {
            ensemble_workspace workspace;
            std::unique_lock<std::mutex> lock(mutex);
            for (;;) {
                changed.wait(lock, [&] { return !queue.empty() || stopped; });
                if (queue.empty())
                    return;
                ensemble_chunk chunk = queue.front();
                queue.pop_front();
                ++active;
                lock.unlock();
                try {
                    ensemble_chunk_result result = compute_chunk(problem, workspace, chunk);
                    lock.lock();
                    outbox.push_back(std::move(result));
                } catch (...) {
                    lock.lock();
                    error = std::current_exception();
                }
                --active;
            }
        });
    if (pool.empty())
        throw computation_error("no computing thread could be started on this rank (the system refused them)");
    const unsigned long long signature = problem.signature();
    bool asked = false, done = false;
    clock_type::time_point said = clock_type::now();  // the last message to rank 0
    clock_type::time_point heard = clock_type::now(); // the last reply from rank 0
    while (!done) {
        bool progressed = false;
        if (seconds_since(said) > 1) {
            MPI_Send(nullptr, 0, MPI_BYTE, 0, tag_alive, MPI_COMM_WORLD);
            said = clock_type::now();
        }
        if (asked && seconds_since(heard) > silence_seconds) {
            std::lock_guard<std::mutex> lock(mutex);
            error = std::make_exception_ptr(silent_rank(0, silence_seconds));
            break; // the pool is stopped below, and the error rethrown
        }
        std::deque<ensemble_chunk_result> sending;
        {
            std::lock_guard<std::mutex> lock(mutex);
            if (error)
                break;
            sending.swap(outbox);
            if (!stopped && !asked && queue.size() < threads) {
                MPI_Send(&signature, 1, MPI_UNSIGNED_LONG_LONG, 0, tag_request, MPI_COMM_WORLD);
                asked = true;
                said = heard = clock_type::now();
            }
        }
        if (asked) {
            int flag = 0;
            MPI_Iprobe(0, tag_chunk, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
            if (flag) {
                unsigned long long reply[2];
                MPI_Recv(reply, 2, MPI_UNSIGNED_LONG_LONG, 0, tag_chunk, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                heard = clock_type::now();
                std::lock_guard<std::mutex> lock(mutex);
                if (reply[1] == 0)
                    stopped = true;
                else
                    queue.push_back({static_cast<std::size_t>(reply[0]), static_cast<std::size_t>(reply[1])});
                asked = false;
                progressed = true;
                changed.notify_all();
            }
        }
        for (const ensemble_chunk_result& r : sending) {
            std::vector<double> message = encode(r);
            MPI_Send(message.data(), static_cast<int>(message.size()), MPI_DOUBLE, 0, tag_result, MPI_COMM_WORLD);
            said = clock_type::now();
            progressed = true;
        }
        {
            std::lock_guard<std::mutex> lock(mutex);
            done = stopped && queue.empty() && active == 0 && outbox.empty();
        }
        if (!progressed && !done)
            pause();
    }
    {
        std::lock_guard<std::mutex> lock(mutex);
        stopped = true;
        queue.clear();
        changed.notify_all();
    }
    for (std::thread& t : pool)
        t.join();
    if (error)
        std::rethrow_exception(error);
}

} // namespace

ensemble_summary run_ensemble_distributed(const ensemble_problem& problem, const ensemble_run_options& options,
                                          const ensemble_sink& sink)
{
    const auto start = std::chrono::steady_clock::now();
    int provided = 0, rank = 0, ranks = 1;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    const std::size_t threads = options.threads ? options.threads : default_ensemble_threads();
    ensemble_summary summary;
    try {
        if (rank == 0) {
            ensemble_scheduler scheduler(problem, options, sink,
                                         threads * static_cast<std::size_t>(ranks));
            if (options.first >= problem.points() && sink.begin)
                sink.begin();
            serve(problem, scheduler, ranks, threads, options.silence_seconds);
            scheduler.rethrow();
            summary = scheduler.summary();
        } else {
            work(problem, threads, options.silence_seconds);
            summary.root = false;
        }
    } catch (const std::exception& e) {
        // One rank cannot go on: the others would wait for it forever.
        std::cerr << "lagrange: error: (MPI rank " << rank << ") " << e.what() << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    MPI_Finalize();
    summary.threads = threads;
    summary.processes = static_cast<std::size_t>(ranks);
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

bool ensemble_mpi_available() { return true; }

} // namespace lagrange
