"""pdps: particle dynamics in Python, driven by PDPS/LAMMPS-style input scripts."""

import os
import tempfile

__version__ = "0.1.0"

# what MPICH's hydra, Open MPI and Intel MPI set for every rank they launch
RANK_COUNT_VARIABLES = ("PMI_SIZE", "OMPI_COMM_WORLD_SIZE", "MPI_LOCALNRANKS")


def launched_ranks():
    return next((int(os.environ[v]) for v in RANK_COUNT_VARIABLES if os.environ.get(v)), 1)


# One BLAS thread per process, set before numpy loads (a user's own setting wins). The kernels are
# numba's; numpy's few BLAS calls are small, and OpenBLAS's worker threads only spin between them: under
# MPI they take the cores the other ranks need (dpd_gw on 2 ranks: 9.0 s instead of 3.1 s for 100
# steps), and on one rank they burn 40 % of a second core for the same loop time (dpd_gw, lj_melt).
# OpenMP's thread count is left to the user on one rank (a plugin's parallel numba kernel may use it).
for _variable in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS") + (("OMP_NUM_THREADS",) if launched_ranks() > 1 else ()):
    os.environ.setdefault(_variable, "1")


def _writable(folder):
    try:
        os.makedirs(folder, exist_ok=True)
        tempfile.TemporaryFile(dir=folder).close()
        return True
    except OSError:
        return False


# numba caches compiled kernels beside their module (__pycache__), else in ~/.cache/numba, and stops
# the import with a traceback when it can write neither (a read-only install and a read-only home, as
# on some clusters and in containers); the temporary folder takes the cache then.
if "NUMBA_CACHE_DIR" not in os.environ:
    _user_cache = os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "numba")
    if not (_writable(os.path.join(os.path.dirname(__file__), "__pycache__")) or _writable(_user_cache)):
        os.environ["NUMBA_CACHE_DIR"] = os.path.join(tempfile.gettempdir(), f"pdps-{os.getuid()}", "numba")
