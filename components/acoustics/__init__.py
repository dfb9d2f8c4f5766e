"""Acoustics models (installed as lpc_mdo.components.acoustics)."""
