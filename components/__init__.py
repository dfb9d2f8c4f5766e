"""OpenMDAO components of lpc-mdo, one module per discipline model.

Installed as ``lpc_mdo.components``.
"""
