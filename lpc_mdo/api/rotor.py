"""Plain-function rotor analyses: one rotor, given blade stations, BEM or steady Pitt–Peters.

``lpc_mdo.api.bem`` and ``lpc_mdo.api.pitt_peters`` build a small Problem around the rotor
components (the same ones the vehicle model uses), run it and return plain numbers, for quick
studies and for comparing with other codes. Blade geometry is given at the stations (no splines);
the airfoil is a packaged name, a user polar or a :class:`~lpc_mdo.components.aero.polar.Polar`
(:func:`lpc_mdo.components.aero.airfoil.get_polar`).
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.components.geometry.blade import azimuth_angles, station_fractions
from lpc_mdo.components.rotor.bem_inflow import BEMInflowComp
from lpc_mdo.components.rotor.bem_loads import BEMLoadsComp, RotorPerformanceComp
from lpc_mdo.components.rotor.pitt_peters_inflow import PittPetersInflowComp
from lpc_mdo.components.rotor.pitt_peters_loads import PittPetersLoadsComp
from lpc_mdo.core.checks import check_integer, check_number, check_range, check_shape
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY
from lpc_mdo.core.mpi import serial_comm


def _positive(name, value):
    return np.asarray(check_range(name, value, lower=0.0, lower_open=True), dtype=float)


def blade_stations(radius, hub_radius, radial_stations):
    """
    Station radii and quadrature widths of one blade.

    Parameters
    ----------
    radius, hub_radius : float
        Tip and hub radius, m (0 < hub_radius < radius).
    radial_stations : int or array_like
        A number n of equal elements between hub and tip (centres at their midpoints), or the
        station radii (m, increasing, strictly between hub and tip; each station's width then
        reaches halfway to its neighbours and to hub and tip).

    Returns
    -------
    (ndarray, ndarray)
        Station radii and widths (m), which sum to radius - hub_radius.
    """
    radius = float(_positive("radius", radius))
    hub_radius = check_number(
        "hub_radius",
        hub_radius,
        lower=0.0,
        upper=radius,
        lower_open=True,
        upper_open=True,
        units="m",
    )
    if np.ndim(radial_stations) == 0:
        n = check_integer("radial_stations", radial_stations, lower=1)
        eta, q = station_fractions(n)
        return hub_radius + (radius - hub_radius) * eta, (radius - hub_radius) * q
    r = np.asarray(radial_stations, dtype=float).ravel()
    if (
        r.size < 1
        or not np.all(np.isfinite(r))
        or np.any(np.diff(r) <= 0.0)
        or r[0] <= hub_radius
        or r[-1] >= radius
    ):
        raise ValueError(
            f"radial_stations = {r.tolist()}; allowed: increasing radii strictly "
            f"between hub_radius ({hub_radius}) and radius ({radius}) m"
        )
    edges = np.concatenate([[hub_radius], 0.5 * (r[1:] + r[:-1]), [radius]])
    return r, np.diff(edges)


def _station_values(name, value, n):
    value = np.asarray(check_range(name, value), dtype=float)
    if value.ndim == 0:
        value = np.full(n, float(value))
    return check_shape(name, value, (n,))  # a scalar or one value per radial station


def _operating_points(**arrays):
    """Broadcast the operating-point arguments to (num_nodes,); scalar flag."""
    try:
        values = np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in arrays.values()])
    except ValueError as err:
        shapes = {k: np.shape(v) for k, v in arrays.items()}
        raise ValueError(f"operating-point arguments do not broadcast: {shapes}") from err
    scalar = values[0].ndim == 0
    out = {}
    for name, v in zip(arrays, values, strict=True):
        if v.ndim > 1:
            raise ValueError(
                f"'{name}' = {v.tolist()} is not allowed: must be a scalar or a 1-D array"
            )
        check_range(name, v)
        out[name] = np.atleast_1d(v)
    return out, scalar


def _set_common(
    prob, radius, hub_radius, r, width, chord, twist, rpm, density, viscosity, speed_of_sound, nn
):
    for name, value in (
        ("radius", radius),
        ("hub_radius", hub_radius),
        ("station_radius", r),
        ("station_width", width),
        ("chord", chord),
        ("twist", twist),
        ("rpm", rpm[None, :]),
        ("density", np.full(nn, density)),
        ("dynamic_viscosity", np.full(nn, viscosity)),
        ("speed_of_sound", np.full(nn, speed_of_sound)),
    ):
        prob.set_val(name, value)


def _squeeze(result, scalar):
    """Drop the operating-point axis (leading) when every operating argument was a scalar."""
    return {k: (v[0] if scalar else v) for k, v in result.items()}


def bem(
    radius,
    hub_radius,
    num_blades,
    radial_stations,
    chord,
    twist_deg,
    rpm,
    axial_velocity,
    airfoil,
    density=SEA_LEVEL_DENSITY,
    viscosity=1.81e-5,
    speed_of_sound=340.3,
    tip_loss=True,
    hub_loss=True,
):
    """
    Blade element momentum analysis of one rotor in axial flow (hover, climb, propeller).

    Paper eq. 12-13, docs theory/rotors 'Blade-element momentum' (Ning's guaranteed-convergence
    residual with Prandtl tip and hub loss and wake swirl): :class:`BEMInflowComp`,
    :class:`BEMLoadsComp` and :class:`RotorPerformanceComp`.

    Parameters
    ----------
    radius, hub_radius : float
        Tip and hub radius, m.
    num_blades : int
    radial_stations : int or array_like
        Number of equal elements, or the station radii in m (:func:`blade_stations`).
    chord : float or array_like (num_radial,)
        Chord at the stations, m.
    twist_deg : float or array_like (num_radial,)
        Blade pitch relative to the rotor plane at the stations, deg.
    rpm : float or array_like (num_nodes,)
        Rotor speed(s).
    axial_velocity : float or array_like (num_nodes,)
        Freestream speed through the disk along the thrust axis, m/s (> 0: climb or forward
        flight of a propeller; 0: hover).
    airfoil : str, dict, array or Polar
        A packaged airfoil name ('naca0012', 'naca0015', 'ls413', 'ls417'), a user polar
        {'alpha_deg', 'cl', 'cd'} or any form :func:`~lpc_mdo.components.aero.airfoil.get_polar`
        takes.
    density, viscosity, speed_of_sound : float
        Air density (kg/m**3), dynamic viscosity (Pa*s) and speed of sound (m/s).
    tip_loss, hub_loss : bool
        Prandtl's tip and hub losses.

    Returns
    -------
    dict
        'thrust' (N), 'torque' (N*m), 'power' (W), 'thrust_coefficient', 'power_coefficient'
        (T/(rho n^2 D^4), P/(rho n^3 D^5)), 'figure_of_merit', 'efficiency', 'advance_ratio',
        'tip_mach' (floats, or arrays (num_nodes,) when rpm or axial_velocity is an array), and
        per station 'inflow_angle' (rad), 'angle_of_attack' (rad), 'normal_load' and
        'tangential_load' (thrust and in-plane drag of one blade per unit span, N/m), shape
        (num_radial,) or (num_nodes, num_radial); 'station_radius', 'station_width' (m).

    Raises
    ------
    ValueError
        An argument out of range (the message names it and what is allowed).
    om.AnalysisError
        The inflow solve failed.
    """
    r, width = blade_stations(radius, hub_radius, radial_stations)
    n = r.size
    chord = _positive("chord", _station_values("chord", chord, n))
    twist = np.radians(_station_values("twist_deg", twist_deg, n))
    ops, scalar = _operating_points(rpm=rpm, axial_velocity=axial_velocity)
    _positive("rpm", ops["rpm"])
    for name, value in (
        ("density", density),
        ("viscosity", viscosity),
        ("speed_of_sound", speed_of_sound),
    ):
        _positive(name, value)
    nn = ops["rpm"].size
    polar = get_polar(airfoil)
    kw = dict(
        num_nodes=nn,
        num_radial=n,
        num_blades=int(num_blades),
        polar=polar,
        tip_loss=tip_loss,
        hub_loss=hub_loss,
    )
    prob = om.Problem(reports=False, comm=serial_comm())
    prob.model.add_subsystem("inflow", BEMInflowComp(**kw), promotes=["*"])
    prob.model.add_subsystem("loads", BEMLoadsComp(**kw), promotes=["*"])
    prob.model.add_subsystem("performance", RotorPerformanceComp(num_nodes=nn), promotes=["*"])
    prob.setup()
    _set_common(
        prob,
        radius,
        hub_radius,
        r,
        width,
        chord,
        twist,
        ops["rpm"],
        density,
        viscosity,
        speed_of_sound,
        nn,
    )
    prob.set_val("axial_velocity", ops["axial_velocity"][None, :])
    prob.run_model()
    out = {
        name: prob.get_val(name)[0]
        for name in (
            "thrust",
            "torque",
            "power",
            "thrust_coefficient",
            "power_coefficient",
            "figure_of_merit",
            "efficiency",
            "advance_ratio",
            "tip_mach",
            "inflow_angle",
            "angle_of_attack",
        )
    }
    out["normal_load"] = prob.get_val("thrust_per_span")[0]
    out["tangential_load"] = prob.get_val("drag_per_span")[0]
    result = _squeeze(out, scalar)
    result.update(station_radius=r, station_width=width)
    return result


def pitt_peters(
    radius,
    hub_radius,
    num_blades,
    radial_stations,
    chord,
    twist_deg,
    rpm,
    edgewise_velocity,
    disk_angle_deg,
    airfoil,
    num_azimuth=25,
    density=SEA_LEVEL_DENSITY,
    viscosity=1.81e-5,
    speed_of_sound=340.3,
    tip_loss=True,
    hub_loss=True,
    loss_placement="momentum",
    tangential_induction=True,
    spin_direction=1,
):
    """
    Steady Pitt–Peters analysis of one rotor in edgewise (or any non-axial) flight.

    Paper eq. 14-15, docs theory/rotors 'Pitt-Peters inflow':
    :class:`PittPetersInflowComp` and :class:`PittPetersLoadsComp`.

    The flight speed V = ``edgewise_velocity`` meets the disk at the disk angle of attack
    alpha_d (positive with the disk tilted back, so the air flows up through it, as for a
    helicopter rotor in forward flight): the hub's velocity relative to the air is
    V cos(alpha_d) along the disk e_x axis (towards the advancing side's motion, psi = 90 deg)
    and -V sin(alpha_d) along the thrust axis.

    Parameters
    ----------
    radius, hub_radius, num_blades, radial_stations, chord, twist_deg, airfoil
        As :func:`bem`.
    rpm, edgewise_velocity, disk_angle_deg : float or array_like (num_nodes,)
        Rotor speed, flight speed (m/s, >= 0) and disk angle of attack (deg); they broadcast.
    num_azimuth : int
        Azimuthal stations psi_k = 2 pi k/num_azimuth (>= 3), measured in the direction of
        rotation from the downstream blade.
    density, viscosity, speed_of_sound : float
    tip_loss, hub_loss : bool
    loss_placement : str
        'momentum' (default: Prandtl's F on the momentum side, as in the BEM) or
        'blade_element' (F on the loads, docs theory/rotors 'Pitt-Peters inflow').
    tangential_induction : bool
        Include the wake swirl per station (default, as the BEM).
    spin_direction : int
        +1 (right-handed about the thrust axis) or -1.

    Returns
    -------
    dict
        'thrust', 'torque', 'power' (N, N*m, W), 'inflow_states' (lambda_0, lambda_c,
        lambda_s), 'inplane_force' (H, Y along the disk e_x, e_y, N) and 'hub_moment' (about
        e_x, e_y, N*m): floats / arrays (3,), (2,) at one operating point, else with a leading
        (num_nodes,) axis; per station over (num_radial, num_azimuth): 'normal_load',
        'tangential_load' (N/m, one blade), 'inflow_angle' (rad); 'azimuth' (rad),
        'station_radius', 'station_width' (m).

    Raises
    ------
    ValueError
        An argument out of range (the message names it and what is allowed).
    om.AnalysisError
        The inflow solve failed (e.g. the vortex-ring state).
    """
    r, width = blade_stations(radius, hub_radius, radial_stations)
    n = r.size
    chord = _positive("chord", _station_values("chord", chord, n))
    twist = np.radians(_station_values("twist_deg", twist_deg, n))
    ops, scalar = _operating_points(
        rpm=rpm, edgewise_velocity=edgewise_velocity, disk_angle_deg=disk_angle_deg
    )
    _positive("rpm", ops["rpm"])
    if np.any(ops["edgewise_velocity"] < 0.0):
        raise ValueError(
            f"edgewise_velocity = {ops['edgewise_velocity'].tolist()}; allowed: "
            ">= 0 m/s (the disk angle of attack sets the direction)"
        )
    for name, value in (
        ("density", density),
        ("viscosity", viscosity),
        ("speed_of_sound", speed_of_sound),
    ):
        _positive(name, value)
    nn = ops["rpm"].size
    alpha = np.radians(ops["disk_angle_deg"])
    speed = ops["edgewise_velocity"]
    inplane = np.zeros((1, nn, 2))
    inplane[0, :, 0] = speed * np.cos(alpha)
    kw = dict(
        num_nodes=nn,
        num_radial=n,
        num_azimuth=int(num_azimuth),
        num_blades=int(num_blades),
        spin_direction=int(spin_direction),
        polar=get_polar(airfoil),
        tip_loss=tip_loss,
        hub_loss=hub_loss,
        loss_placement=loss_placement,
        tangential_induction=tangential_induction,
    )
    prob = om.Problem(reports=False, comm=serial_comm())
    prob.model.add_subsystem("inflow", PittPetersInflowComp(**kw), promotes=["*"])
    prob.model.add_subsystem("loads", PittPetersLoadsComp(**kw), promotes=["*"])
    prob.setup()
    _set_common(
        prob,
        radius,
        hub_radius,
        r,
        width,
        chord,
        twist,
        ops["rpm"],
        density,
        viscosity,
        speed_of_sound,
        nn,
    )
    prob.set_val("axial_velocity", (-speed * np.sin(alpha))[None, :])
    prob.set_val("inplane_velocity", inplane)
    prob.run_model()
    out = {
        name: prob.get_val(name)[0]
        for name in (
            "thrust",
            "torque",
            "inflow_states",
            "inplane_force",
            "hub_moment",
            "inflow_angle",
        )
    }
    out["power"] = out["torque"] * ops["rpm"] * RPM_TO_RAD_S
    out["normal_load"] = prob.get_val("thrust_per_span")[0]
    out["tangential_load"] = prob.get_val("drag_per_span")[0]
    result = _squeeze(out, scalar)
    result.update(azimuth=azimuth_angles(int(num_azimuth)), station_radius=r, station_width=width)
    return result
