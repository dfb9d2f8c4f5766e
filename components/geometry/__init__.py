"""Geometry models (installed as lpc_mdo.components.geometry)."""
