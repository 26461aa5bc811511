"""Communicators: SerialComm on one rank, MPIComm (mpi4py) when launched by mpirun/mpiexec."""

from .. import launched_ranks
from .serial import SerialComm


def world():
    """The communicator for this process: MPI only when started as one of several ranks, so a
    serial run never imports mpi4py."""
    if launched_ranks() > 1:
        from .mpi import MPIComm
        return MPIComm()
    return SerialComm()
