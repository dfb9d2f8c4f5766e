"""Energy models (installed as lpc_mdo.components.energy)."""
