"""Plain-function rotor noise: tonal, broadband and total levels of rotors at an observer.

:func:`rotor_noise` builds a small Problem around :class:`lpc_mdo.groups.acoustics.RotorNoiseGroup`
(the assembly the hover condition uses), runs it and returns plain numbers.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.constants import SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND
from lpc_mdo.groups.acoustics import RotorNoiseGroup
from lpc_mdo.mpi import serial_comm

__all__ = ["rotor_noise"]


def rotor_noise(
    radius,
    rpm,
    thrust,
    chord,
    *,
    num_blades=2,
    torque=None,
    thrust_per_span=None,
    drag_per_span=None,
    inflow_angle=None,
    thickness_to_chord=0.12,
    radial_stations=None,
    radial_weights=None,
    hub_radius_ratio=0.2,
    hub_position=None,
    thrust_direction=(0.0, 0.0, -1.0),
    observer_position=None,
    observer_distance=100.0,
    observer_elevation_deg=45.0,
    observer_azimuth_deg=180.0,
    flight_velocity=(0.0, 0.0, 0.0),
    density=SEA_LEVEL_DENSITY,
    speed_of_sound=SEA_LEVEL_SPEED_OF_SOUND,
    num_harmonics=3,
    num_bands=38,
    loading_path="auto",
    **group_options,
):
    """
    Noise of one or more rotors at an observer: tonal, broadband and total levels.

    Builds a small Problem around :class:`RotorNoiseGroup`, runs it and returns the levels.
    Defaults are the paper's hover case: observer 100 m from the rotor-hub centroid, 45 deg below
    the rotor plane (aft), thrust axes up, vehicle at rest.

    Parameters
    ----------
    radius, rpm, thrust : float or array (num_rotors,)
        Radius (m), speed (rpm) and thrust (N) of each rotor; num_rotors is their broadcast size.
    chord : float, array (num_radial,) or (num_rotors, num_radial)
        Chord (m) at the acoustic radial stations; a scalar means a constant chord with 25
        stations (or len(radial_stations)).
    num_blades : int or sequence of int
        Blades per rotor.
    torque : float or array (num_rotors,), optional
        Torque (N*m); required when sectional loads are not given (an assumed hover load shape
        is then used, see HoverLoadDistributionComp).
    thrust_per_span, drag_per_span, inflow_angle : array, optional
        Sectional loads of one blade (N/m) and inflow angle (rad), shapes (num_radial,),
        (num_radial, num_azimuth) or (num_rotors, num_radial, num_azimuth). Give all three or none.
    thickness_to_chord : float or array
        Section t/c (default 0.12).
    radial_stations, radial_weights, hub_radius_ratio :
        Acoustic radial stations r/R and weights (default: element centres on [0.2, 1]).
    hub_position : array (num_rotors, 3), optional
        Hub positions in the body frame, m (default all at the origin).
    thrust_direction : array (3,) or (num_rotors, 3)
        Thrust axes in the body frame (default up, (0, 0, -1)).
    observer_position : array (3,), optional
        Observer in the body frame, m. If None, the observer is placed at observer_distance (m),
        observer_elevation_deg below the rotor plane and observer_azimuth_deg (from +x towards
        +y) about the hub centroid.
    flight_velocity : array (3,)
        Vehicle velocity in the body frame, m/s.
    density, speed_of_sound : float
        Atmosphere (kg/m**3, m/s).
    num_harmonics, num_bands : int
        Blade-passing harmonics and one-third-octave bands.
    loading_path : str
        'auto', 'sears' or 'unsteady' (see LowsonLoadingNoiseComp).
    **group_options
        Further RotorNoiseGroup options (e.g. gust_factor, rotation_direction).

    Returns
    -------
    dict
        Floats: 'total_spl_a' (dBA), 'total_spl' (dB). Arrays (num_rotors,): 'rotor_spl_a',
        'rotor_spl', 'tonal_spl_a', 'tonal_spl', 'broadband_oaspl_a', 'broadband_oaspl',
        'distance' (m), 'elevation_deg' (observer above each rotor plane). Arrays
        (num_rotors, num_harmonics): 'loading_spl', 'thickness_spl', 'loading_spl_a',
        'thickness_spl_a', 'harmonic_frequency' (Hz). Arrays (num_rotors, num_bands):
        'broadband_spl', 'broadband_spl_a'; (num_bands,): 'band_frequency' (Hz). Levels are dB
        re 20 uPa.
    """
    per_rotor = np.broadcast_arrays(
        *(np.atleast_1d(np.asarray(v, dtype=float)) for v in (radius, rpm, thrust))
    )
    if per_rotor[0].ndim != 1:
        raise ValueError(
            "rotor_noise: radius, rpm and thrust must be scalars or 1-D arrays of "
            f"one value per rotor, got shape {per_rotor[0].shape}."
        )
    radius, rpm, thrust = (v.copy() for v in per_rotor)
    nr = radius.size

    sectional = [x is not None for x in (thrust_per_span, drag_per_span, inflow_angle)]
    if any(sectional) and not all(sectional):
        raise ValueError(
            "rotor_noise: give all of thrust_per_span, drag_per_span and "
            "inflow_angle, or none of them."
        )
    if all(sectional):
        loads = [np.asarray(x, dtype=float) for x in (thrust_per_span, drag_per_span, inflow_angle)]
        shape = loads[0].shape
        if len(shape) == 1:
            shape = (nr, shape[0], 1)
        elif len(shape) == 2:
            shape = (nr,) + shape
        try:
            loads = [
                np.broadcast_to(x.reshape(x.shape + (1,) if x.ndim == 1 else x.shape), shape)
                for x in loads
            ]
        except ValueError:
            shapes = [np.shape(x) for x in (thrust_per_span, drag_per_span, inflow_angle)]
            raise ValueError(
                f"rotor_noise: thrust_per_span, drag_per_span and inflow_angle must "
                f"share one shape (num_radial,), (num_radial, num_azimuth) or "
                f"(num_rotors = {nr}, num_radial, num_azimuth); got {shapes}."
            ) from None
        nrad, naz = shape[1], shape[2]
        load_input = "sectional"
    else:
        if torque is None:
            raise ValueError(
                "rotor_noise: torque is required when the sectional loads "
                "(thrust_per_span, drag_per_span, inflow_angle) are not given."
            )
        load_input = "totals"
        naz = 1
        chord_arr = np.asarray(chord, dtype=float)
        if chord_arr.ndim:
            nrad = chord_arr.shape[-1]
        elif radial_stations is not None:
            nrad = len(radial_stations)
        else:
            nrad = 25

    chord = np.asarray(chord, dtype=float)
    try:
        chord = np.broadcast_to(chord, (nr, nrad)).copy()
        tc = np.broadcast_to(np.asarray(thickness_to_chord, dtype=float), (nr, nrad)).copy()
    except ValueError:
        raise ValueError(
            f"rotor_noise: chord and thickness_to_chord must broadcast to "
            f"(num_rotors, num_radial) = {(nr, nrad)}, got {np.shape(chord)} and "
            f"{np.shape(thickness_to_chord)}."
        ) from None
    hub = np.zeros((nr, 3)) if hub_position is None else np.asarray(hub_position, dtype=float)
    direction = np.asarray(thrust_direction, dtype=float)
    try:
        hub = np.broadcast_to(hub, (nr, 3))
        direction = np.broadcast_to(direction, (nr, 3))
    except ValueError:
        raise ValueError(
            f"rotor_noise: hub_position and thrust_direction must broadcast to "
            f"(num_rotors, 3) = {(nr, 3)}."
        ) from None

    group = RotorNoiseGroup(
        num_rotors=nr,
        num_blades=num_blades,
        num_radial=nrad,
        num_azimuth=naz,
        num_harmonics=num_harmonics,
        num_bands=num_bands,
        loading_path=loading_path,
        load_input=load_input,
        observer_input="relative" if observer_position is None else "position",
        radial_stations=radial_stations,
        radial_weights=radial_weights,
        hub_radius_ratio=float(hub_radius_ratio),
        **group_options,
    )
    prob = om.Problem(group, reports=False, comm=serial_comm())
    prob.setup()
    prob.set_val("radius", radius, units="m")
    prob.set_val("rpm", rpm, units="rpm")
    prob.set_val("thrust", thrust, units="N")
    prob.set_val("chord", chord, units="m")
    prob.set_val("thickness_to_chord", tc)
    prob.set_val("hub_position", hub, units="m")
    prob.set_val("thrust_direction", direction)
    prob.set_val("flight_velocity", np.asarray(flight_velocity, dtype=float), units="m/s")
    prob.set_val("density", density, units="kg/m**3")
    prob.set_val("speed_of_sound", speed_of_sound, units="m/s")
    if observer_position is None:
        prob.set_val("observer_distance", observer_distance, units="m")
        prob.set_val("observer_elevation", observer_elevation_deg, units="deg")
        prob.set_val("observer_azimuth", observer_azimuth_deg, units="deg")
    else:
        prob.set_val("observer_position", np.asarray(observer_position, dtype=float), units="m")
    if load_input == "sectional":
        prob.set_val("thrust_per_span", loads[0], units="N/m")
        prob.set_val("drag_per_span", loads[1], units="N/m")
        prob.set_val("inflow_angle", loads[2], units="rad")
    else:
        prob.set_val("torque", np.broadcast_to(np.asarray(torque, dtype=float), (nr,)), units="N*m")
    prob.run_model()

    result = {name: float(prob.get_val(name)[0]) for name in ("total_spl_a", "total_spl")}
    for name in (
        "rotor_spl_a",
        "rotor_spl",
        "tonal_spl_a",
        "tonal_spl",
        "broadband_oaspl_a",
        "broadband_oaspl",
        "loading_spl",
        "thickness_spl",
        "loading_spl_a",
        "thickness_spl_a",
        "harmonic_frequency",
        "broadband_spl",
        "broadband_spl_a",
        "distance",
    ):
        result[name] = prob.get_val(name).copy()
    result["elevation_deg"] = np.degrees(
        np.arcsin(np.clip(prob.get_val("axial_distance") / prob.get_val("distance"), -1.0, 1.0))
    )
    result["band_frequency"] = group.band_frequencies.copy()
    return result
