// SPDX-License-Identifier: GPL-2.0-or-later
/** @file run.h
 *  An ensemble run in parallel: threads on this machine (std::thread, one workspace each,
 *  the compiled problem shared read-only), and under `mpirun` processes on several machines
 *  (mpi.cpp, built when CMake finds MPI). The points are handed out in chunks of
 *  consecutive indices on demand (dynamic load balancing: points near a separatrix cost far
 *  more than others), and the rows are given back in index order, from a reorder buffer of a
 *  bounded number of chunks, so that memory stays constant in the number of points and the
 *  output is the same for any number of threads and processes. */
#pragma once

#include "ensemble/ensemble.h"

#include <cstddef>
#include <functional>
#include <limits>

namespace lagrange {

/// What a run (or one chunk of it) cost, and its error estimate.
struct ensemble_summary {
    static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    std::size_t points = 0;         ///< points computed in this run
    std::size_t steps = 0;          ///< accepted DOP853 steps, the error-estimate reruns included
    std::size_t failures = 0;       ///< points whose integration failed (NaN measures)
    std::size_t first_failure = none;
    std::size_t sampled = 0;        ///< points rerun at tolerance/1000
    double worst_error = 0;         ///< largest |measure − tight measure| over them
    std::size_t worst_error_index = none;
    std::size_t threads = 1;        ///< per process
    std::size_t threads_asked = 1;  ///< per process: more than `threads` when the system refused some
    std::size_t processes = 1;
    double seconds = 0;
    bool root = true;               ///< this process received the rows (MPI rank 0)
    void add(const ensemble_summary& part); ///< the counts, failures and errors of another part
};

/// Where the rows go, on the root process only: `begin` once before the first row, then
/// `row` for each point in index order, one call at a time.
struct ensemble_sink {
    std::function<void()> begin;
    std::function<void(std::size_t index, const double* row)> row;
};

struct ensemble_run_options {
    std::size_t threads = 0;       ///< per process; 0: the cores divided among the processes on this machine
    std::size_t first = 0;         ///< start at this point (--resume)
    /// Under MPI: a process that sends nothing for this long (stopped, or on a frozen node)
    /// ends the run with a message that names it; every process sends a sign of life each second.
    double silence_seconds = 60;
    /// Called on the root now and then with the points written so far (of `first`…) and the total.
    std::function<void(std::size_t done, std::size_t total)> progress;
};

/// Computes points first … points()−1 and hands their rows to `sink`. Under mpirun with
/// more than one process, the processes share the work and rank 0 receives every row;
/// a build without MPI then throws computation_error saying so.
ensemble_summary run_ensemble(const ensemble_problem& problem, const ensemble_run_options& options,
                              const ensemble_sink& sink);

/// The number of processes `mpirun` started this one among (OMPI_COMM_WORLD_SIZE, PMI_SIZE), or 1.
std::size_t launched_processes();
/// Whether this process is rank 0 of its `mpirun` (OMPI_COMM_WORLD_RANK, PMI_RANK), or was not started by it.
bool ensemble_root_process();
/// Whether this binary was built with MPI.
bool ensemble_mpi_available();

} // namespace lagrange
