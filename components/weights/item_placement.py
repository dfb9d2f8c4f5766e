"""Positions of mass items that sit at fixed fractions of the fuselage length."""

import numpy as np
import openmdao.api as om


def _check_stations(name, value):
    if not isinstance(value, dict) or not value:
        raise ValueError(f"Option '{name}' = {value!r}; must be a non-empty dict.")
    for key, station in value.items():
        if not (isinstance(key, str) and key.isidentifier()):
            raise ValueError(f"Option '{name}': key {key!r} must be a Python identifier.")
        if len(station) != 3 or not 0.0 <= float(station[0]) <= 1.5:
            raise ValueError(
                f"Option '{name}': station of {key!r} = {station!r}; must be "
                "(x_fraction in [0, 1.5], y, z)."
            )


class FuselageStationComp(om.ExplicitComponent):
    """
    cg of items placed at fuselage stations: x = -f_x L_fuselage, y and z fixed (body frame).

    The body frame has its origin at the fuselage nose and x forward (docs getting_started
    'Conventions'), so an item at the fraction f_x of the fuselage length sits at x = -f_x L
    and moves aft when the fuselage is stretched. Linear: d x / d L = -f_x.

    Inputs
    ------
    fuselage_length : float, (1,), m

    Outputs
    -------
    {name}_cg : float, (3,), m
        One per station.

    Options
    -------
    stations : dict of str -> (float, float, float)
        name -> (f_x, y in m, z in m).
    """

    def initialize(self):
        self.options.declare(
            "stations", types=dict, check_valid=_check_stations, desc="name -> (f_x, y, z)"
        )

    def setup(self):
        self.add_input("fuselage_length", 9.144, units="m", desc="fuselage length")
        for name, (fx, _, _) in self.options["stations"].items():
            self.add_output(f"{name}_cg", np.zeros(3), units="m", desc=f"cg of {name}")
            self.declare_partials(f"{name}_cg", "fuselage_length", rows=[0], cols=[0], val=-fx)

    def compute(self, inputs, outputs):
        length = inputs["fuselage_length"][0]
        for name, (fx, y, z) in self.options["stations"].items():
            outputs[f"{name}_cg"] = np.array([-fx * length, y, z])
