"""Beam and wing-box assemblies (frame FEM, box section, stress, buckling) and plain wrappers."""

import numpy as np
import openmdao.api as om

from lpc_mdo.checks import check_integer, check_number, check_range, check_shape
from lpc_mdo.components.ks import KSComp
from lpc_mdo.components.structures.beam import (
    BeamDisplacementComp,
    BeamForcesComp,
    BeamMassComp,
)
from lpc_mdo.components.structures.box_section import TORSION_FORMULAS, BoxSectionComp
from lpc_mdo.components.structures.buckling import PANEL_MODELS, PanelBucklingComp
from lpc_mdo.components.structures.load_transfer import LoadTransferComp
from lpc_mdo.components.structures.stress import BoxStressComp
from lpc_mdo.mpi import serial_comm


def _declare_frame_options(group):
    group.options.declare('num_nodes', types=int, lower=2, desc='Number of beam nodes (>= 2)')
    group.options.declare('connectivity', default=None, allow_none=True,
                          desc='Element node pairs (num_elements, 2); None: consecutive nodes')
    group.options.declare('fixed_nodes', default=(0,), types=(tuple, list),
                          desc='Clamped nodes (all 6 DoF fixed)')
    group.options.declare('fixed_dofs', default=(), types=(tuple, list),
                          desc='Further constrained (node, dof) pairs, dof 0..5')


def _add_frame(group, with_mass=True):
    """Add mass, stiffness solve and load recovery, everything promoted."""
    opts = {'num_nodes': group.options['num_nodes'],
            'connectivity': group.options['connectivity']}
    if with_mass:
        group.add_subsystem('mass', BeamMassComp(**opts), promotes=['*'])
    group.add_subsystem('fem', BeamDisplacementComp(
        fixed_nodes=tuple(group.options['fixed_nodes']),
        fixed_dofs=tuple(tuple(p) for p in group.options['fixed_dofs']), **opts), promotes=['*'])
    group.add_subsystem('internal_loads', BeamForcesComp(**opts), promotes=['*'])


class BeamGroup(om.Group):
    """
    Linear static Euler-Bernoulli space frame with given section properties (paper eq. 17).

    Subsystems, all promoted: ``mass`` (BeamMassComp: element masses, beam mass and cg),
    ``fem`` (BeamDisplacementComp: K u = f, sparse direct solve, implicit) and
    ``internal_loads`` (BeamForcesComp: element end forces, section resultants, reactions).
    The implicit ``fem`` solves itself and provides its own linear solve (LU of K), so the
    group runs once and needs no Newton or DirectSolver; totals (fwd or adjoint) cost one
    triangular solve pair per right-hand side.

    Inputs (promoted)
    -----------------
    nodes : (num_nodes, 3), m; area : (num_elements,), m**2;
    bending_inertia_vertical, bending_inertia_inplane, torsion_constant : (num_elements,), m**4;
    youngs_modulus, shear_modulus : scalar, Pa; density : scalar, kg/m**3;
    node_forces : (num_nodes, 3), N; node_moments : (num_nodes, 3), N*m (global frame).

    Outputs (promoted)
    ------------------
    displacements : (num_nodes, 3), m; rotations : (num_nodes, 3), rad;
    element_end_forces, element_end_moments : (num_elements, 2, 3), N and N*m (element frame);
    section_forces : (num_elements, 3), N; section_moments : (num_elements, 3), N*m;
    reaction_forces : (num_nodes, 3), N; reaction_moments : (num_nodes, 3), N*m;
    element_mass : (num_elements,), kg; beam_mass : scalar, kg; beam_cg : (3,), m.

    Options
    -------
    num_nodes : int
    connectivity : array (num_elements, 2) of int or None (consecutive nodes)
    fixed_nodes : tuple of int, default (0,) (clamped root)
    fixed_dofs : tuple of (node, dof) pairs, default ()
    """

    def initialize(self):
        _declare_frame_options(self)

    def setup(self):
        _add_frame(self)


