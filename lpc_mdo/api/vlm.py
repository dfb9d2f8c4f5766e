"""Plain-function vortex-lattice aerodynamics of one or more lifting surfaces described by dicts.

:func:`vlm` meshes each surface from a planform dict (trapezoidal, or cranked with ``sections``),
builds a small Problem around :class:`lpc_mdo.groups.vlm.VLMGroup` (the lattice the design
conditions use, all surfaces in one lattice so that they see each other), runs it and returns
plain numbers: CL, CDi, CM, lift, induced drag and the sectional c_l along each span.
"""

import numbers

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.airfoil import get_polar, zero_lift_angle
from lpc_mdo.components.atmosphere import ATMOSPHERE_CONSTANTS
from lpc_mdo.components.geometry.planform import SPACINGS, span_stations
from lpc_mdo.core.checks import check_choice, check_integer, check_number, check_range, check_shape
from lpc_mdo.core.mpi import serial_comm
from lpc_mdo.groups.vlm import VLMGroup, VLMSurface

__all__ = ["SURFACE_KEYS", "MAX_PANELS", "surface_mesh", "vlm"]

#: Keys of a surface dict and their defaults (``REQUIRED`` = must be given).
REQUIRED = object()
SURFACE_KEYS = {
    "span": REQUIRED,
    "root_chord": REQUIRED,
    "tip_chord": None,  # None: = root_chord
    "sweep_le_deg": 0.0,
    "dihedral_deg": 0.0,
    "twist_root_deg": 0.0,
    "twist_tip_deg": 0.0,
    "root_le": (0.0, 0.0, 0.0),
    "num_spanwise": 20,
    "num_chordwise": 4,
    "spacing": "cosine",
    "airfoil": None,
    "sections": None,
    "name": None,
    "reynolds": None,
    "mach": 0.0,
}

#: Largest lattice (all surfaces) :func:`vlm` accepts: the dense influence matrices grow as its
#: square (2000 panels: about 100 MB per angle of attack).
MAX_PANELS = 2000

#: Sea-level dynamic viscosity of the ICAO atmosphere (Pa s), for the default Reynolds number.
_SEA_LEVEL_VISCOSITY = ATMOSPHERE_CONSTANTS["icao"]["mu_ref"]
_ANGLE = {"lower": -90.0, "upper": 90.0, "lower_open": True, "upper_open": True, "units": "deg"}


def _check_surface(index, surface):
    """Validate one surface dict; return it completed with defaults, SI values and radians."""
    where = f"vlm: surfaces[{index}]"
    if not isinstance(surface, dict):
        raise ValueError(
            f"{where} must be a dict with keys {', '.join(SURFACE_KEYS)}, "
            f"got {type(surface).__name__} {surface!r}"[:300]
        )
    unknown = sorted(set(surface) - set(SURFACE_KEYS), key=str)
    if unknown:
        raise ValueError(
            f"{where}: unknown key(s) {', '.join(repr(k) for k in unknown)}; allowed keys: "
            f"{', '.join(SURFACE_KEYS)}"
        )
    missing = [k for k, v in SURFACE_KEYS.items() if v is REQUIRED and k not in surface]
    if missing:
        raise ValueError(f"{where}: missing required key(s) {', '.join(repr(k) for k in missing)}")
    s = {k: surface.get(k, v) for k, v in SURFACE_KEYS.items()}

    name = s["name"] if s["name"] is not None else f"surface_{index}"
    if not (isinstance(name, str) and name.isidentifier()):
        raise ValueError(
            f"{where}: 'name' = {name!r} is not allowed: must be a Python identifier "
            f"(letters, digits, underscores)"
        )
    s["name"] = name
    where = f"vlm: surface '{name}'"
    s["span"] = check_number("span", s["span"], lower=0.0, lower_open=True, units="m", where=where)
    s["root_chord"] = check_number(
        "root_chord", s["root_chord"], lower=0.0, lower_open=True, units="m", where=where
    )
    if s["tip_chord"] is None:
        s["tip_chord"] = s["root_chord"]
    s["tip_chord"] = check_number("tip_chord", s["tip_chord"], lower=0.0, units="m", where=where)
    for key in ("sweep_le_deg", "dihedral_deg", "twist_root_deg", "twist_tip_deg"):
        s[key] = check_number(key, s[key], where=where, **_ANGLE)
    root_le = check_shape("root_le", np.asarray(s["root_le"], dtype=object), (3,), where=where)
    s["root_le"] = np.array(
        [check_number(f"root_le[{i}]", v, units="m", where=where) for i, v in enumerate(root_le)]
    )
    s["num_spanwise"] = check_integer(
        "num_spanwise",
        s["num_spanwise"],
        lower=2,
        upper=None if _is_even(s["num_spanwise"]) else -1,
        allowed=">= 2 and even (panels over the full span; a node lies on the root)",
        where=where,
    )
    s["num_chordwise"] = check_integer(
        "num_chordwise", s["num_chordwise"], lower=1, upper=50, where=where
    )
    check_choice("spacing", s["spacing"], SPACINGS, where=where)
    if s["reynolds"] is not None:
        s["reynolds"] = check_number(
            "reynolds", s["reynolds"], lower=1e3, upper=1e9, allowed="in [1e3, 1e9]", where=where
        )
    s["mach"] = check_number("mach", s["mach"], lower=0.0, upper=0.9, where=where)
    s["sections"] = _check_sections(s["sections"], s, where)
    return s


