"""The foundation of lpc-mdo: input checks, physical constants, numerics and MPI helpers.

These modules import nothing else of the project; every other layer (the vehicle data, the
components, the groups and the application) may import them.
"""
