"""Dynamics models (installed as lpc_mdo.components.dynamics)."""