def _is_even(value):
    return isinstance(value, numbers.Real) and float(value).is_integer() and int(value) % 2 == 0


def _check_sections(sections, s, where):
    """Validate ``sections``; return (fractions, chords, x_le offsets) including root and tip."""
    half = 0.5 * s["span"]
    tip_offset = half * np.tan(np.radians(s["sweep_le_deg"]))
    fractions, chords, offsets = [0.0], [s["root_chord"]], [0.0]
    if sections is None:
        sections = ()
    if isinstance(sections, (str, bytes, dict)) or not hasattr(sections, "__len__"):
        raise ValueError(
            f"{where}: 'sections' = {sections!r} is not allowed: must be None or a list of "
            f"(span_fraction, chord, x_le_offset) tuples"
        )
    for k, section in enumerate(sections):
        label = f"sections[{k}]"
        row = np.asarray(section, dtype=object)
        if row.shape != (3,):
            raise ValueError(
                f"{where}: '{label}' = {section!r} is not allowed: must be a tuple "
                f"(span_fraction, chord, x_le_offset) of 3 numbers"
            )
        fraction = check_number(
            f"{label}[0] (span_fraction)",
            row[0],
            lower=fractions[-1],
            upper=1.0,
            lower_open=True,
            upper_open=True,
            allowed=f"in ({fractions[-1]:.6g}, 1): increasing, strictly inside the half span",
            where=where,
        )
        chord = check_number(
            f"{label}[1] (chord)", row[1], lower=0.0, lower_open=True, units="m", where=where
        )
        offset = check_number(f"{label}[2] (x_le_offset)", row[2], units="m", where=where)
        fractions.append(fraction)
        chords.append(chord)
        offsets.append(offset)
    fractions.append(1.0)
    chords.append(s["tip_chord"])
    offsets.append(tip_offset)
    return np.array(fractions), np.array(chords), np.array(offsets)


def surface_mesh(surface):
    """
    Return the VLM mesh (nx, ny, 3) of a checked surface dict (see :func:`vlm`), in m.

    Body frame x forward, y right, z down; nodes i chord-wise (0 = leading edge, uniform), j
    span-wise from the left tip to the right tip at the stations of
    :func:`~lpc_mdo.components.geometry.planform.span_stations`. With f = abs(eta) the fraction
    of the half span, h = f b/2, the leading-edge offset x_off(f) and the chord c(f) piecewise
    linear through the root, the ``sections`` and the tip (x_off(1) = b/2 tan(sweep_le)), and the
    twist theta(f) linear from ``twist_root_deg`` to ``twist_tip_deg`` (positive nose up, a
    rotation about the leading edge):
    X = (x0 - x_off - s c cos(theta), y0 + eta b/2, z0 - h tan(dihedral) + s c sin(theta)).
    Without ``sections`` this is the mesh of
    :class:`~lpc_mdo.components.geometry.planform.PlanformMeshComp` with linear twist.
    """
    fractions, chords, offsets = surface["sections"]
    eta = span_stations(surface["num_spanwise"], surface["spacing"])
    f = np.abs(eta)
    b, x0 = surface["span"], surface["root_le"]
    chord = np.interp(f, fractions, chords)
    x_off = np.interp(f, fractions, offsets)
    theta = np.radians(
        surface["twist_root_deg"] + (surface["twist_tip_deg"] - surface["twist_root_deg"]) * f
    )
    s = (np.arange(surface["num_chordwise"] + 1) / surface["num_chordwise"])[:, None]
    sc = s * chord[None, :]
    mesh = np.empty((s.size, eta.size, 3))
    mesh[..., 0] = x0[0] - x_off[None, :] - sc * np.cos(theta)[None, :]
    mesh[..., 1] = (x0[1] + 0.5 * b * eta)[None, :]
    z_le = x0[2] - 0.5 * b * f * np.tan(np.radians(surface["dihedral_deg"]))
    mesh[..., 2] = z_le[None, :] + sc * np.sin(theta)[None, :]
    return mesh


