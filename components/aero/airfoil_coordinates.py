"""
Airfoil coordinates: reading a Selig-format file and the section numbers the vehicle takes from it.

A designer's own wing or tail airfoil comes as a polar file (its aerodynamics) and a coordinate
file (its shape). From the shape the model takes the maximum thickness and its chord-wise
position (the drag build-up's form factor, docs theory/aerodynamics 'Drag build-up'), the
wing box's depth, camber offset and skin radii
(:class:`~lpc_mdo.components.structures.wing_box_geometry.WingBoxSection`), and the thin-airfoil
zero-lift angle, which checks that the polar and the coordinates describe the same section.

Definitions:

- thickness t/c: the largest distance between the upper and lower surface at one x/c
  (Abbott & von Doenhoff, Theory of Wing Sections, 1959, sec. 6.2, measured normal to the chord
  line rather than to the camber line; the two differ by O(camber slope^2));
- thin-airfoil zero-lift angle (Abbott & von Doenhoff sec. 4.3; Anderson, Fundamentals of
  Aerodynamics, 6th ed., eq. 4.61):
  alpha_L0 = -(1/pi) int_0^pi (dz/dx)(cos theta - 1) dtheta with x/c = (1 - cos theta)/2 and
  z the camber line (y_upper + y_lower)/2. NACA 4412 gives -4.15 deg (Anderson, Example 4.6);
  measured sections lie within about 1 deg of it (viscous decambering; Abbott & von Doenhoff
  appendix IV: NACA 4412 -4.0 deg).
"""

import dataclasses
import math
from pathlib import Path

import numpy as np

#: Fewest and most points of a coordinate file: a section needs some 20 points to resolve its
#: nose and thickness (UIUC tables have 35-200); 2000 catches a file of something else.
MIN_POINTS = 20
MAX_POINTS = 2000
#: How far the chord may be from [0, 1] (a normalised table holds x/c from 0 to 1; tables
#: rounded to 4-5 digits or with a closed blunt trailing edge stay within 0.005).
CHORD_TOLERANCE = 0.005


@dataclasses.dataclass(frozen=True)
class AirfoilShape:
    """
    Section numbers from airfoil coordinates.

    Attributes
    ----------
    name : str
        The file's first line, or its file name.
    coordinates : ndarray, (n, 2)
        x/c, y/c in Selig order (trailing edge, upper surface, leading edge, lower surface).
    thickness_to_chord : float
        Maximum thickness over chord (-).
    max_thickness_location : float
        x/c of the maximum thickness (-).
    max_camber : float
        Largest camber-line height over chord (-), signed.
    zero_lift_angle : float
        Thin-airfoil zero-lift angle (rad), negative for positive camber.
    """

    name: str
    coordinates: np.ndarray
    thickness_to_chord: float
    max_thickness_location: float
    max_camber: float
    zero_lift_angle: float

    def surfaces(self):
        """Return (upper, lower): (m, 2) arrays of x/c, y/c, leading to trailing edge."""
        return split_surfaces(self.coordinates)


def split_surfaces(coordinates, source="coordinates"):
    """
    Split Selig-order coordinates at the leading edge (least x) into two surfaces.

    Returns (upper, lower), each running from the leading edge to the trailing edge with x/c
    strictly increasing; raises ValueError naming ``source`` if either surface folds back.
    """
    xy = np.asarray(coordinates, dtype=float)
    le = int(np.argmin(xy[:, 0]))
    upper, lower = xy[: le + 1][::-1], xy[le:]
    for name, surf in (("upper", upper), ("lower", lower)):
        if surf.shape[0] < 2 or np.any(np.diff(surf[:, 0]) <= 0.0):
            raise ValueError(
                f"{source}: the {name} surface is not monotonic in x/c; allowed: Selig order "
                "(trailing edge -> upper surface -> leading edge -> lower surface -> trailing "
                "edge), one point per x/c on each surface"
            )
    return upper, lower


def airfoil_shape(coordinates, name="coordinates"):
    """
    Section numbers of Selig-order coordinates; ValueError naming ``name`` if they are no airfoil.

    The chord must run from x/c = 0 to 1 (within :data:`CHORD_TOLERANCE`), the upper surface
    must lie above the lower one wherever both are defined, and the section must have a
    thickness.
    """
    xy = np.asarray(coordinates, dtype=float)
    if xy.ndim != 2 or xy.shape[1] != 2 or not MIN_POINTS <= xy.shape[0] <= MAX_POINTS:
        raise ValueError(
            f"{name}: {xy.shape[0] if xy.ndim == 2 else 0} points of (x/c, y/c); allowed: "
            f"{MIN_POINTS} to {MAX_POINTS} points"
        )
    if not np.all(np.isfinite(xy)):
        raise ValueError(f"{name}: holds a non-finite number; allowed: finite x/c, y/c")
    lo, hi = float(np.min(xy[:, 0])), float(np.max(xy[:, 0]))
    if abs(lo) > CHORD_TOLERANCE or abs(hi - 1.0) > CHORD_TOLERANCE:
        raise ValueError(
            f"{name}: x/c runs from {lo:.4g} to {hi:.4g}; allowed: coordinates normalised to a "
            f"unit chord (x/c from 0 to 1 within {CHORD_TOLERANCE:g})"
        )
    upper, lower = split_surfaces(xy, name)
    x = 0.5 * (1.0 - np.cos(np.linspace(0.0, math.pi, 401)))  # cosine spacing, dense at the LE
    x = np.clip(x, max(upper[0, 0], lower[0, 0]), min(upper[-1, 0], lower[-1, 0]))
    y_up, y_lo = np.interp(x, upper[:, 0], upper[:, 1]), np.interp(x, lower[:, 0], lower[:, 1])
    thickness = y_up - y_lo
    if np.min(thickness) < -1e-4:
        where = float(x[np.argmin(thickness)])
        raise ValueError(
            f"{name}: the upper surface lies below the lower one at x/c = {where:.3g}; "
            "allowed: Selig order with the upper surface first"
        )
    i = int(np.argmax(thickness))
    camber = 0.5 * (y_up + y_lo)
    return AirfoilShape(
        name=name,
        coordinates=xy,
        thickness_to_chord=float(thickness[i]),
        max_thickness_location=float(x[i]),
        max_camber=float(camber[np.argmax(np.abs(camber))]),
        zero_lift_angle=_thin_airfoil_zero_lift_angle(upper, lower),
    )


