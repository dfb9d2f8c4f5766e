"""OpenMDAO groups of lpc-mdo: assemblies of components (installed as lpc_mdo.groups)."""