class BoxBeamGroup(om.Group):
    """
    Wing-box beam: box section, frame FEM, stress recovery and skin-panel buckling.

    reference/models_structures_motor_vehicle.md §6 and paper eqs. 17-18. Subsystems, all
    promoted, in execution order:

    - ``section`` (BoxSectionComp): A, I_y, I_z, J and the mean web thickness from the box
      width and height and the four wall thicknesses (per element = per bay);
    - ``mass`` (BeamMassComp): element masses, half-wing mass ``beam_mass`` and ``beam_cg``;
    - ``load_transfer`` (LoadTransferComp, only if ``num_aero_points`` > 0 or
      ``num_point_masses`` > 0): aerodynamic point forces, the beam's own weight and point
      masses at the load factor onto ``node_forces``/``node_moments``; otherwise those are
      inputs;
    - ``fem``, ``internal_loads``: as in BeamGroup;
    - ``stress`` (BoxStressComp): von Mises stress at 5 points per element, skin stresses;
    - ``buckling`` (PanelBucklingComp): critical stresses and buckling ratios of the top and
      bottom skin panels (curved panels, paper eq. 18, by default).

    - with ``ks_rho`` set: ``stress_ks`` (KSComp, paper eq. 7) aggregating every
      ``stress_ratio`` into ``stress_ratio_ks``, and ``top_buckling_ks``/``bottom_buckling_ks``
      aggregating the buckling ratios of the first ``num_buckling_bays`` bays into
      ``top_skin_buckling_ratio_ks``/``bottom_skin_buckling_ratio_ks``.

    The constraints of the paper's structural subproblem are ``top_skin_buckling_ratio`` and
    ``bottom_skin_buckling_ratio`` <= 1 without the tip bay, ``stress_ratio`` <= 1 and the
    vertical displacement (or their KS aggregates).

    Inputs (promoted)
    -----------------
    nodes : (num_nodes, 3), m; box_width, box_height : (num_elements,), m;
    top_skin_thickness, bottom_skin_thickness, front_spar_thickness, rear_spar_thickness :
    (num_elements,), m; top_skin_radius, bottom_skin_radius : (num_elements,), m (curved panels);
    youngs_modulus, shear_modulus : Pa; density : kg/m**3; poisson_ratio : -;
    node_forces, node_moments : (num_nodes, 3), N, N*m (without load transfer), or aero_points,
    aero_forces : (num_aero_points, 3), m, N; point_masses : (k,), kg;
    point_mass_locations : (k, 3), m; load_factor; pitch, roll : rad (with load transfer).

    Outputs (promoted)
    ------------------
    Those of BeamGroup, plus area, bending_inertia_vertical, bending_inertia_inplane,
    torsion_constant, web_thickness (num_elements,); von_mises_stress (num_elements, 5), Pa;
    top_skin_stress, bottom_skin_stress, top_skin_critical_stress,
    bottom_skin_critical_stress (num_elements,), Pa; top_skin_buckling_ratio,
    bottom_skin_buckling_ratio (num_elements,).

    Options
    -------
    num_nodes : int; fixed_nodes, fixed_dofs : as in BeamGroup (the chain of consecutive nodes
    is the only connectivity here);
    torsion_formula : 'polar' (default, reference model) or 'bredt';
    web_points : 'one' (default, five points) or 'both';
    panel : 'curved' (default) or 'flat'; flat_plate_coefficient : float (default 4);
    num_aero_points : int (default 0); num_point_masses : int (default 0);
    include_weight : bool (default True; with load transfer); span_axis : int (default 1);
    ks_rho : float or None (default None: no aggregation); num_buckling_bays : int or None
    (bays from the root in the buckling aggregate; default None = all but the tip bay).
    """

    def initialize(self):
        _declare_frame_options(self)
        self.options.declare('torsion_formula', default='polar', values=TORSION_FORMULAS,
                             desc="Torsion constant and torsional shear: 'polar' or 'bredt'")
        self.options.declare('web_points', default='one', values=('one', 'both'),
                             desc="Stress points on the webs: 'one' (five points) or 'both'")
        self.options.declare('panel', default='curved', values=PANEL_MODELS,
                             desc="Skin-panel buckling model: 'curved' (eq. 18) or 'flat'")
        self.options.declare('flat_plate_coefficient', default=4.0, types=(int, float),
                             desc='Buckling coefficient k of flat panels')
        self.options.declare('num_aero_points', default=0, types=int, lower=0,
                             desc='Aerodynamic force points for the load transfer (0: nodal '
                                  'loads are inputs)')
        self.options.declare('num_point_masses', default=0, types=int, lower=0,
                             desc='Point masses carried by the wing box (load transfer)')
        self.options.declare('include_weight', default=True, types=bool,
                             desc="With load transfer: add the box's own weight at the load "
                                  'factor')
        self.options.declare('span_axis', default=1, values=(0, 1, 2),
                             desc='Span coordinate of the load transfer')
        self.options.declare('ks_rho', default=None, types=(int, float), allow_none=True,
                             desc='KS parameter of the stress and buckling aggregates (None: '
                                  'no aggregation)')
        self.options.declare('num_buckling_bays', default=None, types=int, allow_none=True,
                             desc='Bays from the root in the buckling aggregate (None: all but '
                                  'the tip bay, as the paper)')

    def setup(self):
        if self.options['connectivity'] is not None:
            raise ValueError(f"{self.msginfo}: option 'connectivity' must be None; the box "
                             "beam is a chain of consecutive nodes.")
        n = self.options['num_nodes']
        ne = n - 1
        formula = self.options['torsion_formula']
        self.add_subsystem('section', BoxSectionComp(num_elements=ne, torsion_formula=formula),
                           promotes=['*'])
        self.add_subsystem('mass', BeamMassComp(num_nodes=n), promotes=['*'])
        if self.options['num_aero_points'] or self.options['num_point_masses']:
            self.add_subsystem('load_transfer', LoadTransferComp(
                num_nodes=n, num_points=self.options['num_aero_points'],
                num_point_masses=self.options['num_point_masses'],
                include_weight=self.options['include_weight'],
                span_axis=self.options['span_axis']), promotes=['*'])
        _add_frame(self, with_mass=False)
        self.add_subsystem('stress', BoxStressComp(num_elements=ne, torsion_formula=formula,
                                                   web_points=self.options['web_points']),
                           promotes=['*'])
        self.add_subsystem('buckling', PanelBucklingComp(
            num_elements=ne, panel=self.options['panel'],
            flat_plate_coefficient=self.options['flat_plate_coefficient']), promotes=['*'])
        if self.options['ks_rho'] is not None:
            self._add_aggregates(ne)

    def _add_aggregates(self, ne):
        rho = self.options['ks_rho']
        nb = self.options['num_buckling_bays']
        nb = max(ne - 1, 1) if nb is None else nb
        check_integer("num_buckling_bays", nb, lower=1, upper=ne,
                      allowed=f"in [1, {ne}] (num_nodes - 1)", where=self.msginfo)
        npts = 5 if self.options['web_points'] == 'one' else 6
        self.add_subsystem('stress_ks', KSComp(width=ne * npts, rho=rho),
                           promotes_outputs=[('KS', 'stress_ratio_ks')])
        self.connect('stress_ratio', 'stress_ks.g',
                     src_indices=np.arange(ne * npts), flat_src_indices=True)
        for skin in ('top', 'bottom'):
            self.add_subsystem(f'{skin}_buckling_ks', KSComp(width=nb, rho=rho),
                               promotes_outputs=[('KS', f'{skin}_skin_buckling_ratio_ks')])
            self.connect(f'{skin}_skin_buckling_ratio', f'{skin}_buckling_ks.g',
                         src_indices=np.arange(nb), flat_src_indices=True)


