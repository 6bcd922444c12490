#pragma once
/// The job's communicator: Open MPI's MPI_COMM_WORLD when this process was started by
/// `mpirun` (or srun) and simhuman was built with Open MPI (CMake option SIMHUMAN_MPI), else
/// core::SerialCommunicator. A process started without a launcher never initialises MPI, so
/// the single-process binary behaves as one built without MPI. No mpi.h here.

#include <memory>

#include "simhuman/core/communicator.h"

namespace simhuman::dist {

/// True when this binary was built with Open MPI.
bool MpiBuilt();

/// True when an MPI launcher started this process (Open MPI's OMPI_COMM_WORLD_SIZE, or PMI /
/// PMIx variables that srun sets).
bool LaunchedByMpi();

/// The communicator of this process (see the file comment). Initialises MPI once per process
/// (MPI_THREAD_FUNNELED: only the main thread calls it) and finalises it when the returned
/// object is destroyed. Errors: Internal when MPI was launched but cannot start, or
/// FailedPrecondition when a launcher started this process but the binary has no MPI and more
/// than one rank was requested (each rank would run the whole job alone).
core::StatusOr<std::unique_ptr<core::Communicator>> StartCommunicator();

}  // namespace simhuman::dist
