"""Where the parts of a lift-plus-cruise vehicle may be: on or inside its airframe.

A vehicle file places every part and mass item by its own coordinates (body frame: x forward
from the nose at x = 0, so the airframe lies at x < 0; y to the right; z down). Each field is
checked on its own (:mod:`lpc_mdo.vehicle.parts`); this module checks them against each other,
so that a tail ahead of the wing, a rotor hub beyond the wing tip or a battery 16 m behind the
tail is refused by name before any analysis (docs theory/geometry 'Where the parts may be').

The rules, with L the fuselage length, W its width, H its height, the body's bottom at
``fuselage.cabin_floor_z`` and its top H above it, b the wing span:

- *attached to the body*: the wing's, horizontal tail's and fin's root leading edges lie on
  the symmetry plane (y = 0), between the nose and the tail end, and at most H/2 above the
  body's top or below its bottom (a high, mid or low wing; a tail on the tail cone; the
  horizontal tail may also sit on top of the fin, a T-tail);
- *tails aft of the wing*: the horizontal tail's and the fin's root leading edges behind the
  wing's root trailing edge (the vehicle's pitch and yaw stability come from them);
- *the wing's sections* add up to the half span that its area and aspect ratio give within a
  factor 1.4 either way: the sections give the planform's shape, which the model scales to area
  and aspect ratio (so a resized wing keeps its sections), but sections that add up to the full
  span, or to half the half span, are a mix-up, not a shape;
- *lift rotors on booms under the wing*: each hub between the nose and the tail end and
  within the wing's half span of the symmetry plane; its boom's attach point within the half
  span and within a rotor radius of its hub's y;
- *the pusher at the tail*: its hub within half the body width of the symmetry plane, behind
  the wing's root trailing edge and at most one pusher radius behind the tail end;
- *no disk through the fuselage or another disk*: a lift disk whose plane lies within the
  body's height must stay clear of the body's plan outline (nose to tail end, half its width
  either side), a pusher disk whose plane crosses the body's length must stay clear of its
  cross-section, and no lift disk may cut through the pusher disk (the body's outline is a box
  here; the optimizer's clearances, :mod:`lpc_mdo.vehicle.clearances`, keep the stated floors);
- *mass items inside the airframe*: the battery, payload, systems, power electronics and other
  masses between the nose and the tail end, within the half span, and at most H/2 above the
  body's top or below its bottom.

These are the layouts the model's geometry holds (the lift-plus-cruise configuration:
fuselage, wing, conventional or T-tail, lift rotors on booms, a pusher at the tail).
"""

from __future__ import annotations

import math

from lpc_mdo.vehicle.schema import VehicleSpecError

#: Largest factor between the sections' half span and sqrt(AR S)/2 (either way).
SECTION_SPAN_FACTOR = 1.4
#: Distance (m) from y = 0 that still counts as on the symmetry plane.
ON_SYMMETRY_PLANE = 1e-6


class _Envelope:
    """The airframe's extent from the fuselage and the wing (see the module docstring)."""

    def __init__(self, parts: dict):
        fuselage, wing = parts["fuselage"], parts["wing"]
        self.length = fuselage.length
        self.half_width = fuselage.max_width / 2.0
        self.bottom = fuselage.cabin_floor_z
        self.top = fuselage.cabin_floor_z - fuselage.max_height
        self.reach = fuselage.max_height / 2.0
        self.half_span = wing.span / 2.0
        self.wing_trailing_edge = wing.root_leading_edge[0] - wing.root_chord

    def x_range(self) -> str:
        return f"x in [{-self.length:.4g}, 0] (m, nose to tail end; fuselage.length)"

    def z_range(self, extra_top: float = 0.0) -> tuple[float, float]:
        return self.top - self.reach - extra_top, self.bottom + self.reach


def _fmt(position) -> str:
    return "[" + ", ".join(f"{float(v):.6g}" for v in position) + "]"


def _refuse(key: str, value, why: str) -> None:
    raise VehicleSpecError(f"'{key}' = {value} is out of range: {why}")


def _check_between_nose_and_tail(env: _Envelope, key: str, position, what: str) -> None:
    x = float(position[0])
    if not -env.length <= x <= 0.0:
        _refuse(key, _fmt(position), f"{what} must lie at {env.x_range()}, got x = {x:.6g}")


