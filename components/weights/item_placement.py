"""Stations of the mass items in the fuselage's zones: nose bay, cabin, under the floor, tail cone.

The fuselage is a nose bay, a cabin and a tail cone (docs theory/geometry 'Fuselage zones'). A
change of the fuselage length goes into the tail cone, between the cabin's aft bulkhead and the
tail: an item ahead of that plug keeps its body-frame station, an item carried by the tail end
(the empennage, the pusher with its motor and gearbox) moves aft by the change of length. This
module holds the stations of the NASA lift-plus-cruise items that sit ahead of the plug and the
component that moves the items that ride on the tail.

NASA's NDARC weight statement of the LPC places its landing gear and its systems group
(NASA SACD UAM reference configurations, https://sacd.larc.nasa.gov/uam-refs/, as transcribed in
NASA's GUAM, github.com/nasa/Generic-Urban-Air-Mobility-GUAM,
vehicles/Lift+Cruise/AeroProp/SFunction/build_Lift_plus_Cruise.m: gear at
(-13.32464336, 0, -1.391179415) ft, systems at (-16, 0, -6) ft). GUAM's frame is the CAD frame
in feet with x aft negative, so the body frame (origin at the nose, CAD (2.464, 0, 5.113) ft)
has x = (x_GUAM + 2.464) 0.3048 and z = (z_GUAM + 5.113) 0.3048 (docs theory/weights 'Positions').
"""

import numpy as np
import openmdao.api as om

_FT = 0.3048
_NOSE_X_FT, _NOSE_Z_FT = 2.464, 5.113


def _guam_to_body(x_ft, z_ft):
    return ((x_ft + _NOSE_X_FT) * _FT, 0.0, (z_ft + _NOSE_Z_FT) * _FT)


#: Landing-gear cg of NASA's LPC weight statement, body frame (m): 3.31 m aft of the nose, under
#: the cabin floor (the wheels hang 0.6 m below the fuselage's bottom line).
NASA_LANDING_GEAR_STATION = _guam_to_body(-13.32464336, -1.391179415)
#: Systems-group cg of NASA's LPC weight statement, body frame (m): 4.13 m aft of the nose, the
#: equipment bay behind the cabin's aft bulkhead (3.86 m in the reference vehicle).
NASA_SYSTEMS_STATION = _guam_to_body(-16.0, -6.0)


def _rows(name, value):
    """Return the 0/1 mask of an item's rows and its cg shape ((3,) for a single 0 or 1)."""
    mask = np.atleast_1d(np.asarray(value))
    if mask.ndim != 1 or mask.size == 0 or not np.all((mask == 0) | (mask == 1)):
        raise ValueError(
            f"Option '{name}' = {value!r}; must be 0, 1 or a non-empty 1-D sequence of 0 and 1."
        )
    return mask.astype(float), (3,) if np.ndim(value) == 0 else (mask.size, 3)


class TailConeShiftComp(om.ExplicitComponent):
    """
    Positions of items carried by the tail end: they move aft with a tail-cone stretch.

    A change of fuselage length is a plug in the tail cone (docs theory/geometry 'Fuselage
    zones'), so what the tail end carries (the empennage, the pusher's rotor, motor and
    gearbox) moves with the fuselage's end: with the body x forward,

        p = p_ref - (L - L_ref) e_x

    on the rows marked 1 in ``rows``; the other rows keep their position (p = p_ref). The same
    rule moves the tail surfaces (:class:`~lpc_mdo.components.geometry.tail_position.
    TailPositionComp`) and the pusher hub (:class:`~lpc_mdo.components.geometry.rotor_layout.
    RotorLayoutComp`). Linear; constant sparse partials.

    Inputs
    ------
    fuselage_length : float, (1,), m
    {name}_reference_cg : float, (n, 3) or (3,), m
        One per entry of ``items``: the positions at the reference fuselage length.

    Outputs
    -------
    {name}_cg : float, (n, 3) or (3,), m

    Options
    -------
    items : dict of str -> 0, 1 or sequence of 0/1
        name -> per row (n rows), 1 if the row rides on the tail end; a single 0 or 1 for one
        body of shape (3,).
    reference_length : float
        L_ref, the fuselage length of the reference positions (m, > 0).
    """

    def initialize(self):
        self.options.declare("items", types=dict, desc="name -> rows riding on the tail (0/1)")
        self.options.declare("reference_length", types=(int, float), lower=0.0, desc="L_ref, m")

    def setup(self):
        length = float(self.options["reference_length"])
        self.add_input("fuselage_length", length, units="m", desc="fuselage length")
        self._masks = {}
        for name, rows in self.options["items"].items():
            mask, shape = _rows(f"items[{name!r}]", rows)
            self._masks[name] = mask
            self.add_input(
                f"{name}_reference_cg",
                np.zeros(shape),
                units="m",
                desc=f"cg of {name} at the reference fuselage length",
            )
            self.add_output(f"{name}_cg", np.zeros(shape), units="m", desc=f"cg of {name}")
            diagonal = np.arange(3 * mask.size)
            self.declare_partials(
                f"{name}_cg", f"{name}_reference_cg", rows=diagonal, cols=diagonal, val=1.0
            )
            moving = 3 * np.flatnonzero(mask)
            self.declare_partials(
                f"{name}_cg", "fuselage_length", rows=moving, cols=0 * moving, val=-1.0
            )

    def compute(self, inputs, outputs):
        shift = inputs["fuselage_length"][0] - self.options["reference_length"]
        for name, mask in self._masks.items():
            cg = inputs[f"{name}_reference_cg"].reshape(-1, 3).copy()
            cg[:, 0] -= shift * mask
            outputs[f"{name}_cg"] = cg.reshape(outputs[f"{name}_cg"].shape)


__all__ = ["NASA_LANDING_GEAR_STATION", "NASA_SYSTEMS_STATION", "TailConeShiftComp"]
