"""MPI helpers: the package's internal problems always run serially, one per process."""

from openmdao.utils.mpi import MPI


def serial_comm():
    """MPI.COMM_SELF under MPI (so a helper problem is not spread over the ranks), else None."""
    return MPI.COMM_SELF if MPI is not None else None
