"""Plain-function structural analyses: a 3-D frame (``beam``) and a wing box (``box_beam``).

Each builds a small Problem around :class:`lpc_mdo.groups.beam.BeamGroup` or
:class:`lpc_mdo.groups.beam.BoxBeamGroup` (the assemblies the structural condition uses), runs
it and returns plain numbers.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.structures.box_section import TORSION_FORMULAS
from lpc_mdo.core.checks import check_number, check_range, check_shape
from lpc_mdo.core.mpi import serial_comm
from lpc_mdo.groups.beam import BeamGroup, BoxBeamGroup

__all__ = ["beam", "box_beam"]


def _array(name, value, shape=None, positive=False, units=""):
    if shape is not None:
        check_shape(name, value, shape)
    arr = check_range(
        name, value, lower=0.0 if positive else None, lower_open=True, units=units or None
    )
    return np.asarray(arr, dtype=float)


def _per_element(name, value, num_elements, units):
    arr = _array(name, value, positive=True, units=units)
    if arr.ndim == 0:
        return np.full(num_elements, float(arr))
    if arr.shape != (num_elements,):
        raise ValueError(
            f"'{name}' must be a scalar or have shape ({num_elements},) (one value "
            f"per element), got shape {arr.shape}."
        )
    return arr


def _scalar(name, value, units, low=0.0, high=np.inf):
    return check_number(
        name,
        value,
        lower=low,
        upper=None if np.isinf(high) else high,
        lower_open=True,
        upper_open=True,
        units=units or None,
    )


def _frame_arguments(nodes, loads, fixed_nodes):
    nodes = _array("nodes", nodes)
    if nodes.ndim != 2 or nodes.shape[1] != 3 or nodes.shape[0] < 2:
        raise ValueError(f"'nodes' must have shape (num_nodes >= 2, 3), got {nodes.shape}.")
    n = nodes.shape[0]
    loads = _array("loads", loads, shape=(n, 6))
    fixed = tuple(fixed_nodes)
    if not fixed or any(not isinstance(i, (int, np.integer)) or not 0 <= i < n for i in fixed):
        raise ValueError(
            f"'fixed_nodes' = {fixed_nodes!r} must be a non-empty sequence of node "
            f"indices in [0, {n - 1}]."
        )
    return nodes, loads, tuple(int(i) for i in fixed)


def _run(group, values):
    prob = om.Problem(reports=False, comm=serial_comm())
    prob.model.add_subsystem("beam", group, promotes=["*"])
    prob.setup()
    for name, val in values.items():
        prob.set_val(name, val)
    prob.run_model()
    return prob


def _frame_results(prob):
    ne = prob.get_val("section_forces").shape[0]
    ends = np.concatenate(
        [prob.get_val("element_end_forces"), prob.get_val("element_end_moments")], axis=2
    )  # (ne, 2, 6)
    return {
        "displacements": np.hstack([prob.get_val("displacements"), prob.get_val("rotations")]),
        "reactions": np.hstack([prob.get_val("reaction_forces"), prob.get_val("reaction_moments")]),
        "element_forces": ends.reshape(ne, 12),
        "section_loads": np.hstack(
            [prob.get_val("section_forces"), prob.get_val("section_moments")]
        ),
        "element_mass": prob.get_val("element_mass").copy(),
        "mass": float(prob.get_val("beam_mass")[0]),
        "cg": prob.get_val("beam_cg").copy(),
    }


def beam(
    nodes,
    area,
    bending_inertia_vertical,
    bending_inertia_inplane,
    torsion_constant,
    youngs_modulus,
    shear_modulus,
    density,
    loads,
    fixed_nodes=(0,),
):
    """
    Solve a linear static Euler-Bernoulli frame of consecutive nodes (BeamGroup).

    Parameters
    ----------
    nodes : array_like, (num_nodes, 3)
        Node coordinates, m; element i joins nodes i and i + 1.
    area : float or array_like (num_elements,)
        Section area, m**2 (> 0).
    bending_inertia_vertical : float or array_like (num_elements,)
        I_y about the element's local y axis (bending in the local x-z plane), m**4 (> 0).
    bending_inertia_inplane : float or array_like (num_elements,)
        I_z about the local z axis, m**4 (> 0).
    torsion_constant : float or array_like (num_elements,)
        J, m**4 (> 0).
    youngs_modulus, shear_modulus : float
        E, G in Pa (> 0).
    density : float
        kg/m**3 (> 0).
    loads : array_like, (num_nodes, 6)
        Nodal forces (N) and moments (N*m) (F_x, F_y, F_z, M_x, M_y, M_z), global frame.
    fixed_nodes : sequence of int
        Clamped nodes (all 6 DoF). Default (0,).

    Returns
    -------
    dict
        'displacements' (num_nodes, 6): u, v, w (m), θx, θy, θz (rad), global frame;
        'reactions' (num_nodes, 6): K u - f (N, N*m), global frame, zero at free nodes;
        'element_forces' (num_elements, 12): end forces and moments on each element, element
        frame (node a F, M; node b F, M); 'section_loads' (num_elements, 6): mean internal
        (N, V_y, V_z, M_x, M_y, M_z), element frame, tension positive; 'element_mass'
        (num_elements,), 'mass' (kg) and 'cg' (3,), m.

    Local axes: x along the element, y = (-m, l, 0)/sqrt(l² + m²), z = x × y (see
    lpc_mdo.components.structures.beam).
    """
    nodes, loads, fixed = _frame_arguments(nodes, loads, fixed_nodes)
    ne = nodes.shape[0] - 1
    values = {
        "nodes": nodes,
        "area": _per_element("area", area, ne, "m**2"),
        "bending_inertia_vertical": _per_element(
            "bending_inertia_vertical", bending_inertia_vertical, ne, "m**4"
        ),
        "bending_inertia_inplane": _per_element(
            "bending_inertia_inplane", bending_inertia_inplane, ne, "m**4"
        ),
        "torsion_constant": _per_element("torsion_constant", torsion_constant, ne, "m**4"),
        "youngs_modulus": _scalar("youngs_modulus", youngs_modulus, "Pa"),
        "shear_modulus": _scalar("shear_modulus", shear_modulus, "Pa"),
        "density": _scalar("density", density, "kg/m**3"),
        "node_forces": loads[:, :3],
        "node_moments": loads[:, 3:],
    }
    prob = _run(BeamGroup(num_nodes=nodes.shape[0], fixed_nodes=fixed), values)
    return _frame_results(prob)


def box_beam(
    nodes,
    width,
    height,
    top_skin_thickness,
    bottom_skin_thickness,
    web_thickness,
    youngs_modulus,
    shear_modulus,
    density,
    loads,
    fixed_nodes=(0,),
    *,
    poisson_ratio=0.33,
    front_spar_thickness=None,
    rear_spar_thickness=None,
    top_skin_radius=None,
    bottom_skin_radius=None,
    torsion_formula="polar",
    web_points="one",
    flat_plate_coefficient=4.0,
):
    """
    Solve a box beam of consecutive nodes from box dimensions and wall thicknesses.

    The same model as BoxBeamGroup: box section (docs theory/structures 'Box section'), frame
    FEM, stresses at five points per element (docs theory/structures 'Stress') and skin-panel
    buckling (paper eq. 18).

    Parameters
    ----------
    nodes, youngs_modulus, shear_modulus, density, loads, fixed_nodes
        As in :func:`beam`.
    width, height : float or array_like (num_elements,)
        Outer box width (spar to spar) and height, m (> 0).
    top_skin_thickness, bottom_skin_thickness : float or array_like (num_elements,)
        Skin thicknesses, m (> 0).
    web_thickness : float, array_like (num_elements,) or None
        Spar web thickness, m (> 0), used for both spars; None if ``front_spar_thickness`` and
        ``rear_spar_thickness`` are given (the beam then uses their mean, as the reference).
    poisson_ratio : float
        ν in (-1, 0.5); default 0.33.
    front_spar_thickness, rear_spar_thickness : float, array_like (num_elements,) or None
    top_skin_radius, bottom_skin_radius : float, array_like (num_elements,) or None
        Radii of curvature of the skin panels, m (> 0): curved panels (paper eq. 18). Both None
        (default): flat simply supported panels with k = ``flat_plate_coefficient``.
    torsion_formula : str
        'polar' (default, J = I_y + I_z as the reference model) or 'bredt'.
    web_points : str
        'one' (default, five stress points) or 'both' (a sixth point on the other web).
    flat_plate_coefficient : float
        k of the flat panels (default 4).

    Returns
    -------
    dict
        The entries of :func:`beam`, plus 'area', 'bending_inertia_vertical',
        'bending_inertia_inplane', 'torsion_constant', 'web_thickness' (num_elements,);
        'von_mises_stress' (num_elements, 5), Pa; 'top_skin_stress', 'bottom_skin_stress'
        (tension positive), 'top_skin_critical_stress', 'bottom_skin_critical_stress' (Pa) and
        'top_skin_buckling_ratio', 'bottom_skin_buckling_ratio' (compressive stress over the
        critical stress; <= 1 is safe), each (num_elements,).
    """
    nodes, loads, fixed = _frame_arguments(nodes, loads, fixed_nodes)
    n = nodes.shape[0]
    ne = n - 1
    if web_thickness is None:
        if front_spar_thickness is None or rear_spar_thickness is None:
            raise ValueError(
                "'web_thickness' is None: give both 'front_spar_thickness' and "
                "'rear_spar_thickness'."
            )
        front = _per_element("front_spar_thickness", front_spar_thickness, ne, "m")
        rear = _per_element("rear_spar_thickness", rear_spar_thickness, ne, "m")
    else:
        if front_spar_thickness is not None or rear_spar_thickness is not None:
            raise ValueError(
                "give either 'web_thickness' or 'front_spar_thickness' and "
                "'rear_spar_thickness', not both."
            )
        front = rear = _per_element("web_thickness", web_thickness, ne, "m")
    if (top_skin_radius is None) != (bottom_skin_radius is None):
        raise ValueError(
            "give both 'top_skin_radius' and 'bottom_skin_radius' (curved panels) "
            "or neither (flat panels)."
        )
    if torsion_formula not in TORSION_FORMULAS:
        raise ValueError(f"'torsion_formula' = {torsion_formula!r}; allowed {TORSION_FORMULAS}.")
    if web_points not in ("one", "both"):
        raise ValueError(f"'web_points' = {web_points!r}; allowed ('one', 'both').")
    curved = top_skin_radius is not None
    values = {
        "nodes": nodes,
        "box_width": _per_element("width", width, ne, "m"),
        "box_height": _per_element("height", height, ne, "m"),
        "top_skin_thickness": _per_element("top_skin_thickness", top_skin_thickness, ne, "m"),
        "bottom_skin_thickness": _per_element(
            "bottom_skin_thickness", bottom_skin_thickness, ne, "m"
        ),
        "front_spar_thickness": front,
        "rear_spar_thickness": rear,
        "youngs_modulus": _scalar("youngs_modulus", youngs_modulus, "Pa"),
        "shear_modulus": _scalar("shear_modulus", shear_modulus, "Pa"),
        "density": _scalar("density", density, "kg/m**3"),
        "poisson_ratio": _scalar("poisson_ratio", poisson_ratio, "", low=-1.0, high=0.5),
        "node_forces": loads[:, :3],
        "node_moments": loads[:, 3:],
    }
    if curved:
        values["top_skin_radius"] = _per_element("top_skin_radius", top_skin_radius, ne, "m")
        values["bottom_skin_radius"] = _per_element(
            "bottom_skin_radius", bottom_skin_radius, ne, "m"
        )
    group = BoxBeamGroup(
        num_nodes=n,
        fixed_nodes=fixed,
        torsion_formula=torsion_formula,
        web_points=web_points,
        panel="curved" if curved else "flat",
        flat_plate_coefficient=_scalar("flat_plate_coefficient", flat_plate_coefficient, ""),
    )
    prob = _run(group, values)
    out = _frame_results(prob)
    for name in (
        "area",
        "bending_inertia_vertical",
        "bending_inertia_inplane",
        "torsion_constant",
        "web_thickness",
        "von_mises_stress",
        "top_skin_stress",
        "bottom_skin_stress",
        "top_skin_critical_stress",
        "bottom_skin_critical_stress",
        "top_skin_buckling_ratio",
        "bottom_skin_buckling_ratio",
    ):
        out[name] = prob.get_val(name).copy()
    return out
