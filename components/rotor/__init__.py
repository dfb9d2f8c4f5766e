"""Rotor models (installed as lpc_mdo.components.rotor)."""
