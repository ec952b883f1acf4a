// SPDX-License-Identifier: GPL-2.0-or-later
/** @file no_mpi.cpp
 *  The distributed runner of a build without MPI (CMake did not find it): a clear error when
 *  such a binary is started by `mpirun` with more than one process, instead of every process
 *  computing the whole ensemble. */
#include "ensemble/run.h"

namespace lagrange {

ensemble_summary run_ensemble_distributed(const ensemble_problem&, const ensemble_run_options&, const ensemble_sink&)
{
    throw computation_error("this lagrange was built without MPI, but mpirun started it as one of " +
                            std::to_string(launched_processes()) +
                            " processes: install OpenMPI (Debian: libopenmpi-dev openmpi-bin) and build again, "
                            "or run it without mpirun (it uses every core of this machine with threads)");
}

bool ensemble_mpi_available() { return false; }

} // namespace lagrange