# ------------------------------------------------------------------------------------------------
# Plain wrappers


def _array(name, value, shape=None, positive=False, units=''):
    if shape is not None:
        check_shape(name, value, shape)
    arr = check_range(name, value, lower=0.0 if positive else None, lower_open=True,
                      units=units or None)
    return np.asarray(arr, dtype=float)


def _per_element(name, value, num_elements, units):
    arr = _array(name, value, positive=True, units=units)
    if arr.ndim == 0:
        return np.full(num_elements, float(arr))
    if arr.shape != (num_elements,):
        raise ValueError(f"'{name}' must be a scalar or have shape ({num_elements},) (one value "
                         f"per element), got shape {arr.shape}.")
    return arr


def _scalar(name, value, units, low=0.0, high=np.inf):
    return check_number(name, value, lower=low, upper=None if np.isinf(high) else high,
                        lower_open=True, upper_open=True, units=units or None)


def _frame_arguments(nodes, loads, fixed_nodes):
    nodes = _array('nodes', nodes)
    if nodes.ndim != 2 or nodes.shape[1] != 3 or nodes.shape[0] < 2:
        raise ValueError(f"'nodes' must have shape (num_nodes >= 2, 3), got {nodes.shape}.")
    n = nodes.shape[0]
    loads = _array('loads', loads, shape=(n, 6))
    fixed = tuple(fixed_nodes)
    if not fixed or any(not isinstance(i, (int, np.integer)) or not 0 <= i < n for i in fixed):
        raise ValueError(f"'fixed_nodes' = {fixed_nodes!r} must be a non-empty sequence of node "
                         f"indices in [0, {n - 1}].")
    return nodes, loads, tuple(int(i) for i in fixed)


