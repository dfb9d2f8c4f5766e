"""Physical constants used by more than one model, defined once.

``GRAVITY`` is the gravitational acceleration of the equations of motion, the structural
inertia loads and the trim-residual bookkeeping: 9.81 m/s**2, the value of the study's
reference model (paper eq. 29). The standard atmosphere keeps its own ``g0`` = 9.80665 m/s**2
(U.S. Standard Atmosphere 1976), which defines the geopotential altitude of its tables and is a
property of that model, not of the vehicle dynamics.
"""

#: Gravitational acceleration of the vehicle dynamics, m/s**2 (paper eq. 29).
GRAVITY = 9.81
