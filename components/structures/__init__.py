"""Structures models (installed as lpc_mdo.components.structures)."""