def _run(group, values):
    prob = om.Problem(reports=False, comm=serial_comm())
    prob.model.add_subsystem('beam', group, promotes=['*'])
    prob.setup()
    for name, val in values.items():
        prob.set_val(name, val)
    prob.run_model()
    return prob


def _frame_results(prob):
    ne = prob.get_val('section_forces').shape[0]
    ends = np.concatenate([prob.get_val('element_end_forces'),
                           prob.get_val('element_end_moments')], axis=2)  # (ne, 2, 6)
    return {
        'displacements': np.hstack([prob.get_val('displacements'), prob.get_val('rotations')]),
        'reactions': np.hstack([prob.get_val('reaction_forces'),
                                prob.get_val('reaction_moments')]),
        'element_forces': ends.reshape(ne, 12),
        'section_loads': np.hstack([prob.get_val('section_forces'),
                                    prob.get_val('section_moments')]),
        'element_mass': prob.get_val('element_mass').copy(),
        'mass': float(prob.get_val('beam_mass')[0]),
        'cg': prob.get_val('beam_cg').copy(),
    }


def beam(nodes, area, bending_inertia_vertical, bending_inertia_inplane, torsion_constant,
         youngs_modulus, shear_modulus, density, loads, fixed_nodes=(0,)):
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
        'nodes': nodes,
        'area': _per_element('area', area, ne, 'm**2'),
        'bending_inertia_vertical': _per_element('bending_inertia_vertical',
                                                 bending_inertia_vertical, ne, 'm**4'),
        'bending_inertia_inplane': _per_element('bending_inertia_inplane',
                                                bending_inertia_inplane, ne, 'm**4'),
        'torsion_constant': _per_element('torsion_constant', torsion_constant, ne, 'm**4'),
        'youngs_modulus': _scalar('youngs_modulus', youngs_modulus, 'Pa'),
        'shear_modulus': _scalar('shear_modulus', shear_modulus, 'Pa'),
        'density': _scalar('density', density, 'kg/m**3'),
        'node_forces': loads[:, :3],
        'node_moments': loads[:, 3:],
    }
    prob = _run(BeamGroup(num_nodes=nodes.shape[0], fixed_nodes=fixed), values)
    return _frame_results(prob)


