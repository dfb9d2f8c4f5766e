"""Airfoil sections of the vehicle: each polar file with the shape the model needs; both agree.

A named airfoil (:data:`~lpc_mdo.vehicle.parts.AIRFOILS`) brings its polar, thickness and
wing-box numbers. A designer's own section is a polar file plus:

- for a lifting surface, a coordinate file (``coordinates``, Selig format): its thickness and
  its position feed the drag build-up, and for the wing the wing box's depth, camber offset
  and skin radii (docs theory/structures 'Material, mesh and load transfer');
- for a rotor, its ``thickness_to_chord`` (the thickness noise, docs theory/acoustics).

Checked here, at load time: that what the model needs is there; that the coordinates and the
polar describe one section (their zero-lift angles agree: thin-airfoil theory on the coordinates
against the polar, within :data:`ZERO_LIFT_ANGLE_TOLERANCE_DEG`); that the wing's polar has
the cm column its camber moment needs; and that the tails are symmetric sections, as the model
takes them (no zero-lift angle and no camber moment enter their lattice).
"""

from __future__ import annotations

import dataclasses
import math

from lpc_mdo.components.aero.airfoil_coordinates import read_coordinates
from lpc_mdo.vehicle.parts import AIRFOILS, SECTION_THICKNESS_RANGE, Rotor
from lpc_mdo.vehicle.schema import VehicleSpecError

#: Largest difference (deg) between a polar's zero-lift angle and the thin-airfoil one of its
#: coordinates. Viscous decambering makes a measured section's zero-lift angle smaller than thin-
#: airfoil theory by up to about 15 % (Abbott & von Doenhoff, Theory of Wing Sections, 1959,
#: sec. 4.3 and appendix IV: NACA 4412 -4.0 deg measured against -4.15 deg); the shipped
#: LS(1)-0413 table lies 0.3 deg from its coordinates. A polar of another section is further
#: off: 2 % camber moves the angle by about 2 deg (NACA 2412 -2.1, 4412 -4.2 deg).
ZERO_LIFT_ANGLE_TOLERANCE_DEG = 1.5
#: Largest magnitude of the zero-lift angle (deg) of a tail section: the model takes the tails
#: as symmetric (0 deg); 0.5 deg is the zero-lift angle of 0.5 % camber, about the accuracy of a
#: symmetric section's table (NeuralFoil on NACA 0012: 0.0 deg).
TAIL_ZERO_LIFT_ANGLE_DEG = 0.5
#: Largest difference of t/c between a named airfoil and the coordinates given with it (-): a
#: table of the same section rounds to within 0.1 % (UIUC LS(1)-0413: 0.1293 for 0.13).
NAMED_THICKNESS_TOLERANCE = 0.01
#: Reynolds number (-) at which a multi-Reynolds polar's zero-lift angle is compared: the
#: wings of this vehicle class cruise at 3e6-8e6 on their mean chord (the reference 5.2e6).
_CHECK_REYNOLDS = 5e6

#: The vehicle's lifting surfaces (its fields of :class:`~lpc_mdo.vehicle.parts.LiftingSurface`).
SURFACE_NAMES = ("wing", "horizontal_tail", "vertical_tail")


def with_section_thickness(rotor: Rotor, where: str) -> Rotor:
    """Return ``rotor`` with its blade t/c: a named airfoil's own, or the file's key.

    Raises
    ------
    VehicleSpecError
        A polar-file airfoil without ``thickness_to_chord``, or a named airfoil with a
        ``thickness_to_chord`` that is not its own.
    """
    named = AIRFOILS.get(rotor.airfoil)
    if named is None:
        if rotor.thickness_to_chord is None:
            raise VehicleSpecError(
                f"missing key '{where}.thickness_to_chord' (number in "
                f"[{SECTION_THICKNESS_RANGE[0]:g}, {SECTION_THICKNESS_RANGE[1]:g}]): "
                f"'{where}.airfoil' is a polar file, which gives no thickness, and the rotor's "
                "thickness noise needs it"
            )
        return rotor
    if rotor.thickness_to_chord is None:
        return dataclasses.replace(rotor, thickness_to_chord=named.thickness_to_chord)
    if abs(rotor.thickness_to_chord - named.thickness_to_chord) > NAMED_THICKNESS_TOLERANCE:
        raise VehicleSpecError(
            f"'{where}.thickness_to_chord' = {rotor.thickness_to_chord!r} is not that of "
            f"'{where}.airfoil' = {rotor.airfoil!r} ({named.thickness_to_chord:g}); allowed: "
            "leave the key out for a named airfoil, or give the blade's own polar file"
        )
    return rotor


