"""Motor models (installed as lpc_mdo.components.motor)."""
