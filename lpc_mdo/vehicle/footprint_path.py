"""The departure's path over the ground and its geometry to a noise footprint's observers.

A vehicle file's ``[noise_footprint]`` (:class:`~lpc_mdo.vehicle.parts.NoiseFootprint`) names
ground observers; the departure they hear is the first hover without a failed rotor, held over
the vertiport, then every transition point in file order (docs theory/acoustics 'Noise
footprint'). This module turns the vehicle file into that path and, for each part of it and
each observer, the geometry the noise model needs: plain numbers, fixed by the file, computed
once when the model is built.

Frames: earth axes with x along the track (the flight direction), y to the right and z down,
origin on the ground under the vertiport hover. Each leg is a straight segment flown at
constant speed; the hover is a leg of zero length.

A leg of length l flown at V = l/T is heard at each observer by quadrature in the angle
beta between the observer's perpendicular to the leg's line and the line of sight: with h the
observer's distance from that line and s* its projection on it, the source at
s = s* + h tan(beta) is r = h/cos(beta) away and dt = h/(V cos^2 beta) dbeta, so the leg's
A-weighted sound energy is

    E = integral 10^(L(t)/10) dt = integral 10^(L(beta)/10) h/(V cos^2 beta) dbeta,

L(beta) the noise model's level from that point (directivity, Doppler, spreading and
absorption of that line of sight). Gauss-Legendre nodes in beta over the leg give the points
and their **equivalent times** tau_k = w_k h/(V cos^2 beta_k), E = sum_k 10^(L_k/10) tau_k:
exact for a source of uniform directivity with spherical spreading (the integrand is then
constant in beta), and the nodes follow the line of sight evenly however long the leg. Each
observer hears each leg at one node per :data:`QUADRATURE_ANGLE` of the angle the leg subtends
(at least one, at most the footprint's ``quadrature_points``): a far leg, seen over a narrow
angle, at one point. The hover is one point held for its time.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from lpc_mdo.vehicle.schema import VehicleSpecError

#: Least distance from the path to a footprint observer in rotor radii (the far-field forms of
#: the noise model; lpc_mdo.vehicle.consistency.FAR_FIELD_RADII for the hover observers).
FOOTPRINT_FAR_FIELD_RADII = 10.0
#: Line-of-sight angle per Gauss point of a leg (rad): a leg seen over up to 30 deg is heard at
#: one point, one seen over nearly 180 deg (passing overhead) at six (docs theory/acoustics
#: 'Noise footprint' measures the choice against one point per 10 deg).
QUADRATURE_ANGLE = np.radians(30.0)


@dataclass(frozen=True)
class PathLeg:
    """One straight part of the departure, flown in one design condition.

    Attributes
    ----------
    condition : str
        The design condition flown (its rotors' state makes the noise).
    start, end : tuple of 3 float
        Ends of the leg in earth axes (m; x along the track, y right, z down).
    time : float
        Time to fly it (s); the hover's time over the vertiport.
    """

    condition: str
    start: tuple[float, float, float]
    end: tuple[float, float, float]
    time: float

    @property
    def length(self) -> float:
        """Length of the leg (m), 0 for the hover."""
        return float(np.linalg.norm(np.subtract(self.end, self.start)))


def departure_conditions(vehicle) -> tuple:
    """
    Return the design conditions of the departure.

    The first hover without a failed rotor, then every transition point, in file order.
    Raises VehicleSpecError without such a hover.
    """
    hovers = [c for c in vehicle.conditions if c.kind == "hover" and c.failed_rotor < 0]
    if not hovers:
        raise VehicleSpecError(
            "'noise_footprint' needs a 'hover' condition without a failed rotor: the departure "
            "it hears starts with the hover over the vertiport"
        )
    return (hovers[0], *(c for c in vehicle.conditions if c.kind == "transition"))


def departure_legs(vehicle) -> tuple[PathLeg, ...]:
    """
    Return the legs of the departure, in flight order.

    The hover is held at its condition's altitude over the origin for the footprint's
    ``hover_time``. Each transition point flies its own leg of length V T (its speed and
    duration: a point stands for its part of the transition) along +x from where the last one
    ended, climbing at its flight-path angle, centred on its condition's altitude, and split
    into the footprint's ``leg_subdivisions`` equal parts.
    """
    footprint = vehicle.noise_footprint
    hover, *transition = departure_conditions(vehicle)
    legs = [PathLeg(hover.name, (0.0, 0.0, -hover.altitude), (0.0, 0.0, -hover.altitude),
                    footprint.hover_time)]  # fmt: skip
    x = 0.0
    parts = footprint.subdivisions
    for c in transition:
        length = c.speed * c.duration
        dx, dz = length * np.cos(c.flight_path_angle), -length * np.sin(c.flight_path_angle)
        start = np.array([x, 0.0, -c.altitude - 0.5 * dz])
        step = np.array([dx, 0.0, dz]) / parts
        for k in range(parts):
            a, b = start + k * step, start + (k + 1) * step
            legs.append(PathLeg(c.name, tuple(a), tuple(b), c.duration / parts))
        x += dx
    return tuple(legs)


def footprint_observers(footprint) -> np.ndarray:
    """
    Return the observer positions (num_observers, 3) in earth axes (m).

    For each lateral offset, every track position (offset-major), at the microphone height.
    """
    track = np.asarray(footprint.track_positions, dtype=float)
    return np.array([(x, y, -footprint.height) for y in footprint.offsets for x in track])


@dataclass(frozen=True)
class LegGeometry:
    """Where and for how long the observers hear one leg: its quadrature points, flat.

    Attributes
    ----------
    observer : ndarray of int, (num_points,)
        The observer hearing each point (each observer hears at least one, in order).
    offset : ndarray, (num_points, 3)
        That observer minus the point, earth axes (m).
    equivalent_time : ndarray, (num_points,)
        tau_k (s): the leg's energy at an observer is the sum over its points of
        10^(L_k/10) tau_k, L_k the level from point k (module docstring).
    """

    observer: np.ndarray
    offset: np.ndarray
    equivalent_time: np.ndarray


def leg_nodes(span, max_nodes, angle=None):
    """Gauss points for a leg seen over ``span`` rad: one per ``angle``, 1 to ``max_nodes``."""
    angle = QUADRATURE_ANGLE if angle is None else angle
    return np.clip(np.ceil(np.asarray(span) / angle - 1e-9), 1, max_nodes).astype(int)


def leg_geometry(leg: PathLeg, observers: np.ndarray, max_nodes: int, angle=None) -> LegGeometry:
    """
    Return the quadrature points and equivalent times of one leg for every observer.

    See the module docstring. Each observer hears the leg at :func:`leg_nodes` Gauss points in
    the angle of its line of sight over the angle the leg subtends; the hover (a leg of zero
    length) at one point held for its time.
    """
    start = np.asarray(leg.start, dtype=float)
    rel = np.asarray(observers, dtype=float) - start
    index = np.arange(len(rel))
    length = leg.length
    if length == 0.0:
        return LegGeometry(index, rel, np.full(len(rel), leg.time))
    along = (np.asarray(leg.end) - start) / length
    s_star = rel @ along
    h = np.sqrt(np.maximum(np.sum(rel * rel, axis=1) - s_star**2, 0.0))
    first, last = np.arctan(-s_star / h), np.arctan((length - s_star) / h)
    counts = leg_nodes(last - first, max_nodes, angle)
    speed = length / leg.time
    observer, offset, times = [], [], []
    for i, n in zip(index, counts, strict=True):
        nodes, weights = np.polynomial.legendre.leggauss(n)
        half = 0.5 * (last[i] - first[i])
        beta = 0.5 * (last[i] + first[i]) + half * nodes
        position = s_star[i] + h[i] * np.tan(beta)
        observer.append(np.full(n, i))
        offset.append(rel[i] - position[:, None] * along)
        times.append(half * weights * h[i] / (speed * np.cos(beta) ** 2))
    return LegGeometry(np.concatenate(observer), np.concatenate(offset), np.concatenate(times))


def footprint_geometry(vehicle) -> tuple[tuple[PathLeg, ...], list[LegGeometry]]:
    """
    Return the departure's legs and their geometry to the footprint's observers.

    Raises VehicleSpecError naming ``noise_footprint`` if an observer comes closer to the path
    than :data:`FOOTPRINT_FAR_FIELD_RADII` times the largest rotor radius (the noise model's
    far-field forms).
    """
    footprint = vehicle.noise_footprint
    if footprint.max_sel is None and footprint.max_lamax is None:
        raise VehicleSpecError(
            "'noise_footprint' has no limit: give 'max_sel' (dBA), 'max_lamax' (dBA) or both"
        )
    legs = departure_legs(vehicle)
    observers = footprint_observers(footprint)
    radius = max(r.radius for r in (*vehicle.lift_rotors, vehicle.pusher))
    closest = min(float(np.min(_distance_to(leg, observers))) for leg in legs)
    if closest < FOOTPRINT_FAR_FIELD_RADII * radius:
        raise VehicleSpecError(
            f"'noise_footprint' has an observer {closest:.1f} m from the departure path: must be "
            f"at least {FOOTPRINT_FAR_FIELD_RADII:g} rotor radii "
            f"({FOOTPRINT_FAR_FIELD_RADII * radius:.1f} m) away, where the noise model's "
            "far-field forms hold; fly the departure higher or move the observers"
        )
    return legs, [leg_geometry(leg, observers, footprint.nodes) for leg in legs]


def _distance_to(leg, observers):
    """Return each observer's distance to the closest point of ``leg`` (m)."""
    start = np.asarray(leg.start, dtype=float)
    rel = np.asarray(observers, dtype=float) - start
    if leg.length == 0.0:
        return np.linalg.norm(rel, axis=1)
    along = (np.asarray(leg.end) - start) / leg.length
    closest = np.clip(rel @ along, 0.0, leg.length)
    return np.linalg.norm(rel - closest[:, None] * along, axis=1)


def departure_points(legs, geometry) -> dict[str, LegGeometry]:
    """Return each departure condition's quadrature points, its legs' joined, in flight order."""
    parts: dict[str, list[LegGeometry]] = {}
    for leg, g in zip(legs, geometry, strict=True):
        parts.setdefault(leg.condition, []).append(g)
    return {
        name: LegGeometry(
            np.concatenate([g.observer for g in mine]),
            np.concatenate([g.offset for g in mine]),
            np.concatenate([g.equivalent_time for g in mine]),
        )
        for name, mine in parts.items()
    }
