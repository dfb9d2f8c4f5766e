"""Plain-function rotor noise: tonal, broadband and total levels of rotors at an observer.

:func:`rotor_noise` builds a small Problem around :class:`lpc_mdo.groups.acoustics.RotorNoiseGroup`
(the assembly the hover condition uses), runs it and returns plain numbers.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_choice, check_range, check_shape
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND
from lpc_mdo.core.mpi import serial_comm
from lpc_mdo.groups.acoustics import RotorNoiseGroup

__all__ = ["PARTS", "rotor_noise"]

#: The noise sources of :func:`rotor_noise`: Lowson loading (tonal, needs the in-plane load, i.e.
#: the torque or the sectional drag), Barry–Magliozzi thickness (tonal, blade geometry and speed
#: only) and Gill–Lee broadband (thrust, speed, radius, chord).
PARTS = ("loading", "thickness", "broadband")

_OBSERVER_KEYS = ("observer_distance", "observer_elevation_deg", "observer_azimuth_deg")


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
    parts=PARTS,
    **group_options,
):
    """
    Noise of one or more rotors at one or several observers: tonal, broadband and total levels.

    Builds a small Problem around :class:`RotorNoiseGroup`, runs it once (all observers in one
    vectorized pass, option ``num_observers``) and returns the levels. Defaults are the paper's
    hover case: observer 100 m from the rotor-hub centroid, 45 deg below the rotor plane (aft),
    thrust axes up, vehicle at rest.

    Without a torque (and without sectional loads) only the parts that do not need the in-plane
    load can be computed: pass ``parts=('thickness', 'broadband')`` (or one of them). Thickness
    noise (Barry–Magliozzi) needs the blade geometry, t/c and speed; broadband noise (Gill–Lee)
    the thrust, speed, radius and chord. Loading noise needs the torque (the in-plane drag of
    the assumed hover load shape) or the sectional loads; the tonal, rotor and total levels sum
    loading and thickness, so they are returned only when ``parts`` holds all three sources.

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
        Torque (N*m); required when sectional loads are not given and ``parts`` includes
        'loading' (an assumed hover load shape is then used, see HoverLoadDistributionComp).
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
    observer_position : array (3,) or (num_observers, 3), optional
        Observer(s) in the body frame, m. If None, the observer is placed at observer_distance
        (m), observer_elevation_deg below the rotor plane and observer_azimuth_deg (from +x
        towards +y) about the hub centroid.
    observer_distance, observer_elevation_deg, observer_azimuth_deg : float or array (n,)
        Observer(s) about the hub centroid (used when observer_position is None); arrays
        broadcast against each other, one observer per entry. The distance must be at least
        the largest rotor radius (the models are far-field).
    flight_velocity : array (3,)
        Vehicle velocity in the body frame, m/s.
    density, speed_of_sound : float
        Atmosphere (kg/m**3, m/s).
    num_harmonics, num_bands : int
        Blade-passing harmonics and one-third-octave bands.
    loading_path : str
        'auto', 'sears' or 'unsteady' (see LowsonLoadingNoiseComp).
    parts : sequence of str
        The noise sources to compute, a non-empty subset of :data:`PARTS` ('loading',
        'thickness', 'broadband'; default all). Without 'loading' no torque is needed.
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

        Keys of a source not in ``parts`` are absent ('loading_spl*' without 'loading',
        'thickness_spl*' without 'thickness', 'broadband_*' without 'broadband'), and so are the
        sums 'tonal_spl*', 'rotor_spl*', 'total_spl*' unless ``parts`` holds all three.

        With several observers (an observer argument given as an array, or observer_position
        of shape (num_observers, 3)) every level, 'distance', 'elevation_deg' and
        'harmonic_frequency' (Doppler-shifted in flight) get a leading axis num_observers (the
        floats become arrays (num_observers,)); entry k equals the single-observer result at
        observer k. 'band_frequency' does not depend on the observer and keeps its shape.
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
    parts = _check_parts(parts)

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
        if torque is None and "loading" in parts:
            raise ValueError(
                "rotor_noise: torque is required when the sectional loads "
                "(thrust_per_span, drag_per_span, inflow_angle) are not given and 'parts' "
                "includes 'loading'; give torque, or parts=('thickness', 'broadband') for the "
                "levels that do not need it."
            )
        if torque is None:
            torque = 0.0  # feeds only the loading noise, which is not returned
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

    observers, num_observers = _observers(
        observer_position, observer_distance, observer_elevation_deg, observer_azimuth_deg
    )
    _check_far_field(observers, observer_position is None, radius, hub)

    n_obs = len(observers)
    group = RotorNoiseGroup(
        num_rotors=nr,
        num_observers=n_obs,
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
    if load_input == "sectional":
        prob.set_val("thrust_per_span", loads[0], units="N/m")
        prob.set_val("drag_per_span", loads[1], units="N/m")
        prob.set_val("inflow_angle", loads[2], units="rad")
    else:
        prob.set_val("torque", np.broadcast_to(np.asarray(torque, dtype=float), (nr,)), units="N*m")
    for name, _, units in observers[0]:
        values = np.array([observer[name] for observer in _by_name(observers)])  # (n,) or (n, 3)
        prob.set_val(name, values[0] if n_obs == 1 else values, units=units)
    prob.run_model()
    result = _levels(prob, parts, n_obs)
    if num_observers is None:
        result = {key: value[0] if key in _PER_OBSERVER else value for key, value in result.items()}
    result["band_frequency"] = group.band_frequencies.copy()
    return result


_TOTALS = ("total_spl_a", "total_spl")
_SUMS = ("rotor_spl_a", "rotor_spl", "tonal_spl_a", "tonal_spl")
_BY_PART = {
    "loading": ("loading_spl", "loading_spl_a"),
    "thickness": ("thickness_spl", "thickness_spl_a"),
    "broadband": ("broadband_oaspl_a", "broadband_oaspl", "broadband_spl", "broadband_spl_a"),
}
_PER_OBSERVER = set(_TOTALS + _SUMS + ("distance", "elevation_deg", "harmonic_frequency")).union(
    *_BY_PART.values()
)


def _check_parts(parts):
    """Return ``parts`` as a tuple of distinct names of :data:`PARTS` (non-empty)."""
    if isinstance(parts, str):
        parts = (parts,)
    try:
        parts = tuple(parts)
    except TypeError:
        parts = (parts,)
    if not parts:
        raise ValueError(
            f"rotor_noise: 'parts' = () is not allowed: must be a non-empty subset of {PARTS}"
        )
    for part in parts:
        check_choice("parts", part, PARTS, where="rotor_noise")
    return tuple(p for p in PARTS if p in parts)


def _observers(position, distance, elevation_deg, azimuth_deg):
    """
    Return the observers as lists of (input, value, units), and their number (None = one).

    A single observer (scalars, or a position of shape (3,)) gives num_observers None, so that
    the result keeps the single-observer shapes.
    """
    where = "rotor_noise"
    if position is not None:
        pos = np.asarray(position, dtype=float)
        if pos.ndim == 1:
            check_shape("observer_position", pos, (3,), where=where)
        else:
            check_shape("observer_position", pos, (None, 3), where=where)
        check_range("observer_position", pos, units="m", where=where)
        rows = np.atleast_2d(pos)
        observers = [[("observer_position", row, "m")] for row in rows]
        return observers, (None if pos.ndim == 1 else rows.shape[0])
    values = [np.asarray(v, dtype=float) for v in (distance, elevation_deg, azimuth_deg)]
    for name, value in zip(_OBSERVER_KEYS, values, strict=True):
        if value.ndim > 1:
            raise ValueError(
                f"{where}: '{name}' must be a number or a 1-D array (one entry per observer), "
                f"got shape {value.shape}"
            )
        check_range(name, value, units="m" if name == "observer_distance" else "deg", where=where)
    try:
        broadcast = np.broadcast_arrays(*(np.atleast_1d(v) for v in values))
    except ValueError:
        shapes = ", ".join(f"{n} {v.shape}" for n, v in zip(_OBSERVER_KEYS, values, strict=True))
        raise ValueError(
            f"{where}: the observer arrays must broadcast to one length (one entry per "
            f"observer), got {shapes}"
        ) from None
    observers = [
        [
            ("observer_distance", d, "m"),
            ("observer_elevation", e, "deg"),
            ("observer_azimuth", a, "deg"),
        ]
        for d, e, a in zip(*broadcast, strict=True)
    ]
    single = all(v.ndim == 0 for v in values)
    return observers, (None if single else len(observers))


def _check_far_field(observers, relative, radius, hub):
    """Each observer at least the largest rotor radius from the hub centroid or from each hub."""
    where = "rotor_noise"
    for k, observer in enumerate(observers):
        value = observer[0][1]
        if relative:
            check_range(
                "observer_distance" if len(observers) == 1 else f"observer_distance[{k}]",
                float(value),
                lower=float(np.max(radius)),
                units="m",
                allowed=f">= the largest rotor radius {np.max(radius):.6g} (far field)",
                where=where,
            )
        else:
            gap = np.linalg.norm(np.asarray(value)[None, :] - hub, axis=1)
            check_range(
                "observer distance from hub"
                if len(observers) == 1
                else f"observer[{k}] distance from hub",
                gap,
                lower=radius,
                units="m",
                allowed="at least that rotor's radius (far field)",
                where=where,
            )


def _by_name(observers):
    """Return the observers as dicts input name -> value."""
    return [{name: value for name, value, _ in observer} for observer in observers]


def _levels(prob, parts, num_observers):
    """
    Return the levels of the noise Problem for the computed ``parts``, per observer.

    Every level gets a leading axis num_observers: the group's rows are rotor-observer pairs,
    observer-major (row j nr + k is rotor k heard by observer j).
    """

    def split(value):
        return value.reshape((num_observers, -1) + value.shape[1:])

    result = {}
    names = []
    if len(parts) == len(PARTS):
        result.update({name: prob.get_val(name).copy() for name in _TOTALS})
        names.extend(_SUMS)
    for part in parts:
        names.extend(_BY_PART[part])
    if "loading" in parts or "thickness" in parts:
        names.append("harmonic_frequency")
    names.append("distance")
    for name in names:
        result[name] = split(prob.get_val(name).copy())
    result["elevation_deg"] = split(
        np.degrees(
            np.arcsin(np.clip(prob.get_val("axial_distance") / prob.get_val("distance"), -1.0, 1.0))
        )
    )
    return result