def _planform_area_and_mac(surface):
    """Projected area (m**2) and mean aerodynamic chord (m) of the piecewise-linear planform."""
    fractions, chords, _ = surface["sections"]
    dy = np.diff(fractions) * 0.5 * surface["span"]
    a, b = chords[:-1], chords[1:]
    area = 2.0 * np.sum(dy * 0.5 * (a + b))
    mac = 2.0 * np.sum(dy * (a * a + a * b + b * b) / 3.0) / area
    return float(area), float(mac)


def _zero_lift_angle(surface, velocity, density, mac):
    """Sectional zero-lift angle (rad) of the surface's airfoil; 0 for a flat plate (None)."""
    if surface["airfoil"] is None:
        return 0.0, None
    try:
        polar = get_polar(surface["airfoil"])
    except ValueError as err:
        raise ValueError(f"vlm: surface '{surface['name']}': 'airfoil': {err}") from None
    reynolds = surface["reynolds"]
    if reynolds is None:
        reynolds = density * velocity * mac / _SEA_LEVEL_VISCOSITY
    return zero_lift_angle(polar, reynolds, surface["mach"]), float(reynolds)


def vlm(
    surfaces,
    alpha_deg,
    velocity,
    density=1.225,
    beta_deg=0.0,
    reference_area=None,
    reference_point=(0.0, 0.0, 0.0),
    reference_chord=None,
):
    """
    Vortex-lattice lift, induced drag and pitching moment of lifting surfaces given as dicts.

    All surfaces form one lattice (:class:`~lpc_mdo.groups.vlm.VLMGroup`: vortex rings,
    free-stream-aligned wake, Kutta–Joukowski forces; docs theory/aerodynamics 'Vortex-lattice
    method'), so a tail sees the wing's downwash. Inviscid: the drag is the induced drag only (no
    profile drag). Body frame of lpc-mdo: x forward, y right, z down (a point aft of the origin
    has a negative x).

    Parameters
    ----------
    surfaces : dict or list of dict
        One surface dict or a list of them. Keys (SI units; angles in degrees):

        - ``span`` (m, > 0): projected span, both halves (each surface is mirrored about its
          root); ``root_chord`` (m, > 0); ``tip_chord`` (m, >= 0; default = root_chord);
        - ``sweep_le_deg``: leading-edge sweep, positive aft; ``dihedral_deg``: positive tip up;
          ``twist_root_deg``, ``twist_tip_deg``: section incidence at the root and the tip,
          positive nose up, linear in between, a rotation about the leading edge (default 0);
        - ``root_le``: (x, y, z) of the root leading edge, m (default the origin);
        - ``num_spanwise``: panels over the full span (even, default 20); ``num_chordwise``:
          chord-wise panels, uniform (default 4); ``spacing``: span-wise 'cosine' (default,
          nodes clustered at the tips) or 'uniform';
        - ``airfoil``: None (default, flat plate) or anything
          :func:`~lpc_mdo.components.aero.airfoil.get_polar` accepts (a name such as 'ls413', a
          file or a table). The VLM takes the airfoil's camber through its sectional zero-lift
          angle (the boundary-condition normals are tilted by it, as the design conditions do
          with the wing airfoil); it is evaluated at ``reynolds`` (default rho V MAC/mu with
          the sea-level viscosity 1.7894e-5 Pa s) and ``mach`` (default 0);
        - ``sections``: a cranked planform, a list of (span_fraction, chord, x_le_offset) break
          sections, span_fraction = y/(b/2) strictly increasing in (0, 1), chord in m,
          x_le_offset the aft distance of the section's leading edge behind the root leading
          edge, m. Chord and leading edge are piecewise linear through the root, the breaks and
          the tip; the tip leading edge sits b/2 tan(sweep_le_deg) aft of the root's (so
          ``sweep_le_deg`` is the root-to-tip leading-edge sweep). The break is resolved to the
          nearest node (a kink between nodes is cut by that panel);
        - ``name``: an identifier for the results (default ``surface_<index>``).

        Unknown keys are an error that names them.
    alpha_deg : float or array_like (n,)
        Angle(s) of attack, deg, in (-90, 90) (the lattice is linear; keep it below stall).
    velocity : float
        Airspeed, m/s (> 0).
    density : float
        Air density, kg/m**3 (> 0; default sea level).
    beta_deg : float
        Sideslip angle, deg, positive with the wind from the right.
    reference_area : float, optional
        Area of the coefficients, m**2; default: the projected area of the first surface.
    reference_point : array_like (3,)
        Moment reference point, m, body frame.
    reference_chord : float, optional
        Chord of CM, m; default: the mean aerodynamic chord of the first surface,
        (2/S) integral of c**2 dy over its planform.

    Returns
    -------
    dict
        Scalars if ``alpha_deg`` is a scalar, else arrays (n,):
        'CL', 'CDi' (near-field), 'CDi_trefftz' (Trefftz plane), 'CM' (pitching moment
        coefficient about reference_point, positive nose up, M_y/(q S c_ref)), 'lift',
        'induced_drag', 'side_force' (N), 'pitching_moment' (N*m); 'force', 'moment' (body
        axes, N and N*m, shape (3,) or (n, 3)). 'reference_area', 'reference_chord' (the
        values used). 'surfaces': per surface name a dict with 'y' (strip centres, m, left tip
        to right tip), 'span_fraction' ((y - y_root)/(b/2)), 'chord' (strip chords, m), 'cl'
        (sectional lift coefficient of each strip, (ns,) or (n, ns)), 'lift' (N), 'area' and
        'mean_aerodynamic_chord' (planform), 'zero_lift_angle_deg' and 'reynolds' (None for a
        flat plate), 'mesh' (nx, ny, 3), m.

    Examples
    --------
    >>> import lpc_mdo.api as lpc
    >>> wing = {"span": 10.0, "root_chord": 1.0, "num_spanwise": 10, "num_chordwise": 2,
    ...         "spacing": "uniform"}
    >>> out = lpc.vlm(wing, alpha_deg=5.0, velocity=60.0)
    >>> print(f"{out['CL']:.5f} {out['CDi']:.6f}")
    0.44264 0.005877
    """
    if isinstance(surfaces, dict):
        surfaces = [surfaces]
    if isinstance(surfaces, (str, bytes)) or not hasattr(surfaces, "__len__") or not surfaces:
        raise ValueError(
            f"vlm: 'surfaces' = {surfaces!r} is not allowed: must be a surface dict or a "
            f"non-empty list of them"[:300]
        )
    checked = [_check_surface(i, s) for i, s in enumerate(surfaces)]
    names = [s["name"] for s in checked]
    for i, name in enumerate(names):
        if name in names[:i]:
            raise ValueError(
                f"vlm: surfaces[{i}] 'name' = {name!r} is not allowed: must differ from the "
                f"other surfaces' names"
            )
    num_panels = sum(s["num_spanwise"] * s["num_chordwise"] for s in checked)
    if num_panels > MAX_PANELS:
        raise ValueError(
            f"vlm: 'num_spanwise x num_chordwise' summed over the surfaces = {num_panels} is out "
            f"of range: must be <= {MAX_PANELS} panels"
        )
    scalar = np.ndim(alpha_deg) == 0
    alpha = check_range(
        "alpha_deg", np.atleast_1d(np.asarray(alpha_deg, dtype=float)), where="vlm", **_ANGLE
    )
    if alpha.ndim != 1:
        raise ValueError(f"vlm: 'alpha_deg' must be a number or a 1-D array, got {alpha.shape}")
    velocity = check_number(
        "velocity", velocity, lower=0.0, lower_open=True, units="m/s", where="vlm"
    )
    density = check_number(
        "density", density, lower=0.0, lower_open=True, units="kg/m**3", where="vlm"
    )
    beta = check_number("beta_deg", beta_deg, where="vlm", **_ANGLE)
    point = check_shape(
        "reference_point", np.asarray(reference_point, dtype=object), (3,), where="vlm"
    )
    point = np.array(
        [
            check_number(f"reference_point[{i}]", v, units="m", where="vlm")
            for i, v in enumerate(point)
        ]
    )
    area0, mac0 = _planform_area_and_mac(checked[0])
    if reference_area is None:
        reference_area = area0
    reference_area = check_number(
        "reference_area", reference_area, lower=0.0, lower_open=True, units="m**2", where="vlm"
    )
    if reference_chord is None:
        reference_chord = mac0
    reference_chord = check_number(
        "reference_chord", reference_chord, lower=0.0, lower_open=True, units="m", where="vlm"
    )

    nn = alpha.size
    lattice = tuple(VLMSurface(s["name"], s["num_chordwise"], s["num_spanwise"]) for s in checked)
    meshes = [surface_mesh(s) for s in checked]
    zero_lift = [
        _zero_lift_angle(s, velocity, density, _planform_area_and_mac(s)[1]) for s in checked
    ]

    prob = om.Problem(reports=False, comm=serial_comm())
    ivc = prob.model.add_subsystem("inputs", om.IndepVarComp(), promotes=["*"])
    for s, mesh in zip(checked, meshes, strict=True):
        ivc.add_output(f"{s['name']}_mesh", mesh, units="m")
    prob.model.add_subsystem("vlm", VLMGroup(surfaces=lattice, num_nodes=nn), promotes=["*"])
    prob.setup()
    prob.set_val("speed", np.full(nn, velocity), units="m/s")
    prob.set_val("density", np.full(nn, density), units="kg/m**3")
    prob.set_val("angle_of_attack", alpha, units="deg")
    prob.set_val("sideslip_angle", np.full(nn, beta), units="deg")
    prob.set_val("reference_area", reference_area, units="m**2")
    prob.set_val("reference_point", point, units="m")
    for s, (alpha0, _) in zip(checked, zero_lift, strict=True):
        prob.set_val(
            f"{s['name']}_zero_lift_angle", np.full((nn, s["num_spanwise"]), alpha0), units="rad"
        )
    prob.run_model()

    q_s = 0.5 * density * velocity**2 * reference_area
    moment = prob.get_val("moment", units="N*m").copy()
    result = {
        "CL": prob.get_val("CL").copy(),
        "CDi": prob.get_val("CDi").copy(),
        "CDi_trefftz": prob.get_val("trefftz_induced_drag", units="N") / q_s,
        "CM": moment[:, 1] / (q_s * reference_chord),
        "lift": prob.get_val("lift", units="N").copy(),
        "induced_drag": prob.get_val("induced_drag", units="N").copy(),
        "side_force": prob.get_val("side_force", units="N").copy(),
        "pitching_moment": moment[:, 1].copy(),
        "force": prob.get_val("force", units="N").copy(),
        "moment": moment,
    }
    panel_forces = prob.get_val("panel_forces", units="N")
    lift_direction = prob.get_val("lift_direction")
    per_surface = {}
    offset = 0
    for s, mesh, (alpha0, reynolds) in zip(checked, meshes, zero_lift, strict=True):
        n_panels = s["num_spanwise"] * s["num_chordwise"]
        forces = panel_forces[:, offset : offset + n_panels]
        offset += n_panels
        le, te = mesh[0], mesh[-1]
        chord_nodes = np.linalg.norm(te[:, [0, 2]] - le[:, [0, 2]], axis=1)
        area, mac = _planform_area_and_mac(s)
        y = 0.5 * (le[1:, 1] + le[:-1, 1])
        per_surface[s["name"]] = {
            "y": y,
            "span_fraction": (y - s["root_le"][1]) / (0.5 * s["span"]),
            "chord": 0.5 * (chord_nodes[1:] + chord_nodes[:-1]),
            "cl": prob.get_val(f"{s['name']}_sectional_cl").copy(),
            "lift": np.einsum("npk,nk->n", forces, lift_direction),
            "area": area,
            "mean_aerodynamic_chord": mac,
            "zero_lift_angle_deg": float(np.degrees(alpha0)),
            "reynolds": reynolds,
            "mesh": mesh,
        }
    if scalar:
        result = {k: v[0] if v.ndim == 1 else v[0].copy() for k, v in result.items()}
        result = {k: float(v) if np.ndim(v) == 0 else v for k, v in result.items()}
        for data in per_surface.values():
            data["cl"] = data["cl"][0].copy()
            data["lift"] = float(data["lift"][0])
    result["reference_area"] = reference_area
    result["reference_chord"] = reference_chord
    result["surfaces"] = per_surface
    return result
