"""Blade chord margin over a minimum chord proportional to the rotor radius (a linear constraint).

docs theory/rotors 'Minimum chord'. The chord of every blade is a B-spline of its control points
(:mod:`lpc_mdo.components.geometry.blade`); B-spline basis functions are non-negative and sum to
one, so the chord at any station lies between the smallest and the largest control point (the
convex-hull property; de Boor, *A Practical Guide to Splines*, 2001, ch. IX). A lower bound on
every control point is therefore a lower bound on the whole chord distribution.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class BladeChordMarginComp(om.ExplicitComponent):
    """
    Margin of every blade-chord control point over a fraction of its rotor's radius.

    chord_margin[i, j] = chord_cp[i, j] - f R[i] (>= 0 keeps the whole chord distribution of
    rotor group i at or above f R[i]). Linear in the design variables: the partials are
    constant (declared once, ``val``), so a problem declares the constraint ``linear=True``.

    Inputs
    ------
    blade_chord_cp : float, (num_rotors, num_cp), m
        Chord control points of each rotor group, root to tip.
    rotor_radius : float, (num_rotors,), m
        Tip radius of each rotor group.

    Outputs
    -------
    blade_chord_margin : float, (num_rotors, num_cp), m
        chord_cp - min_chord_radius_ratio * radius.

    Options
    -------
    num_rotors, num_cp : int
        Rotor groups (>= 1) and chord control points per blade (>= 1).
    min_chord_radius_ratio : float
        The fraction f, in [0, 0.5] (vehicle file ``constraints.min_chord_radius_ratio``).
    """

    def initialize(self):
        self.options.declare("num_rotors", types=int, lower=1, desc="rotor groups")
        self.options.declare("num_cp", default=4, types=int, lower=1, desc="chord control points")
        self.options.declare(
            "min_chord_radius_ratio",
            default=0.03,
            types=(int, float),
            check_valid=_check_ratio,
            desc="smallest chord as a fraction of the radius, [0, 0.5]",
        )

    def setup(self):
        nr, ncp = self.options["num_rotors"], self.options["num_cp"]
        ratio = float(self.options["min_chord_radius_ratio"])
        self.add_input(
            "blade_chord_cp", np.full((nr, ncp), 0.2), units="m", desc="blade chord control points"
        )
        self.add_input("rotor_radius", np.full(nr, 1.5), units="m", desc="rotor tip radius")
        self.add_output(
            "blade_chord_margin",
            np.zeros((nr, ncp)),
            units="m",
            desc="chord control point minus the minimum chord",
        )
        n = nr * ncp
        self.declare_partials(
            "blade_chord_margin", "blade_chord_cp", rows=np.arange(n), cols=np.arange(n), val=1.0
        )
        self.declare_partials(
            "blade_chord_margin",
            "rotor_radius",
            rows=np.arange(n),
            cols=np.repeat(np.arange(nr), ncp),
            val=-ratio,
        )

    def compute(self, inputs, outputs):
        ratio = float(self.options["min_chord_radius_ratio"])
        outputs["blade_chord_margin"] = (
            inputs["blade_chord_cp"] - ratio * inputs["rotor_radius"][:, None]
        )


def _check_ratio(name, value):
    check_range(name, value, lower=0.0, upper=0.5)
