"""Weights models (installed as lpc_mdo.components.weights)."""
