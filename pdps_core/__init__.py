"""pdps: particle dynamics in Python, driven by PDPS/LAMMPS-style input scripts."""

import os

__version__ = "0.1.0"

# what MPICH's hydra, Open MPI and Intel MPI set for every rank they launch
RANK_COUNT_VARIABLES = ("PMI_SIZE", "OMPI_COMM_WORLD_SIZE", "MPI_LOCALNRANKS")


def launched_ranks():
    return next((int(os.environ[v]) for v in RANK_COUNT_VARIABLES if os.environ.get(v)), 1)


# One BLAS thread per MPI rank, set before numpy loads: OpenBLAS's spinning worker threads otherwise
# take the cores the other ranks need (dpd_gw on 2 ranks: 9.0 s instead of 3.1 s for 100 steps).
if launched_ranks() > 1:
    for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(_variable, "1")