def _check_height(env: _Envelope, key: str, position, what: str, extra_top=0.0) -> None:
    low, high = env.z_range(extra_top)
    z = float(position[2])
    if not low <= z <= high:
        _refuse(
            key,
            _fmt(position),
            f"{what} must lie at z in [{low:.4g}, {high:.4g}] (m: at most half the fuselage "
            f"height, {env.reach:.4g}, above its top or below its bottom, "
            f"fuselage.cabin_floor_z), got z = {z:.6g}",
        )


def _check_surface_roots(parts: dict, env: _Envelope) -> None:
    fin_height = parts["vertical_tail"].span
    surfaces = (
        ("wing", "the wing's root", 0.0, False),
        ("horizontal_tail", "the horizontal tail's root", fin_height, True),
        ("vertical_tail", "the fin's root", 0.0, True),
    )
    for name, what, extra_top, aft_of_wing in surfaces:
        key = f"{name}.root_leading_edge"
        position = parts[name].root_leading_edge
        if abs(position[1]) > ON_SYMMETRY_PLANE:
            _refuse(
                key,
                _fmt(position),
                f"{what} must lie on the symmetry plane (y = 0; the surface is mirrored "
                f"about it or, for the fin, lies in it), got y = {position[1]:.6g}",
            )
        _check_between_nose_and_tail(env, key, position, what)
        _check_height(env, key, position, what, extra_top)
        if aft_of_wing and position[0] > env.wing_trailing_edge:
            _refuse(
                key,
                _fmt(position),
                f"{what} leading edge must lie behind the wing's root trailing edge, x <= "
                f"{env.wing_trailing_edge:.4g} (m, wing.root_leading_edge x less the root "
                f"chord), got x = {position[0]:.6g}",
            )


def _check_wing_sections(wing) -> None:
    if wing.sections is None:
        return
    total = sum(s.span for s in wing.sections)
    half = wing.span / 2.0
    if not half / SECTION_SPAN_FACTOR <= total <= half * SECTION_SPAN_FACTOR:
        spans = " + ".join(f"{s.span:.6g}" for s in wing.sections)
        raise VehicleSpecError(
            f"'wing.sections' spans add up to {total:.6g} m ({spans}); allowed: within a "
            f"factor {SECTION_SPAN_FACTOR:g} of the half span sqrt(wing.aspect_ratio x "
            f"wing.area)/2 = {half:.6g} m (each section's span is its extent along one wing "
            "half; the model scales the sections to the area and aspect ratio)"
        )


def _check_rotors(parts: dict, env: _Envelope) -> None:
    attach = parts["booms"].attach_points
    for i, rotor in enumerate(parts["lift_rotors"]):
        key = f"lift_rotors[{i}].hub_position"
        hub = rotor.hub_position
        _check_between_nose_and_tail(env, key, hub, "a lift rotor's hub")
        _check_height(env, key, hub, "a lift rotor's hub")
        if abs(hub[1]) > env.half_span:
            _refuse(
                key,
                _fmt(hub),
                "a lift rotor's hub must lie within the wing's half span of the symmetry "
                f"plane, |y| <= {env.half_span:.4g} (m; its boom hangs from the wing), got "
                f"y = {hub[1]:.6g}",
            )
        if i < len(attach):
            point, akey = attach[i], f"booms.attach_points[{i}]"
            _check_between_nose_and_tail(env, akey, point, "a boom's attach point")
            _check_height(env, akey, point, "a boom's attach point")
            if abs(point[1]) > env.half_span or abs(point[1] - hub[1]) > rotor.radius:
                _refuse(
                    akey,
                    _fmt(point),
                    f"a boom's attach point must lie within the wing's half span "
                    f"(|y| <= {env.half_span:.4g} m) and within a rotor radius "
                    f"({rotor.radius:.4g} m) of its rotor's hub y = {hub[1]:.6g} "
                    f"(lift_rotors[{i}].hub_position), got y = {point[1]:.6g}",
                )
    pusher = parts["pusher"]
    hub = pusher.hub_position
    low, high = -env.length - pusher.radius, env.wing_trailing_edge
    if abs(hub[1]) > env.half_width or not low <= hub[0] <= high:
        _refuse(
            "pusher.hub_position",
            _fmt(hub),
            f"the pusher must sit at the tail: |y| <= {env.half_width:.4g} (m, half the "
            f"fuselage width) and x in [{low:.4g}, {high:.4g}] (behind the wing's root "
            "trailing edge, at most one pusher radius behind the tail end)",
        )
    _check_height(env, "pusher.hub_position", hub, "the pusher's hub")


