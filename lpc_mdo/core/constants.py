"""Physical constants used by more than one model, defined once.

``GRAVITY`` is the gravitational acceleration of the equations of motion, the structural
inertia loads and the trim-residual bookkeeping: 9.81 m/s**2, the value of the study's
reference model (paper eq. 29). The standard atmosphere keeps its own ``g0`` = 9.80665 m/s**2
(U.S. Standard Atmosphere 1976), which defines the geopotential altitude of its tables and is a
property of that model, not of the vehicle dynamics.

The sea-level density and speed of sound are the defaults of the components' ``density`` and
``speed_of_sound`` inputs (in the assembled model the atmosphere component sets them), and
``RPM_TO_RAD_S`` converts every rotor speed.
"""

import math

#: Gravitational acceleration of the vehicle dynamics, m/s**2 (paper eq. 29).
GRAVITY = 9.81

#: Air density at ICAO/ISA sea level, kg/m**3 (p0 / (R T0) of the standard atmosphere). The
#: default of the components' ``density`` inputs; in the model the atmosphere sets the value.
SEA_LEVEL_DENSITY = 1.225

#: Speed of sound at ICAO/ISA sea level, m/s (sqrt(gamma R T0)). The default of the components'
#: ``speed_of_sound`` inputs; in the model the atmosphere sets the value.
SEA_LEVEL_SPEED_OF_SOUND = 340.294

#: Conversion of a rotational speed from rpm to rad/s, 2 pi / 60.
RPM_TO_RAD_S = math.pi / 30.0