def check_surface_sections(parts: dict) -> None:
    """Check the wing's and the tails' sections (module docstring); raise VehicleSpecError."""
    from lpc_mdo.components.aero.airfoil import get_polar, zero_lift_angle

    for name in SURFACE_NAMES:
        surface = parts[name]
        named = AIRFOILS.get(surface.airfoil)
        if named is None and surface.coordinates is None:
            needs = "the drag build-up's thickness" + (
                " and the wing box's depth" if name == "wing" else ""
            )
            raise VehicleSpecError(
                f"missing key '{name}.coordinates' (a coordinate file, Selig format): "
                f"'{name}.airfoil' is a polar file, which gives no shape, and {needs} come from "
                "the section's coordinates"
            )
        polar = get_polar(surface.airfoil)
        reynolds = min(max(_CHECK_REYNOLDS, polar.table_reynolds[0]), polar.table_reynolds[-1])
        polar_alpha0 = math.degrees(zero_lift_angle(polar, reynolds, polar.table_mach[0]))
        if name == "wing" and polar.table_cm is None:
            raise VehicleSpecError(
                f"'wing.airfoil' = {surface.airfoil!r}: the polar has no moment coefficient; "
                "allowed: a polar with a cm column (an XFOIL polar file, whose header line "
                "'alpha CL CD CDp CM ...' names it, or an .npz with 'cm'): the wing's camber "
                "moment trims the vehicle"
            )
        if name != "wing" and abs(polar_alpha0) > TAIL_ZERO_LIFT_ANGLE_DEG:
            raise VehicleSpecError(
                f"'{name}.airfoil' = {surface.airfoil!r} has a zero-lift angle of "
                f"{polar_alpha0:.2f} deg; allowed: a symmetric section (within "
                f"{TAIL_ZERO_LIFT_ANGLE_DEG:g} deg of 0): the model takes the tails' sections "
                "as symmetric, without camber lift or moment"
            )
        if surface.coordinates is None:
            continue
        shape = read_coordinates(surface.coordinates)
        low, high = SECTION_THICKNESS_RANGE
        if not low <= shape.thickness_to_chord <= high:
            raise VehicleSpecError(
                f"'{name}.coordinates' = {surface.coordinates!r}: the section is "
                f"{shape.thickness_to_chord:.3g} thick (t/c); allowed: {low:g} to {high:g}"
            )
        if (
            named is not None
            and abs(shape.thickness_to_chord - named.thickness_to_chord) > NAMED_THICKNESS_TOLERANCE
        ):
            raise VehicleSpecError(
                f"'{name}.coordinates' = {surface.coordinates!r}: t/c "
                f"{shape.thickness_to_chord:.3g} is not that of '{name}.airfoil' = "
                f"{surface.airfoil!r} ({named.thickness_to_chord:g}); allowed: the named "
                "section's coordinates, or a polar file of the section the coordinates describe"
            )
        thin_alpha0 = math.degrees(shape.zero_lift_angle)
        if abs(thin_alpha0 - polar_alpha0) > ZERO_LIFT_ANGLE_TOLERANCE_DEG:
            raise VehicleSpecError(
                f"'{name}.coordinates' = {surface.coordinates!r} and '{name}.airfoil' = "
                f"{surface.airfoil!r} describe different sections: the coordinates' camber "
                f"gives a zero-lift angle of {thin_alpha0:.2f} deg (thin-airfoil theory), the "
                f"polar {polar_alpha0:.2f} deg at Re {reynolds:.3g}; allowed: within "
                f"{ZERO_LIFT_ANGLE_TOLERANCE_DEG:g} deg"
            )
