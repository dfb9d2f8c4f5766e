"""lpc-mdo: system-level MDO of the NASA lift-plus-cruise eVTOL air taxi in OpenMDAO."""

__version__ = "0.1.0"