def _check_disks_through_the_body(parts: dict, env: _Envelope) -> None:
    body = (
        f"the fuselage (x in [{-env.length:.4g}, 0], |y| <= {env.half_width:.4g}, z in "
        f"[{env.top:.4g}, {env.bottom:.4g}] m)"
    )
    for i, rotor in enumerate(parts["lift_rotors"]):
        x, y, z = rotor.hub_position
        if not env.top < z < env.bottom:
            continue  # the disk's plane passes above or below the body
        gap = math.hypot(max(-env.length - x, x, 0.0), max(abs(y) - env.half_width, 0.0))
        if gap < rotor.radius:
            _refuse(
                f"lift_rotors[{i}].hub_position",
                _fmt(rotor.hub_position),
                f"its disk (radius {rotor.radius:.4g} m, plane at z = {z:.4g}) cuts through "
                f"{body}: its hub is {gap:.4g} m from the body's side; allowed: a hub at least "
                "a radius from the body, or the disk above or below it",
            )
    pusher = parts["pusher"]
    x, y, z = pusher.hub_position
    if -env.length < x < 0.0:
        gap = math.hypot(max(abs(y) - env.half_width, 0.0), max(env.top - z, z - env.bottom, 0.0))
        if gap < pusher.radius:
            _refuse(
                "pusher.hub_position",
                _fmt(pusher.hub_position),
                f"its disk (radius {pusher.radius:.4g} m, plane at x = {x:.4g}) cuts through "
                f"{body}; allowed: behind the tail end, x <= {-env.length:.4g}, or clear of "
                "the body's cross-section",
            )

    for i, rotor in enumerate(parts["lift_rotors"]):  # a lift disk through the pusher disk
        xh, yh, zh = rotor.hub_position
        xp, yp, zp = pusher.hub_position
        dx, dz = abs(xp - xh), abs(zh - zp)
        if dx < rotor.radius and dz < pusher.radius:
            # The two disks' chords on the line x = xp, z = zh, where their planes meet.
            half_lift = math.sqrt(rotor.radius**2 - dx**2)
            half_pusher = math.sqrt(pusher.radius**2 - dz**2)
            if abs(yh - yp) < half_lift + half_pusher:
                _refuse(
                    f"lift_rotors[{i}].hub_position",
                    _fmt(rotor.hub_position),
                    f"its disk (radius {rotor.radius:.4g} m) and the pusher disk (radius "
                    f"{pusher.radius:.4g} m at {_fmt(pusher.hub_position)}) cut through each "
                    "other; allowed: disks that do not meet",
                )


def _check_mass_items(parts: dict, env: _Envelope) -> None:
    masses = parts["masses"]
    items = (
        ("battery.cg", parts["battery"].cg, "the battery's"),
        ("masses.payload_cg", masses.payload_cg, "the payload's"),
        ("masses.systems_cg", masses.systems_cg, "the systems'"),
        ("masses.other_cg", masses.other_cg, "the other masses'"),
        ("masses.power_electronics_cg", masses.power_electronics_cg, "the power electronics'"),
    )
    for key, position, owner in items:
        what = f"{owner} centre of gravity"
        _check_between_nose_and_tail(env, key, position, what)
        _check_height(env, key, position, what)
        if abs(position[1]) > env.half_span:
            _refuse(
                key,
                _fmt(position),
                f"{what} must lie within the wing's half span, "
                f"|y| <= {env.half_span:.4g} (m), got y = {position[1]:.6g}",
            )


def check_airframe(parts: dict) -> None:
    """
    Check that every part and mass item is on or inside the airframe (module docstring).

    Raises
    ------
    VehicleSpecError
        At the first part outside, naming its key, its position and the allowed range.
    """
    _check_wing_sections(parts["wing"])
    env = _Envelope(parts)
    _check_surface_roots(parts, env)
    _check_rotors(parts, env)
    _check_disks_through_the_body(parts, env)
    _check_mass_items(parts, env)
