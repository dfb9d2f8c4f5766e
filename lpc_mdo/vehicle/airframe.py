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
- *no wing box through the seats*: a wing whose root chord lies over the cabin sits in the
  body's top quarter (a high wing on the roof fairing) or under the cabin floor;
- *tails aft of the wing*: the horizontal tail's and the fin's root leading edges behind the
  wing's root trailing edge (the vehicle's pitch and yaw stability come from them);
- *the wing's sections* add up to the half span that its area and aspect ratio give within a
  factor 1.4 either way: the sections give the planform's shape, which the model scales to area
  and aspect ratio (so a resized wing keeps its sections), but sections that add up to the full
  span, or to half the half span, are a mix-up, not a shape;
- *lift rotors on booms under the wing*: each hub between the nose and the tail end and
  within the wing's half span of the symmetry plane; its boom's attach point within the half
  span and within a rotor radius of its hub's y;
- *booms that reach their rotors*: ``booms.length`` at least the farthest distance from an
  attach point to its hub and at most a rotor radius more;
- *wing sections of a real taper*: every section chord at least 1/20 of the largest, but a
  pointed tip (the last tip chord may be 0); the whole-wing sweep and dihedral within 2 deg of
  the sections' root-to-tip leading edge;
- *the pusher at the tail*: its hub within half the body width of the symmetry plane, behind
  the wing's root trailing edge and at most one pusher radius behind the tail end;
- *no disk through the fuselage or another disk*: a lift disk whose plane lies within the
  body's height must stay clear of the body's plan outline (nose to tail end, half its width
  either side), a pusher disk whose plane crosses the body's length must stay clear of its
  cross-section, and no lift disk may cut through the pusher disk (the body's outline is a box
  here; the optimizer's clearances, :mod:`lpc_mdo.vehicle.clearances`, keep the stated floors);
- *no disk through a wing or tail*: no point of a rotor disk (a lift rotor's or the pusher's,
  hub included) may lie inside the wing, the horizontal tail or the fin: over the surface's
  planform (between its leading and trailing edges, within its span) and within half the
  section's thickness, (t/c) c / 2, of its chord line (the disk is a circle normal to its
  thrust axis; the surface is the planform the model builds, with its dihedral and incidence);
  the optimizer's plan-view clearances keep the disks off the horizontal tail as well;
- *the fin on the body*: its root, from which its height is measured upwards, at or above the
  body's bottom (a fin hung below the belly would run up through the fuselage);
- *the payload in the cabin's width*: its centre of gravity within half the fuselage width of
  the symmetry plane (the cabin check, :mod:`lpc_mdo.vehicle.consistency`, holds its x and z);
- *mass items inside the airframe*: the battery, payload, systems, power electronics and other
  masses between the nose and the tail end, within the half span, and at most H/2 above the
  body's top or below its bottom; one farther than W/2 from the symmetry plane inside the wing
  (the section test of the disks above);
- *the horizontal tail on the tail cone or the fin*: its root no higher than the fin's tip.

