"""The parasite-drag parts of a lift-plus-cruise vehicle, from its vehicle data.

:func:`lpc_drag_components` turns a :class:`~lpc_mdo.vehicle.Vehicle` into the parts and input
values of :class:`~lpc_mdo.components.aero.drag_buildup.DragBuildupComp` (docs
theory/aerodynamics 'Drag build-up'); the conditions that fly on the wing add that component with
these parts.
"""

import math

import numpy as np

from lpc_mdo.components.aero.drag_buildup import (
    LPC_BLADE_THICKNESS,
    LPC_BOOM_DIAMETER,
    LPC_BOOM_INTERFERENCE,
    LPC_HUB_CD,
    LPC_HUB_DIAMETER,
    LPC_HUB_HEIGHT,
    LPC_PYLON_CD,
    LPC_PYLON_THICKNESS,
    LPC_STRUT_CD,
    LPC_STRUT_DIAMETER,
    LPC_STRUT_LENGTH,
    LPC_WHEEL_CD,
    BluffDrag,
    BodyDrag,
    FixedFormFactorDrag,
    LiftingSurfaceDrag,
    SizedBluffDrag,
    max_thickness_sweep,
)
from lpc_mdo.components.aero.tyre_size import tyre_frontal_areas
from lpc_mdo.vehicle import reference_vehicle

__all__ = ["SIZED_DRAG_INPUTS", "lpc_drag_components"]

#: Drag-part inputs a condition takes from the vehicle (``drag_<name>``, outputs of
#: :class:`~lpc_mdo.components.aero.tyre_size.TyreFrontalAreaComp` in the vehicle group).
SIZED_DRAG_INPUTS = ("main_wheels_frontal_area", "nose_wheel_frontal_area")


def lpc_drag_components(vehicle=None, boom_diameter=LPC_BOOM_DIAMETER, gear=True, booms=True):
    """
    Return the drag-build-up components and input values of the LPC vehicle.

    See docs theory/aerodynamics 'Drag build-up'. Parts:

    - wing, horizontal_tail, vertical_tail: LiftingSurfaceDrag (vehicle t/c, (x/c)_m, laminar
      fraction, maximum-thickness sweep);
    - fuselage: BodyDrag;
    - booms: 4 bodies (BodyDrag, count 4), each the two 8 ft "Rotor_i_Support" segments of a
      boom line (length 2 L_c = 4.877 m), diameter ``boom_diameter``, Q = 1.5 (Raymer 12.5.5);
    - lift_rotor_blades: the stopped blades aligned with the flow (parked fore and aft along the
      booms): flow along the span, friction on 2 (1 + 0.2 t/c) c_mean (1 - r_hub/R) R per blade,
      FF 1 (Hoerner, Fluid-Dynamic Drag, ch. 2: flat-plate friction; a section yawed 90 deg has
      no pressure drag), Q 1, running length (1 - r_hub/R) R;
    - lift_rotor_hubs, lift_rotor_pylons, landing gear wheels and struts: BluffDrag (constants
      above);
    - pusher_spinner: friction on a cone of base radius r_hub and length 2 r_hub (assumed), FF 1;
    - allowance: leakage and protuberance, 5 % (``allowance_fraction`` of DragBuildupComp).

    ``gear``/``booms`` False leave those parts out (like-for-like comparisons with NASA's CFD
    model, which had no booms or gear).

    Returns
    -------
    components : tuple
        For the ``components`` option of :class:`DragBuildupComp`.
    values : dict
        Input name -> value (SI) for the geometry and reference area.
    """
    v = vehicle or reference_vehicle()
    comps, values = [], {}
    for name, surf, mirrored in (
        ("wing", v.wing, True),
        ("horizontal_tail", v.horizontal_tail, True),
        ("vertical_tail", v.vertical_tail, False),
    ):
        comps.append(
            LiftingSurfaceDrag(
                name,
                surf.thickness_to_chord,
                surf.max_thickness_location,
                sweep=max_thickness_sweep(surf, mirrored),
                laminar_fraction=surf.laminar_fraction,
            )
        )
        values[f"{name}_area"] = surf.area
        values[f"{name}_mean_aerodynamic_chord"] = surf.mean_aerodynamic_chord
    comps.append(BodyDrag("fuselage"))
    values["fuselage_length"] = v.fuselage.length
    values["fuselage_max_height"] = v.fuselage.max_height
    values["fuselage_max_width"] = v.fuselage.max_width
    if booms:
        n_lines = len(v.booms.attach_points) // 2
        comps.append(BodyDrag("booms", interference_factor=LPC_BOOM_INTERFERENCE, count=n_lines))
        values["booms_length"] = 2.0 * v.booms.length
        values["booms_max_height"] = boom_diameter
        values["booms_max_width"] = boom_diameter

    rotors = v.lift_rotors
    blade_span = np.array([(1.0 - r.hub_radius_ratio) * r.radius for r in rotors])
    # Mean chord of the cubic Bezier chord distribution = mean of its control points.
    chord = np.array([np.mean(r.chord_cp) for r in rotors])
    n_blades = np.array([r.num_blades for r in rotors])
    n_total = int(np.sum(n_blades))
    comps.append(
        FixedFormFactorDrag(
            "lift_rotor_blades", 1.0, count=n_total, interference_factor=1.0, laminar_fraction=0.1
        )
    )
    values["lift_rotor_blades_length"] = float(np.sum(n_blades * blade_span) / n_total)
    values["lift_rotor_blades_wetted_area"] = float(
        2.0 * (1.0 + 0.2 * LPC_BLADE_THICKNESS) * np.sum(n_blades * chord * blade_span) / n_total
    )
    comps.append(
        BluffDrag("lift_rotor_hubs", LPC_HUB_CD, LPC_HUB_DIAMETER * LPC_HUB_HEIGHT, len(rotors))
    )
    hub_z = np.array([r.hub_position[2] for r in rotors])
    boom_z = np.array([p[2] for p in v.booms.attach_points])
    pylon_height = float(np.mean(np.abs(hub_z - boom_z)))
    comps.append(
        BluffDrag(
            "lift_rotor_pylons", LPC_PYLON_CD, LPC_PYLON_THICKNESS * pylon_height, len(rotors)
        )
    )
    r_sp = v.pusher.hub_radius_ratio * v.pusher.radius
    comps.append(
        FixedFormFactorDrag("pusher_spinner", 1.0, interference_factor=1.0, laminar_fraction=0.1)
    )
    values["pusher_spinner_length"] = 2.0 * r_sp
    values["pusher_spinner_wetted_area"] = math.pi * r_sp * math.sqrt(r_sp**2 + (2.0 * r_sp) ** 2)
    if gear:  # tyres sized from W_dg: inputs (TyreFrontalAreaComp in the model)
        main, nose = tyre_frontal_areas(v.masses.design_gross_mass)
        comps.append(SizedBluffDrag("main_wheels", LPC_WHEEL_CD, 2))
        comps.append(SizedBluffDrag("nose_wheel", LPC_WHEEL_CD, 1))
        values["main_wheels_frontal_area"] = main
        values["nose_wheel_frontal_area"] = nose
        comps.append(
            BluffDrag("gear_struts", LPC_STRUT_CD, LPC_STRUT_LENGTH * LPC_STRUT_DIAMETER, 3)
        )
    values["reference_area"] = v.wing.area
    return tuple(comps), values
