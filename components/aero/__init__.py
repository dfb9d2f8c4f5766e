"""Aero models (installed as lpc_mdo.components.aero)."""