These are the layouts the model's geometry holds (the lift-plus-cruise configuration:
fuselage, wing, conventional or T-tail, lift rotors on booms, a pusher at the tail).
"""

from __future__ import annotations

import math

import numpy as np

from lpc_mdo.vehicle.schema import VehicleSpecError

#: Largest factor between the sections' half span and sqrt(AR S)/2 (either way).
SECTION_SPAN_FACTOR = 1.4
#: Largest difference (deg) between a sectioned wing's whole-wing sweep or dihedral and the
#: root-to-tip leading edge of its sections (the reference's: 7.81 and 7.82 deg, -2 and -2 deg).
WHOLE_WING_ANGLE_TOLERANCE_DEG = 2.0
#: Smallest wing-section chord as a fraction of the largest (all but a pointed tip): a taper
#: beyond 20:1 is a typing error (the reference's root to tip is 5.2:1, built wings 2-10:1).
MIN_CHORD_FRACTION = 0.05
#: Distance (m) from y = 0 that still counts as on the symmetry plane.
ON_SYMMETRY_PLANE = 1e-6
#: Points of a rotor disk tested against the surfaces: rings and points per ring (the hub is
#: one more); 24 rings put them under 7 cm apart on the reference's 1.5 m radius.
DISK_RINGS, DISK_POINTS_PER_RING = 24, 96


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
    fin = parts["vertical_tail"]
    fin_tip_z = fin.root_leading_edge[2] - fin.span
    surfaces = (
        ("wing", "the wing's root", 0.0, False),
        ("horizontal_tail", "the horizontal tail's root", fin.span, True),
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
        if name == "horizontal_tail" and position[2] < min(fin_tip_z, env.top) - 1e-6:
            _refuse(
                key,
                _fmt(position),
                f"the horizontal tail's root must lie on the tail cone or on the fin, at most "
                f"as high as the fin's tip, z >= {min(fin_tip_z, env.top):.4g} (m; "
                f"vertical_tail.root_leading_edge z less its height {fin.span:.4g}), got z = "
                f"{position[2]:.6g}",
            )
        if name == "vertical_tail" and position[2] > env.bottom:
            _refuse(
                key,
                _fmt(position),
                f"the fin's root (its height is measured upwards from it) must lie at or above "
                f"the fuselage's bottom, z <= fuselage.cabin_floor_z = {env.bottom:.4g} (m), "
                f"got z = {position[2]:.6g}",
            )
        if aft_of_wing and position[0] > env.wing_trailing_edge:
            _refuse(
                key,
                _fmt(position),
                f"{what} leading edge must lie behind the wing's root trailing edge, x <= "
                f"{env.wing_trailing_edge:.4g} (m, wing.root_leading_edge x less the root "
                f"chord), got x = {position[0]:.6g}",
            )


#: Part of the body's height, from its top, that a wing's root may take over the cabin: the
#: cabin's ceiling lies below the roof fairing that carries a high wing (the reference's root
#: chord is 0.08 m, 5 % of the height, below the body's top line).
WING_ROOT_FAIRING = 0.25


def _check_wing_over_cabin(parts: dict, env: _Envelope) -> None:
    """Check that a wing whose root chord lies over the cabin is high (or low, under the floor)."""
    fuselage, wing = parts["fuselage"], parts["wing"]
    x_le, _, z = wing.root_leading_edge
    over_cabin = x_le > -fuselage.cabin_end and x_le - wing.root_chord < -fuselage.cabin_start
    lowest_high_wing = env.top + WING_ROOT_FAIRING * (env.bottom - env.top)
    if over_cabin and lowest_high_wing < z < env.bottom:
        _refuse(
            "wing.root_leading_edge",
            _fmt(wing.root_leading_edge),
            f"the wing's root chord lies over the cabin (x in [-{fuselage.cabin_end:.4g}, "
            f"-{fuselage.cabin_start:.4g}] m), so its box would run through the seats unless the "
            f"wing sits in the top {WING_ROOT_FAIRING:.0%} of the body, z <= "
            f"{lowest_high_wing:.4g} (a high wing), or under the floor, z >= {env.bottom:.4g} "
            f"(m, fuselage.cabin_floor_z), got z = {z:.6g}",
        )


def _check_wing_sections(wing) -> None:
    if wing.sections is None:
        return
    chords = [c for s in wing.sections for c in (s.root_chord, s.tip_chord)][:-1]
    largest = max(chords)
    for k, section in enumerate(wing.sections):
        for name in ("root_chord", "tip_chord"):
            chord = getattr(section, name)
            if (k, name) != (len(wing.sections) - 1, "tip_chord") and (
                chord < MIN_CHORD_FRACTION * largest
            ):
                raise VehicleSpecError(
                    f"'wing.sections[{k}].{name}' = {chord!r} is out of range: must be >= "
                    f"{MIN_CHORD_FRACTION:g} x the largest section chord {largest:g} = "
                    f"{MIN_CHORD_FRACTION * largest:.4g} (m); only the tip may be pointed "
                    "(a tip_chord of 0 on the last section)"
                )
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
    # The whole-wing sweep and dihedral (the estimates that need one number) are those of the
    # sections' root-to-tip leading edge.
    tip = np.asarray(wing._geometry()["section_leading_edges"])[-1]
    derived = {
        "sweep_deg": math.degrees(math.atan2(-tip[0], tip[1])),
        "dihedral_deg": math.degrees(math.atan2(-tip[2], tip[1])),
    }
    for key, angle in derived.items():
        given = math.degrees(getattr(wing, key.removesuffix("_deg")))
        if abs(given - angle) > WHOLE_WING_ANGLE_TOLERANCE_DEG:
            raise VehicleSpecError(
                f"'wing.{key}' = {given:.6g} is out of range: the sections' leading edge from "
                f"root to tip gives {angle:.4g} deg; allowed: within "
                f"{WHOLE_WING_ANGLE_TOLERANCE_DEG:g} deg of it (the whole-wing figure of the "
                "estimates that need one number)"
            )


def _check_boom_length(parts: dict) -> None:
    """Each boom reaches from its attach point to its hub and runs past it by at most a radius."""
    booms, rotors = parts["booms"], parts["lift_rotors"]
    pairs = list(zip(booms.attach_points, rotors, strict=False))
    if not pairs:
        return
    reach = max(math.dist(point, r.hub_position) for point, r in pairs)
    overhang = max(r.radius for r in rotors)
    if not reach <= booms.length <= reach + overhang:
        raise VehicleSpecError(
            f"'booms.length' = {booms.length!r} is out of range: a boom runs from its attach "
            f"point (booms.attach_points) to its rotor's hub, the farthest {reach:.4g} m, and "
            f"past it by at most a rotor radius ({overhang:.4g} m): must be in "
            f"[{reach:.4g}, {reach + overhang:.4g}] (m)"
        )


def _check_rotors(parts: dict, env: _Envelope) -> None:
    attach = parts["booms"].attach_points
    if len(attach) != len(parts["lift_rotors"]):
        raise VehicleSpecError(
            f"'booms.attach_points' has {len(attach)} entries; allowed: one per lift rotor, "
            f"{len(parts['lift_rotors'])} ([[lift_rotors]] tables), in their order"
        )
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


def _surface_stations(surface, mirrored: bool):
    """
    Return the surface's leading edge and chord at stations along its span: le (n, 3), c (n,).

    The right half of a mirrored surface (the wing's sections as the model scales them, or a
    trapezoid), or the fin from its root upwards.
    """
    root = np.asarray(surface.root_leading_edge, dtype=float)
    if getattr(surface, "sections", None) is not None:
        geometry = surface._geometry()
        return root + geometry["section_leading_edges"], np.asarray(geometry["section_chords"])
    h = surface.span / 2.0 if mirrored else surface.span
    if mirrored:  # dihedral > 0 raises the tip (-z)
        tip = root + h * np.array([-math.tan(surface.sweep), 1.0, -math.tan(surface.dihedral)])
    else:
        tip = root + h * np.array([-math.tan(surface.sweep), 0.0, -1.0])
    return np.array([root, tip]), np.array([surface.root_chord, surface.tip_chord])


def _disk_points(rotor) -> np.ndarray:
    """Points (n, 3) covering a rotor's disk: its hub and rings out to its radius."""
    n = np.asarray(rotor.thrust_axis, dtype=float)
    n = n / np.linalg.norm(n)
    e1 = np.cross(n, [0.0, 1.0, 0.0] if abs(n[1]) < 0.9 else [1.0, 0.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    r = rotor.radius * np.linspace(0.0, 1.0, DISK_RINGS + 1)[1:, None]
    psi = np.linspace(0.0, 2.0 * math.pi, DISK_POINTS_PER_RING, endpoint=False)[None, :]
    ring = (r * np.cos(psi))[..., None] * e1 + (r * np.sin(psi))[..., None] * e2
    hub = np.asarray(rotor.hub_position, dtype=float)
    return np.vstack([hub, hub + ring.reshape(-1, 3)])


def _inside_surface(points, surface, mirrored: bool) -> np.ndarray:
    """Which points lie inside the surface's section (see the module docstring)."""
    le, chord = _surface_stations(surface, mirrored)
    x, y, z = points.T
    if mirrored:  # span along |y|, the section's thickness along z
        span, normal, le_span, le_normal = np.abs(y), z, le[:, 1], le[:, 2]
    else:  # the fin: span upwards (-z) from its root, thickness along y
        span, normal, le_span, le_normal = le[0, 2] - z, y, le[0, 2] - le[:, 2], le[:, 1]
    within = (span >= le_span[0]) & (span <= le_span[-1])
    le_x = np.interp(span, le_span, le[:, 0])
    c = np.interp(span, le_span, chord)
    aft = le_x - x  # distance behind the leading edge
    chord_line = np.interp(span, le_span, le_normal) + (aft * math.sin(surface.incidence))
    t_c = surface.thickness_to_chord or 0.15
    return within & (aft >= 0.0) & (aft <= c) & (np.abs(normal - chord_line) <= 0.5 * t_c * c)


def _check_disks_through_surfaces(parts: dict) -> None:
    surfaces = (
        ("wing", "the wing", True),
        ("horizontal_tail", "the horizontal tail", True),
        ("vertical_tail", "the fin", False),
    )
    rotors = [(f"lift_rotors[{i}]", r) for i, r in enumerate(parts["lift_rotors"])]
    rotors.append(("pusher", parts["pusher"]))
    for path, rotor in rotors:
        points = _disk_points(rotor)
        for name, what, mirrored in surfaces:
            inside = _inside_surface(points, parts[name], mirrored)
            if inside.any():
                where = points[np.flatnonzero(inside)[0]]
                _refuse(
                    f"{path}.hub_position",
                    _fmt(rotor.hub_position),
                    f"its disk (radius {rotor.radius:.4g} m, thrust axis "
                    f"{_fmt(rotor.thrust_axis)}) cuts through {what} (e.g. at {_fmt(where)} m, "
                    f"inside the section between its leading and trailing edges, within half its "
                    f"thickness of the chord line; {name}.root_leading_edge = "
                    f"{_fmt(parts[name].root_leading_edge)}, span {parts[name].span:.4g} m and "
                    f"root chord {parts[name].root_chord:.4g} m from its area and aspect ratio); "
                    "allowed: a disk above, below, ahead of or behind every surface",
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
    payload = masses.payload_cg
    if abs(payload[1]) > env.half_width:
        _refuse(
            "masses.payload_cg",
            _fmt(payload),
            f"the payload's centre of gravity must lie in the cabin, within half the fuselage "
            f"width of the symmetry plane, |y| <= {env.half_width:.4g} (m), got y = "
            f"{payload[1]:.6g}",
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
        outside_body = abs(position[1]) > env.half_width
        if outside_body and not _inside_surface(np.array([position]), parts["wing"], True)[0]:
            _refuse(
                key,
                _fmt(position),
                f"{what} lies outside the fuselage (|y| > {env.half_width:.4g} m, half its "
                "width), so it must lie inside the wing: between its leading and trailing "
                "edges, within half its thickness of the chord line",
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
    _check_wing_over_cabin(parts, env)
    _check_rotors(parts, env)
    _check_disks_through_the_body(parts, env)
    _check_disks_through_surfaces(parts)
    _check_boom_length(parts)
    _check_mass_items(parts, env)
