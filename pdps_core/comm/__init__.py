"""Communicators: SerialComm on one rank, MPIComm (mpi4py) when launched by mpirun/mpiexec."""

import os

from .serial import SerialComm

# what MPICH's hydra, Open MPI and Intel MPI set for every rank they launch
RANK_COUNT_VARIABLES = ("PMI_SIZE", "OMPI_COMM_WORLD_SIZE", "MPI_LOCALNRANKS")


def world():
    """The communicator for this process: MPI only when started as one of several ranks, so a
    serial run never imports mpi4py."""
    size = next((int(os.environ[v]) for v in RANK_COUNT_VARIABLES if os.environ.get(v)), 1)
    if size > 1:
        from .mpi import MPIComm
        return MPIComm()
    return SerialComm()
