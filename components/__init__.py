"""OpenMDAO components of lpc-mdo, one module per discipline model (installed as lpc_mdo.components)."""