def _thin_airfoil_zero_lift_angle(upper, lower):
    """alpha_L0 = -(1/pi) int_0^pi (dz/dx)(cos theta - 1) dtheta (module docstring)."""
    theta = np.linspace(0.0, math.pi, 2001)
    mid = 0.5 * (theta[1:] + theta[:-1])  # midpoints: dz/dx is steep at the edges
    x = 0.5 * (1.0 - np.cos(theta))
    x = np.clip(x, max(upper[0, 0], lower[0, 0]), min(upper[-1, 0], lower[-1, 0]))
    z = 0.5 * (np.interp(x, upper[:, 0], upper[:, 1]) + np.interp(x, lower[:, 0], lower[:, 1]))
    dx, dz = np.diff(x), np.diff(z)
    slope = np.divide(dz, dx, out=np.zeros_like(dz), where=dx > 0.0)  # 0 where x is clipped
    return float(-np.sum(slope * (np.cos(mid) - 1.0) * np.diff(theta)) / math.pi)


def read_coordinates(path):
    """
    Read a Selig-format coordinate file: an optional name line, then x/c y/c pairs.

    Returns the :class:`AirfoilShape`. Lines of two numbers are points; the first line may be
    the name; any other line is an error naming the path and the line (a Lednicer file, whose
    second line gives the point counts of each surface, is refused with that reason).
    """
    path = Path(path)
    raw = path.read_bytes()
    if b"\0" in raw:
        raise ValueError(f"coordinate file '{path}' is binary; allowed: a Selig-format text file")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ValueError(
            f"coordinate file '{path}' is not UTF-8 text (byte {exc.start}); allowed: a "
            "Selig-format text file"
        ) from exc
    lines = [line for line in text.splitlines() if line.strip()]
    name, points = path.stem, []
    for number, line in enumerate(lines):
        parts = line.replace(",", " ").split()
        try:
            values = [float(p) for p in parts]
        except ValueError:
            if number == 0:
                name = line.strip()
                continue
            raise ValueError(
                f"coordinate file '{path}': line {number + 1} {line.strip()[:60]!r} is not a "
                "pair of numbers; allowed: a name line, then x/c y/c pairs (Selig format)"
            ) from None
        if len(values) != 2:
            raise ValueError(
                f"coordinate file '{path}': line {number + 1} holds {len(values)} numbers; "
                "allowed: a name line, then x/c y/c pairs (Selig format)"
            )
        points.append(values)
    if points and min(points[0]) > 1.5:  # Lednicer: "n_upper n_lower" after the name
        raise ValueError(
            f"coordinate file '{path}' starts with the point counts {points[0]} (Lednicer "
            "format); allowed: Selig format (trailing edge -> upper -> leading edge -> lower -> "
            "trailing edge)"
        )
    return airfoil_shape(np.array(points).reshape(-1, 2), f"coordinate file '{path}' ({name})")


def naca_four_digit(code, num_points=81):
    """
    Selig-order coordinates of a NACA four-digit section (closed trailing edge).

    Abbott & von Doenhoff, Theory of Wing Sections, 1959, sec. 6.4: thickness
    y_t = 5 t (0.2969 sqrt(x) - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 - 0.1036 x^4) (the last
    coefficient -0.1036 closes the trailing edge), camber line of maximum m at p, surfaces
    offset normal to the camber line. ``num_points`` per surface, cosine-spaced.
    """
    m, p, t = int(code[0]) / 100.0, int(code[1]) / 10.0, int(code[2:]) / 100.0
    x = 0.5 * (1.0 - np.cos(np.linspace(0.0, math.pi, num_points)))
    yt = (
        5.0 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    )
    if m == 0.0:
        yc, slope = np.zeros_like(x), np.zeros_like(x)
    else:
        fore = x < p
        yc = np.where(
            fore, m / p**2 * (2 * p * x - x**2), m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x**2)
        )
        slope = np.where(fore, 2 * m / p**2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
    th = np.arctan(slope)
    upper = np.column_stack([x - yt * np.sin(th), yc + yt * np.cos(th)])
    lower = np.column_stack([x + yt * np.sin(th), yc - yt * np.cos(th)])
    return np.vstack([upper[::-1], lower[1:]])