def box_beam(nodes, width, height, top_skin_thickness, bottom_skin_thickness, web_thickness,
             youngs_modulus, shear_modulus, density, loads, fixed_nodes=(0,), *,
             poisson_ratio=0.33, front_spar_thickness=None, rear_spar_thickness=None,
             top_skin_radius=None, bottom_skin_radius=None, torsion_formula='polar',
             web_points='one', flat_plate_coefficient=4.0):
    """
    Solve a box beam of consecutive nodes from box dimensions and wall thicknesses.

    The same model as BoxBeamGroup: box section (reference page §6.2), frame FEM, stresses at
    five points per element (§6.4) and skin-panel buckling (paper eq. 18).

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
            raise ValueError("'web_thickness' is None: give both 'front_spar_thickness' and "
                             "'rear_spar_thickness'.")
        front = _per_element('front_spar_thickness', front_spar_thickness, ne, 'm')
        rear = _per_element('rear_spar_thickness', rear_spar_thickness, ne, 'm')
    else:
        if front_spar_thickness is not None or rear_spar_thickness is not None:
            raise ValueError("give either 'web_thickness' or 'front_spar_thickness' and "
                             "'rear_spar_thickness', not both.")
        front = rear = _per_element('web_thickness', web_thickness, ne, 'm')
    if (top_skin_radius is None) != (bottom_skin_radius is None):
        raise ValueError("give both 'top_skin_radius' and 'bottom_skin_radius' (curved panels) "
                         "or neither (flat panels).")
    if torsion_formula not in TORSION_FORMULAS:
        raise ValueError(f"'torsion_formula' = {torsion_formula!r}; allowed {TORSION_FORMULAS}.")
    if web_points not in ('one', 'both'):
        raise ValueError(f"'web_points' = {web_points!r}; allowed ('one', 'both').")
    curved = top_skin_radius is not None
    values = {
        'nodes': nodes,
        'box_width': _per_element('width', width, ne, 'm'),
        'box_height': _per_element('height', height, ne, 'm'),
        'top_skin_thickness': _per_element('top_skin_thickness', top_skin_thickness, ne, 'm'),
        'bottom_skin_thickness': _per_element('bottom_skin_thickness', bottom_skin_thickness,
                                              ne, 'm'),
        'front_spar_thickness': front,
        'rear_spar_thickness': rear,
        'youngs_modulus': _scalar('youngs_modulus', youngs_modulus, 'Pa'),
        'shear_modulus': _scalar('shear_modulus', shear_modulus, 'Pa'),
        'density': _scalar('density', density, 'kg/m**3'),
        'poisson_ratio': _scalar('poisson_ratio', poisson_ratio, '', low=-1.0, high=0.5),
        'node_forces': loads[:, :3],
        'node_moments': loads[:, 3:],
    }
    if curved:
        values['top_skin_radius'] = _per_element('top_skin_radius', top_skin_radius, ne, 'm')
        values['bottom_skin_radius'] = _per_element('bottom_skin_radius', bottom_skin_radius,
                                                    ne, 'm')
    group = BoxBeamGroup(num_nodes=n, fixed_nodes=fixed, torsion_formula=torsion_formula,
                         web_points=web_points, panel='curved' if curved else 'flat',
                         flat_plate_coefficient=_scalar('flat_plate_coefficient',
                                                        flat_plate_coefficient, ''))
    prob = _run(group, values)
    out = _frame_results(prob)
    for name in ('area', 'bending_inertia_vertical', 'bending_inertia_inplane',
                 'torsion_constant', 'web_thickness', 'von_mises_stress', 'top_skin_stress',
                 'bottom_skin_stress', 'top_skin_critical_stress', 'bottom_skin_critical_stress',
                 'top_skin_buckling_ratio', 'bottom_skin_buckling_ratio'):
        out[name] = prob.get_val(name).copy()
    return out


__all__ = ['BeamGroup', 'BoxBeamGroup', 'beam', 'box_beam']
