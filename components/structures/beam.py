"""Euler-Bernoulli space-frame finite elements: stiffness solve K u = f, load recovery and mass.

The element is the 12-DoF frame element of docs theory/structures 'Frame element' (aframe),
assembled and solved as in docs theory/structures 'Assembly and solution'; the residual form R = K u
- f is paper eq. 17.

Frames and sign conventions
---------------------------
- Global frame: the frame of the node coordinates (lpc_mdo: body frame, x forward, y right,
  z down). Each node has 6 DoF, translations (u, v, w) and small rotations (θx, θy, θz) about
  the global axes; they are the outputs ``displacements`` and ``rotations``.
- Element frame (docs theory/structures 'Frame element'): local x along the element (node a to node
  b); with direction cosines (l, m, n) and D = sqrt(l² + m²), local y = (-m, l, 0)/D (horizontal)
  and
  local z = (-l n, -m n, D²)/D, whose global z component is >= 0. For a wing along +y in the
  body frame, local y points aft and local z down. A vertical element (D = 0) uses
  λ = [[0, 0, s], [0, 1, 0], [-s, 0, 0]], s = sign(n).
- Element end forces f = K_local T u_e are the forces and moments the nodes exert on the element,
  in the element frame (12 entries: node a forces, node a moments, node b forces, node b moments).
- Section resultants are the internal forces on the positive (node b) face, averaged over the
  element: N = (f_b - f_a)/2 for each of the 6 components, i.e. (axial force N, shear V_y, shear
  V_z, torque M_x, bending moments M_y, M_z) with tension and the right-hand rule positive. This
  is the negative of the public aframe code's (f[0:6] - f[6:12])/2, so stresses come out with the
  usual signs (tension positive); their magnitudes, and so von Mises stresses, are the same.

Bending inertias: ``bending_inertia_vertical`` I_y acts about local y, i.e. bending in the local
x-z plane (vertical bending of a wing); ``bending_inertia_inplane`` I_z acts about local z
(chord-wise, in-plane bending).
"""

import numpy as np
import openmdao.api as om
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from lpc_mdo.core.checks import check_range

# Complex step used inside linearize/compute_partials for the node-coordinate partials of the
# element matrices (exact to machine precision; see BeamDisplacementComp).
_CS_STEP = 1e-30

# Default material (aluminium, docs theory/structures 'Material, mesh and load transfer') and
# section values shared by every component that promotes the same input names, so their defaults
# agree.
DEFAULT_YOUNGS_MODULUS = 69.0e9
DEFAULT_SHEAR_MODULUS = 26.0e9
DEFAULT_DENSITY = 2700.0

_SECTION_INPUTS = (
    ("area", "m**2", "cross-section area A"),
    (
        "bending_inertia_vertical",
        "m**4",
        "second moment of area I_y about local y (vertical bending)",
    ),
    (
        "bending_inertia_inplane",
        "m**4",
        "second moment of area I_z about local z (in-plane, chord-wise bending)",
    ),
    ("torsion_constant", "m**4", "torsion constant J"),
)


def default_nodes(num_nodes):
    """Return straight default node coordinates (num_nodes, 3): 1 m apart along +y."""
    nodes = np.zeros((num_nodes, 3))
    nodes[:, 1] = np.arange(num_nodes, dtype=float)
    return nodes


def chain_connectivity(num_nodes):
    """Return the element connectivity (num_nodes - 1, 2) of a chain of consecutive nodes."""
    return np.column_stack([np.arange(num_nodes - 1), np.arange(1, num_nodes)])


def check_connectivity(connectivity, num_nodes, owner="connectivity"):
    """Validate and return an element connectivity array (num_elements, 2) of node indices."""
    if connectivity is None:
        return chain_connectivity(num_nodes)
    conn = np.asarray(connectivity)
    if conn.ndim != 2 or conn.shape[1] != 2 or conn.shape[0] < 1:
        raise ValueError(f"{owner} must have shape (num_elements, 2), got shape {conn.shape}.")
    if not np.issubdtype(conn.dtype, np.integer):
        raise ValueError(f"{owner} must hold integer node indices, got dtype {conn.dtype}.")
    if conn.min() < 0 or conn.max() >= num_nodes:
        raise ValueError(
            f"{owner} holds node indices in [{conn.min()}, {conn.max()}]; allowed "
            f"range is [0, {num_nodes - 1}] (num_nodes = {num_nodes})."
        )
    if np.any(conn[:, 0] == conn[:, 1]):
        bad = np.flatnonzero(conn[:, 0] == conn[:, 1])
        raise ValueError(f"{owner}: elements {bad.tolist()} join a node to itself.")
    return conn.astype(int)


def _lengths(start, end):
    d = end - start
    return np.sqrt(np.sum(d * d, axis=-1))


#: Names of the four section properties as arguments of the element functions (the order of
#: _SECTION_INPUTS: A, I_y, I_z, J).
_PROP_ARGS = ("area", "inertia_v", "inertia_i", "torsion")


def element_frames(start, end):
    """
    Return element lengths and rotation matrices (docs theory/structures 'Frame element').

    Parameters
    ----------
    start, end : ndarray, (num_elements, 3)
        End-node coordinates (real or complex).

    Returns
    -------
    length : ndarray, (num_elements,)
    lam : ndarray, (num_elements, 3, 3)
        Rows are the local x, y, z axes in global components.
    """
    d = end - start
    length = np.sqrt(np.sum(d * d, axis=-1))
    e = d / length[:, np.newaxis]
    cx, cy, cz = e[:, 0], e[:, 1], e[:, 2]  # direction cosines (l, m, n)
    dxy = np.sqrt(cx * cx + cy * cy)
    vertical = dxy.real < 1e-9
    dsafe = np.where(vertical, 1.0, dxy)
    lam = np.zeros((d.shape[0], 3, 3), dtype=e.dtype)
    lam[:, 0, :] = e
    lam[:, 1, 0] = -cy / dsafe
    lam[:, 1, 1] = cx / dsafe
    lam[:, 2, 0] = -cx * cz / dsafe
    lam[:, 2, 1] = -cy * cz / dsafe
    lam[:, 2, 2] = dxy
    if np.any(vertical):
        s = np.sign(cz.real[vertical])
        lam_v = np.zeros((s.size, 3, 3))
        lam_v[:, 0, 2] = s
        lam_v[:, 1, 1] = 1.0
        lam_v[:, 2, 0] = -s
        lam[vertical] = lam_v
    return length, lam


# (row, col, kind, coefficient, power of L): upper triangle of the local stiffness matrix
# (docs theory/structures 'Frame element'). kind: A -> E A, J -> G J, Y -> E I_y, Z -> E I_z; entry
# = c kind / L**p.
_K_ENTRIES = (
    (0, 0, "A", 1.0, 1),
    (6, 6, "A", 1.0, 1),
    (0, 6, "A", -1.0, 1),
    (1, 1, "Z", 12.0, 3),
    (7, 7, "Z", 12.0, 3),
    (1, 7, "Z", -12.0, 3),
    (2, 2, "Y", 12.0, 3),
    (8, 8, "Y", 12.0, 3),
    (2, 8, "Y", -12.0, 3),
    (3, 3, "J", 1.0, 1),
    (9, 9, "J", 1.0, 1),
    (3, 9, "J", -1.0, 1),
    (4, 4, "Y", 4.0, 1),
    (10, 10, "Y", 4.0, 1),
    (4, 10, "Y", 2.0, 1),
    (5, 5, "Z", 4.0, 1),
    (11, 11, "Z", 4.0, 1),
    (5, 11, "Z", 2.0, 1),
    (1, 5, "Z", 6.0, 2),
    (1, 11, "Z", 6.0, 2),
    (5, 7, "Z", -6.0, 2),
    (7, 11, "Z", -6.0, 2),
    (2, 4, "Y", -6.0, 2),
    (2, 10, "Y", -6.0, 2),
    (4, 8, "Y", 6.0, 2),
    (8, 10, "Y", 6.0, 2),
)


def local_stiffness(
    length, area, inertia_vertical, inertia_inplane, torsion_constant, youngs_modulus, shear_modulus
):
    """
    Return the local 12 x 12 element stiffness matrices (num_elements, 12, 12).

    See docs theory/structures 'Frame element'.

    The matrix is linear in each of E A, G J, E I_y and E I_z, so passing unit values of one
    property (and zeros for the others) gives its derivative.
    """
    rigidity = {
        "A": youngs_modulus * area,
        "J": shear_modulus * torsion_constant,
        "Y": youngs_modulus * inertia_vertical,
        "Z": youngs_modulus * inertia_inplane,
    }
    dtype = np.result_type(length, *rigidity.values())
    k = np.zeros((np.size(length), 12, 12), dtype=dtype)
    for row, col, kind, coef, power in _K_ENTRIES:
        val = coef * rigidity[kind] / length**power
        k[:, row, col] = val
        k[:, col, row] = val
    return k


def global_stiffness(lam, k_local):
    """Return T^T K_local T (num_elements, 12, 12) with T = blockdiag(λ, λ, λ, λ)."""
    ne = lam.shape[0]
    k5 = k_local.reshape(ne, 4, 3, 4, 3)
    return np.einsum("epi,eapbq,eqj->eaibj", lam, k5, lam).reshape(ne, 12, 12)


def to_local(lam, u_e):
    """Rotate element DoF vectors (num_elements, 12[, k]) from global to element axes (T u)."""
    ne = lam.shape[0]
    u4 = u_e.reshape(ne, 4, 3, -1)
    return np.einsum("epi,eaik->eapk", lam, u4).reshape(u_e.shape)


def to_global(lam, f_e):
    """Rotate element vectors (num_elements, 12[, k]) from element to global axes (T^T f)."""
    ne = lam.shape[0]
    f4 = f_e.reshape(ne, 4, 3, -1)
    return np.einsum("epi,eapk->eaik", lam, f4).reshape(f_e.shape)


class _SparseSum:
    """
    Unique sparse entries of a partial Jacobian built from many (row, col, value) contributions.

    Entries with a negative row or column index are dropped. ``sum`` adds the contributions that
    land on the same (row, col) (OpenMDAO needs unique rows/cols), and ``split`` cuts the entries
    into per-variable (of, wrt) blocks given the variables' sizes in a flat layout.
    """

    def __init__(self, rows, cols, num_cols):
        rows, cols = np.broadcast_arrays(rows, cols)
        self.shape = rows.shape
        self.keep = (rows >= 0) & (cols >= 0)
        key = rows[self.keep].astype(np.int64) * num_cols + cols[self.keep]
        uniq, self.inv = np.unique(key, return_inverse=True)
        self.size = uniq.size
        self.rows, self.cols = np.divmod(uniq, num_cols)

    def sum(self, values):
        vals = np.broadcast_to(values, self.shape)[self.keep]
        out = np.bincount(self.inv, weights=vals.real, minlength=self.size)
        if np.iscomplexobj(vals):
            out = out + 1j * np.bincount(self.inv, weights=vals.imag, minlength=self.size)
        return out

    def split(self, of_layout, wrt_layout):
        """Return {(of, wrt): (selection, local rows, local cols)} for the non-empty blocks."""
        blocks = {}
        r0 = 0
        for of, of_size in of_layout:
            c0 = 0
            for wrt, wrt_size in wrt_layout:
                sel = np.flatnonzero(
                    (self.rows >= r0)
                    & (self.rows < r0 + of_size)
                    & (self.cols >= c0)
                    & (self.cols < c0 + wrt_size)
                )
                if sel.size:
                    blocks[of, wrt] = (sel, self.rows[sel] - r0, self.cols[sel] - c0)
                c0 += wrt_size
            r0 += of_size
        return blocks


def _declare_blocks(comp, blocks, zero=()):
    """Declare the sparse blocks, dropping the (of, wrt) pairs listed in ``zero``."""
    for key in zero:
        blocks.pop(key, None)
    for (of, wrt), (_, rows, cols) in blocks.items():
        comp.declare_partials(of, wrt, rows=rows, cols=cols)


# (of, wrt) pairs that are identically zero although an element touches both: the axial
# stiffness E A acts on translations only, the torsional stiffness G J on rotations only, and the
# mean section moments (f_b - f_a)/2 (G J or E I times (θ_b - θ_a)/L) involve no translations.
_ZERO_FEM = (
    ("displacements", "torsion_constant"),
    ("displacements", "shear_modulus"),
    ("rotations", "area"),
)
_ZERO_FORCES = (
    ("element_end_forces", "torsion_constant"),
    ("element_end_forces", "shear_modulus"),
    ("element_end_moments", "area"),
    ("section_forces", "torsion_constant"),
    ("section_forces", "shear_modulus"),
    ("section_moments", "area"),
    ("section_moments", "displacements"),
    ("reaction_forces", "torsion_constant"),
    ("reaction_forces", "shear_modulus"),
    ("reaction_moments", "area"),
)


def _set_blocks(partials, blocks, values):
    for (of, wrt), (sel, _, _) in blocks.items():
        partials[of, wrt] = values[sel]


class _FrameMixin:
    """Options, inputs and element kinematics shared by the frame components."""

    def _declare_frame_options(self):
        self.options.declare("num_nodes", types=int, lower=2, desc="Number of beam nodes (>= 2)")
        self.options.declare(
            "connectivity",
            default=None,
            allow_none=True,
            desc="Element node pairs, array (num_elements, 2) of node indices; "
            "None (default): a chain of consecutive nodes",
        )

    def _setup_frame(self):
        n = self.options["num_nodes"]
        self._conn = check_connectivity(
            self.options["connectivity"], n, owner=f"{self.msginfo}: option 'connectivity'"
        )
        ne = self._conn.shape[0]
        # Global DoF of each element in the flat "layout" order [translations (3n), rotations
        # (3n)], i.e. the flat index into concatenate(displacements.ravel(), rotations.ravel()).
        node = np.repeat(self._conn, 6, axis=1)  # (ne, 12): a a a a a a b b b b b b
        k = np.tile(np.arange(6), 2)
        self._edofs = np.where(k < 3, 3 * node + k, 3 * n + 3 * node + k - 3)
        # Flat indices of the element end-node coordinates into nodes (n, 3).
        self._ecoords = np.concatenate(
            [3 * self._conn[:, :1] + np.arange(3), 3 * self._conn[:, 1:] + np.arange(3)], axis=1
        )
        return n, ne

    def _add_frame_inputs(self):
        n = self.options["num_nodes"]
        ne = self._conn.shape[0]
        self.add_input(
            "nodes",
            val=default_nodes(n),
            units="m",
            desc="node coordinates in the global (body) frame",
        )
        for name, units, desc in _SECTION_INPUTS:
            self.add_input(name, val=np.ones(ne), units=units, desc=f"{desc}, per element")
        self.add_input(
            "youngs_modulus", val=DEFAULT_YOUNGS_MODULUS, units="Pa", desc="Young's modulus E"
        )
        self.add_input(
            "shear_modulus", val=DEFAULT_SHEAR_MODULUS, units="Pa", desc="shear modulus G"
        )

    def _element_ends(self, nodes):
        return nodes[self._conn[:, 0]], nodes[self._conn[:, 1]]

    def _check_geometry(self, length, section=None):
        check_range(
            "element length (from input 'nodes')",
            length,
            lower=0.0,
            lower_open=True,
            units="m",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        if section is not None:
            for name, units, _ in _SECTION_INPUTS:
                check_range(
                    name,
                    section[name],
                    lower=0.0,
                    lower_open=True,
                    units=units,
                    error=om.AnalysisError,
                    where=self.msginfo,
                )

    def _element_stiffness(self, start, end, props, modulus, shear, frame="global"):
        """Element stiffness matrices (global or local frame) and the rotation matrices."""
        length, lam = element_frames(start, end)
        k_loc = local_stiffness(length, props[0], props[1], props[2], props[3], modulus, shear)
        if frame == "local":
            return k_loc, lam
        return global_stiffness(lam, k_loc), lam

    @staticmethod
    def _coordinate_blocks(start, end, func, **per_element):
        """
        Differentiate func(start, end, **per_element) by the 6 end-node coordinates (complex step).

        The result has the shape (num_elements, m, 6).

        func(start, end, **per_element) -> (num_elements, m) must be complex-safe and element-wise
        (row e of the result depends on row e of every argument). The node coordinates enter
        only through the element length and direction cosines of each element, so the 6
        perturbations, stacked along the element axis (the ``per_element`` arrays repeated with
        them), give the exact derivative of every element in one evaluation.
        """
        ne = start.shape[0]
        s = np.tile(start.real.astype(complex), (6, 1))
        e = np.tile(end.real.astype(complex), (6, 1))
        for k in range(6):
            rows = slice(k * ne, (k + 1) * ne)
            if k < 3:
                s[rows, k] += 1j * _CS_STEP
            else:
                e[rows, k - 3] += 1j * _CS_STEP
        tiled = {name: np.concatenate([value] * 6) for name, value in per_element.items()}
        values = func(s, e, **tiled).imag / _CS_STEP
        return np.stack(np.split(values, 6), axis=-1)


class BeamDisplacementComp(_FrameMixin, om.ImplicitComponent):
    """
    Static frame solve R = K u - f = 0 for the nodal displacements and rotations (paper eq. 17).

    K is assembled from the 12-DoF Euler-Bernoulli frame elements of docs theory/structures 'Frame
    element' with the direction-cosine transformation K_e = Tᵀ K_local T. The constrained DoF
    (clamped nodes,
    ``fixed_nodes``; single DoF, ``fixed_dofs``) are eliminated as in docs theory/structures
    'Assembly and solution': their rows and columns of K are replaced by the identity and their load
    entries by zero, so the residual of
    a free DoF is (K u)_free - f_free with the constrained columns dropped and the residual of a
    constrained DoF is its displacement.

    ``solve_nonlinear`` assembles K as a sparse matrix and factorizes it with SuperLU (a sparse
    direct solve; the problem is linear). A singular K (a mechanism, e.g. too few constraints, or
    zero stiffness) raises ``om.AnalysisError``. ``linearize`` gives dR/du = K_bc exactly and
    keeps its LU factors for ``solve_linear``, so the component solves its own linear systems
    (fwd and rev) and a parent group needs no DirectSolver. dR/d(section properties, E, G) are
    analytic (K is linear in E A, G J, E I_y, E I_z); dR/d(node coordinates) comes from a complex
    step on the per-element matrices inside ``linearize`` (vectorized over elements, exact to
    machine precision); the vertical-element branch of the transformation (D = 0) is treated as
    locally constant. All partials are sparse.

    Inputs
    ------
    nodes : float, (num_nodes, 3), m
        Node coordinates in the global (body) frame.
    area : float, (num_elements,), m**2
        Cross-section area A.
    bending_inertia_vertical : float, (num_elements,), m**4
        I_y, about local y (vertical bending of a wing).
    bending_inertia_inplane : float, (num_elements,), m**4
        I_z, about local z (in-plane bending).
    torsion_constant : float, (num_elements,), m**4
        Torsion constant J.
    youngs_modulus : float, scalar, Pa
        E.
    shear_modulus : float, scalar, Pa
        G.
    node_forces : float, (num_nodes, 3), N
        External nodal forces, global frame (loads on constrained DoF are taken by the support).
    node_moments : float, (num_nodes, 3), N*m
        External nodal moments, global frame.

    Outputs
    -------
    displacements : float, (num_nodes, 3), m
        Nodal translations (u, v, w), global frame; residual in N.
    rotations : float, (num_nodes, 3), rad
        Nodal small rotations (θx, θy, θz) about the global axes; residual in N*m.

    Options
    -------
    num_nodes : int
        Number of nodes (>= 2).
    connectivity : array (num_elements, 2) of int or None
        Element node pairs; None (default) for a chain of consecutive nodes.
    fixed_nodes : tuple of int
        Clamped nodes (all 6 DoF fixed). Default (0,): clamped root.
    fixed_dofs : tuple of (node, dof) pairs
        Further single constrained DoF, dof 0..5 = (u, v, w, θx, θy, θz); e.g. a symmetry plane
        y = 0 is ((0, 1), (0, 3), (0, 5)). Default ().
    """

    def initialize(self):
        self._declare_frame_options()
        self.options.declare(
            "fixed_nodes", default=(0,), types=(tuple, list), desc="Clamped nodes (all 6 DoF fixed)"
        )
        self.options.declare(
            "fixed_dofs",
            default=(),
            types=(tuple, list),
            desc="Further constrained (node, dof) pairs, dof 0..5 = "
            "(u, v, w, theta_x, theta_y, theta_z)",
        )
        self._lu = None

    def _fixed_mask(self, n):
        fixed = np.zeros(6 * n, dtype=bool)  # layout order
        pairs = [(node, dof) for node in self.options["fixed_nodes"] for dof in range(6)]
        pairs += [tuple(p) for p in self.options["fixed_dofs"]]
        for pair in pairs:
            if len(pair) != 2:
                raise ValueError(
                    f"{self.msginfo}: option 'fixed_dofs' entries must be (node, dof)"
                    f" pairs, got {pair!r}."
                )
            node, dof = pair
            if not (isinstance(node, (int, np.integer)) and 0 <= node < n):
                raise ValueError(
                    f"{self.msginfo}: constrained node {node!r} (options "
                    f"'fixed_nodes'/'fixed_dofs') is out of range; allowed "
                    f"[0, {n - 1}]."
                )
            if not (isinstance(dof, (int, np.integer)) and 0 <= dof < 6):
                raise ValueError(
                    f"{self.msginfo}: option 'fixed_dofs' has dof {dof!r} at node "
                    f"{node}; allowed 0..5 (u, v, w, theta_x, theta_y, theta_z)."
                )
            fixed[3 * node + dof if dof < 3 else 3 * n + 3 * node + dof - 3] = True
        if not fixed.any():
            raise ValueError(
                f"{self.msginfo}: options 'fixed_nodes' = "
                f"{self.options['fixed_nodes']!r} and 'fixed_dofs' = "
                f"{self.options['fixed_dofs']!r} constrain no DoF; the frame would be "
                "a mechanism (singular K). Clamp at least one node."
            )
        return fixed

    def setup(self):
        n, ne = self._setup_frame()
        size = 6 * n
        self._fixed = self._fixed_mask(n)
        self._free = ~self._fixed
        free_idx = self._free_idx = np.flatnonzero(self._free)
        fixed_idx = np.flatnonzero(self._fixed)

        self._add_frame_inputs()
        self.add_input(
            "node_forces",
            val=np.zeros((n, 3)),
            units="N",
            desc="external nodal forces, global frame",
        )
        self.add_input(
            "node_moments",
            val=np.zeros((n, 3)),
            units="N*m",
            desc="external nodal moments, global frame",
        )
        self.add_output(
            "displacements",
            val=np.zeros((n, 3)),
            units="m",
            res_units="N",
            desc="nodal translations (u, v, w), global frame",
        )
        self.add_output(
            "rotations",
            val=np.zeros((n, 3)),
            units="rad",
            res_units="N*m",
            desc="nodal small rotations about the global x, y, z axes",
        )

        res_layout = [("displacements", 3 * n), ("rotations", 3 * n)]
        free_rows = np.where(self._free[self._edofs], self._edofs, -1)  # (ne, 12)

        # Scatter of element vectors (ne, 12) to the global residual (layout order).
        self._scatter = sp.csr_matrix(
            (np.ones(12 * ne), (self._edofs.ravel(), np.arange(12 * ne))), shape=(size, 12 * ne)
        )

        # dR/du: K entries between free DoF plus the identity on the constrained DoF.
        free_cols = np.where(self._free[self._edofs], self._edofs, -1)
        rows = np.concatenate(
            [np.broadcast_to(free_rows[:, :, None], (ne, 12, 12)).ravel(), fixed_idx]
        )
        cols = np.concatenate(
            [np.broadcast_to(free_cols[:, None, :], (ne, 12, 12)).ravel(), fixed_idx]
        )
        self._k_sum = _SparseSum(rows, cols, size)
        self._k_blocks = self._k_sum.split(res_layout, res_layout)
        self._num_k_entries = 144 * ne
        _declare_blocks(self, self._k_blocks)

        # dR/d(section properties): element e's 12 residual rows against column e of each input.
        prop_layout = [(name, ne) for name, _, _ in _SECTION_INPUTS]
        prop_cols = np.arange(ne)[:, None] + ne * np.arange(4)  # (ne, 4)
        self._prop_sum = _SparseSum(free_rows[:, :, None], prop_cols[:, None, :], 4 * ne)
        self._prop_blocks = self._prop_sum.split(res_layout, prop_layout)
        _declare_blocks(self, self._prop_blocks, _ZERO_FEM)

        # dR/d(E, G): dense over the free rows.
        self._mat_sum = _SparseSum(free_rows[:, :, None], np.arange(2)[None, None, :], 2)
        self._mat_blocks = self._mat_sum.split(
            res_layout, [("youngs_modulus", 1), ("shear_modulus", 1)]
        )
        _declare_blocks(self, self._mat_blocks, _ZERO_FEM)

        # dR/d(nodes): element residual rows against its 6 end-node coordinates.
        self._node_sum = _SparseSum(free_rows[:, :, None], self._ecoords[:, None, :], 3 * n)
        self._node_blocks = self._node_sum.split(res_layout, [("nodes", 3 * n)])
        _declare_blocks(self, self._node_blocks)

        # dR/d(loads) = -I on the free DoF (constant).
        free_t = free_idx[free_idx < 3 * n]
        free_r = free_idx[free_idx >= 3 * n] - 3 * n
        self.declare_partials("displacements", "node_forces", rows=free_t, cols=free_t, val=-1.0)
        self.declare_partials("rotations", "node_moments", rows=free_r, cols=free_r, val=-1.0)

    # -- helpers ---------------------------------------------------------------------------------
    def _props(self, inputs):
        return [inputs[name] for name, _, _ in _SECTION_INPUTS]

    def _masked_element_dofs(self, outputs):
        u = np.concatenate([outputs["displacements"].ravel(), outputs["rotations"].ravel()])
        u = np.where(self._free, u, 0.0)
        return u, u[self._edofs]

    def _k_values(self, k_elem):
        """Values of the unique dR/du entries: element K contributions plus the fixed identity."""
        return self._k_sum.sum(
            np.concatenate([k_elem.ravel(), np.ones(np.count_nonzero(self._fixed))])
        )

    def _factorize(self, k_values):
        """
        Sparse LU factors of K_ff, the stiffness between the free DoF (CSC, SuperLU).

        The constrained DoF have identity rows and columns in dR/du, so they are solved apart.
        A singular or numerically singular K_ff (a mechanism, vanishing stiffness) raises
        om.AnalysisError: SuperLU stops at an exactly zero pivot, and a smallest pivot below
        1000 machine epsilons of the largest is treated the same.
        """
        free_idx = self._free_idx
        size = self._free.size
        k_full = sp.csc_matrix((k_values, (self._k_sum.rows, self._k_sum.cols)), shape=(size, size))
        k_ff = k_full[free_idx][:, free_idx].tocsc()
        msg = (
            f"{self.msginfo}: the stiffness matrix K is singular; check the constraints "
            f"(fixed_nodes = {self.options['fixed_nodes']!r}, fixed_dofs = "
            f"{self.options['fixed_dofs']!r}) and that every element has positive section "
            "properties and moduli."
        )
        try:
            lu = splu(k_ff)
        except RuntimeError as err:
            raise om.AnalysisError(f"{msg} ({err})") from err
        pivots = np.abs(lu.U.diagonal())
        if not np.all(np.isfinite(pivots)) or pivots.min() <= 1e3 * np.finfo(float).eps * (
            pivots.max()
        ):
            raise om.AnalysisError(f"{msg} (pivot ratio {pivots.min() / pivots.max():.3g})")
        return lu

    def _solve(self, lu, rhs, trans="N"):
        """Solve dR/du x = rhs (layout order) with the factors of K_ff."""
        sol = np.array(rhs, dtype=np.result_type(rhs, lu.U.dtype))
        sol[self._free_idx] = lu.solve(
            np.ascontiguousarray(rhs[self._free_idx], dtype=sol.dtype), trans=trans
        )
        return sol

    # -- ImplicitComponent API -------------------------------------------------------------------
    def apply_nonlinear(self, inputs, outputs, residuals):
        start, end = self._element_ends(inputs["nodes"])
        self._check_geometry(_lengths(start, end))
        k_elem, _ = self._element_stiffness(
            start, end, self._props(inputs), inputs["youngs_modulus"], inputs["shear_modulus"]
        )
        u, u_e = self._masked_element_dofs(outputs)
        res = self._scatter @ np.einsum("eij,ej->ei", k_elem, u_e).ravel()
        loads = np.concatenate([inputs["node_forces"].ravel(), inputs["node_moments"].ravel()])
        u_all = np.concatenate([outputs["displacements"].ravel(), outputs["rotations"].ravel()])
        res = np.where(self._free, res - loads, u_all)
        n3 = 3 * self.options["num_nodes"]
        residuals["displacements"] = res[:n3].reshape(-1, 3)
        residuals["rotations"] = res[n3:].reshape(-1, 3)

    def solve_nonlinear(self, inputs, outputs):
        props = self._props(inputs)
        start, end = self._element_ends(inputs["nodes"])
        self._check_geometry(_lengths(start, end), {s[0]: inputs[s[0]] for s in _SECTION_INPUTS})
        for name in ("youngs_modulus", "shear_modulus"):
            check_range(
                name,
                inputs[name][0],
                lower=0.0,
                lower_open=True,
                units="Pa",
                error=om.AnalysisError,
                where=self.msginfo,
            )
        k_elem, _ = self._element_stiffness(
            start, end, props, inputs["youngs_modulus"], inputs["shear_modulus"]
        )
        loads = np.concatenate([inputs["node_forces"].ravel(), inputs["node_moments"].ravel()])
        rhs = np.where(self._free, loads, 0.0)
        u = self._solve(self._factorize(self._k_values(k_elem)), rhs)
        if not np.all(np.isfinite(u)):
            raise om.AnalysisError(
                f"{self.msginfo}: the stiffness solve returned non-finite "
                "displacements; check the loads and section properties."
            )
        n3 = 3 * self.options["num_nodes"]
        outputs["displacements"] = u[:n3].reshape(-1, 3)
        outputs["rotations"] = u[n3:].reshape(-1, 3)

    def linearize(self, inputs, outputs, partials):
        props = [p.real for p in self._props(inputs)]
        modulus = inputs["youngs_modulus"].real
        shear = inputs["shear_modulus"].real
        start, end = self._element_ends(inputs["nodes"].real)
        k_elem, lam = self._element_stiffness(start, end, props, modulus, shear)
        _, u_e = self._masked_element_dofs(outputs)
        u_e = u_e.real

        k_values = self._k_values(k_elem)
        _set_blocks(partials, self._k_blocks, k_values)
        self._lu = self._factorize(k_values)

        # Section properties: K is linear in each property, so dK/dp = K(p = 1, others 0).
        length, _ = element_frames(start, end)
        ones, zeros = np.ones_like(length), np.zeros_like(length)
        blocks = []
        for i in range(4):
            unit = [ones if j == i else zeros for j in range(4)]
            k_unit = global_stiffness(lam, local_stiffness(length, *unit, modulus, shear))
            blocks.append(np.einsum("eij,ej->ei", k_unit, u_e))
        _set_blocks(partials, self._prop_blocks, self._prop_sum.sum(np.stack(blocks, axis=-1)))

        k_e = global_stiffness(lam, local_stiffness(length, *props, 1.0, 0.0))
        k_g = global_stiffness(lam, local_stiffness(length, *props, 0.0, 1.0))
        mat = np.stack(
            [np.einsum("eij,ej->ei", k_e, u_e), np.einsum("eij,ej->ei", k_g, u_e)], axis=-1
        )
        _set_blocks(partials, self._mat_blocks, self._mat_sum.sum(mat))

        def element_residual(s, e, area, inertia_v, inertia_i, torsion, u_e):
            props = (area, inertia_v, inertia_i, torsion)
            k, _ = self._element_stiffness(s, e, props, modulus, shear)
            return np.einsum("eij,ej->ei", k, u_e)

        node_blocks = self._coordinate_blocks(
            start, end, element_residual, **dict(zip(_PROP_ARGS, props, strict=True)), u_e=u_e
        )
        _set_blocks(partials, self._node_blocks, self._node_sum.sum(node_blocks))

    def solve_linear(self, d_outputs, d_residuals, mode):
        n3 = 3 * self.options["num_nodes"]
        if mode == "fwd":
            rhs = np.concatenate(
                [d_residuals["displacements"].ravel(), d_residuals["rotations"].ravel()]
            )
            sol = self._solve(self._lu, rhs)
            d_outputs["displacements"] = sol[:n3].reshape(-1, 3)
            d_outputs["rotations"] = sol[n3:].reshape(-1, 3)
        else:
            rhs = np.concatenate(
                [d_outputs["displacements"].ravel(), d_outputs["rotations"].ravel()]
            )
            sol = self._solve(self._lu, rhs, trans="T")
            d_residuals["displacements"] = sol[:n3].reshape(-1, 3)
            d_residuals["rotations"] = sol[n3:].reshape(-1, 3)


class BeamForcesComp(_FrameMixin, om.ExplicitComponent):
    """
    Load recovery of the frame: element end forces, section resultants and support reactions.

    Reference docs theory/structures 'Assembly and solution': element end loads f = K_local T u_e
    (12 per element, element frame); section resultants averaged over the element, here as internal
    forces on the positive face,
    (f[6:12] - f[0:6])/2 (see the module docstring for the sign convention); reactions
    r = K u - f in the global frame (non-zero only at constrained DoF, up to round-off).

    Partials are analytic (linear in u, in each of E A, G J, E I_y, E I_z, and in the loads)
    except d/d(node coordinates), which is a complex step on the per-element quantities
    (exact), all sparse.

    Inputs
    ------
    nodes : float, (num_nodes, 3), m
    area, bending_inertia_vertical, bending_inertia_inplane, torsion_constant :
        float, (num_elements,), m**2 or m**4 (as in BeamDisplacementComp)
    youngs_modulus, shear_modulus : float, scalar, Pa
    displacements : float, (num_nodes, 3), m
    rotations : float, (num_nodes, 3), rad
    node_forces : float, (num_nodes, 3), N
    node_moments : float, (num_nodes, 3), N*m

    Outputs
    -------
    element_end_forces : float, (num_elements, 2, 3), N
        Forces of the nodes on the element at its ends a and b, element frame.
    element_end_moments : float, (num_elements, 2, 3), N*m
        Moments of the nodes on the element at its ends a and b, element frame.
    section_forces : float, (num_elements, 3), N
        Mean internal forces (axial N, shear V_y, shear V_z), element frame, tension positive.
    section_moments : float, (num_elements, 3), N*m
        Mean internal moments (torque M_x, bending M_y, bending M_z), element frame.
    reaction_forces : float, (num_nodes, 3), N
        Support reaction forces (K u - f), global frame.
    reaction_moments : float, (num_nodes, 3), N*m
        Support reaction moments, global frame.

    Options
    -------
    num_nodes : int
    connectivity : array (num_elements, 2) of int or None
    """

    def initialize(self):
        self._declare_frame_options()

    def setup(self):
        n, ne = self._setup_frame()
        self._add_frame_inputs()
        self.add_input(
            "displacements",
            val=np.zeros((n, 3)),
            units="m",
            desc="nodal translations, global frame",
        )
        self.add_input(
            "rotations",
            val=np.zeros((n, 3)),
            units="rad",
            desc="nodal small rotations, global frame",
        )
        self.add_input(
            "node_forces",
            val=np.zeros((n, 3)),
            units="N",
            desc="external nodal forces, global frame",
        )
        self.add_input(
            "node_moments",
            val=np.zeros((n, 3)),
            units="N*m",
            desc="external nodal moments, global frame",
        )
        self.add_output(
            "element_end_forces",
            val=np.zeros((ne, 2, 3)),
            units="N",
            desc="forces of the nodes on each element at ends a, b (element frame)",
        )
        self.add_output(
            "element_end_moments",
            val=np.zeros((ne, 2, 3)),
            units="N*m",
            desc="moments of the nodes on each element at ends a, b (element frame)",
        )
        self.add_output(
            "section_forces",
            val=np.zeros((ne, 3)),
            units="N",
            desc="mean internal forces (axial, shear y, shear z), element frame",
        )
        self.add_output(
            "section_moments",
            val=np.zeros((ne, 3)),
            units="N*m",
            desc="mean internal moments (torque, bending y, bending z), element frame",
        )
        self.add_output(
            "reaction_forces",
            val=np.zeros((n, 3)),
            units="N",
            desc="support reaction forces K u - f, global frame",
        )
        self.add_output(
            "reaction_moments",
            val=np.zeros((n, 3)),
            units="N*m",
            desc="support reaction moments, global frame",
        )

        # Rows of the 30 per-element quantities in the output layout below.
        out_layout = [
            ("element_end_forces", 6 * ne),
            ("element_end_moments", 6 * ne),
            ("section_forces", 3 * ne),
            ("section_moments", 3 * ne),
            ("reaction_forces", 3 * n),
            ("reaction_moments", 3 * n),
        ]
        e = np.arange(ne)[:, None]
        end3 = np.arange(6)[None, :]
        rows = np.concatenate(
            [
                6 * e + end3,  # end forces (a xyz, b xyz)
                6 * ne + 6 * e + end3,  # end moments
                12 * ne + 3 * e + np.arange(3),  # section forces
                15 * ne + 3 * e + np.arange(3),  # section moments
                18 * ne + self._edofs,  # reactions, layout order
            ],
            axis=1,
        )  # (ne, 30)
        dof_layout = [("displacements", 3 * n), ("rotations", 3 * n)]
        self._u_sum = _SparseSum(rows[:, :, None], self._edofs[:, None, :], 6 * n)
        self._u_blocks = self._u_sum.split(out_layout, dof_layout)
        prop_cols = np.arange(ne)[:, None] + ne * np.arange(4)
        self._prop_sum = _SparseSum(rows[:, :, None], prop_cols[:, None, :], 4 * ne)
        self._prop_blocks = self._prop_sum.split(out_layout, [(s[0], ne) for s in _SECTION_INPUTS])
        self._mat_sum = _SparseSum(rows[:, :, None], np.arange(2)[None, None, :], 2)
        self._mat_blocks = self._mat_sum.split(
            out_layout, [("youngs_modulus", 1), ("shear_modulus", 1)]
        )
        self._node_sum = _SparseSum(rows[:, :, None], self._ecoords[:, None, :], 3 * n)
        self._node_blocks = self._node_sum.split(out_layout, [("nodes", 3 * n)])
        for blocks in (self._u_blocks, self._prop_blocks, self._mat_blocks, self._node_blocks):
            _declare_blocks(self, blocks, _ZERO_FORCES)
        self.declare_partials("reaction_forces", "node_forces", diagonal=True, val=-1.0)
        self.declare_partials("reaction_moments", "node_moments", diagonal=True, val=-1.0)

    @staticmethod
    def _outputs_from(k_loc, lam, u_e):
        """Return the 30 per-element quantities (ne, 30[, k]) from local K, λ, u_e (ne, 12[, k])."""
        f_loc = np.einsum("eij,ej...->ei...", k_loc, to_local(lam, u_e))
        f_glob = to_global(lam, f_loc)
        ends = f_loc.reshape(f_loc.shape[0], 2, 2, 3, *f_loc.shape[2:])  # (e, end, F/M, xyz)
        end_f = ends[:, :, 0].reshape(f_loc.shape[0], 6, *f_loc.shape[2:])
        end_m = ends[:, :, 1].reshape(f_loc.shape[0], 6, *f_loc.shape[2:])
        sec = 0.5 * (f_loc[:, 6:] - f_loc[:, :6])
        return np.concatenate([end_f, end_m, sec[:, :3], sec[:, 3:], f_glob], axis=1)

    def _element_dofs(self, inputs):
        u = np.concatenate([inputs["displacements"].ravel(), inputs["rotations"].ravel()])
        return u[self._edofs]

    def compute(self, inputs, outputs):
        n = self.options["num_nodes"]
        ne = self._conn.shape[0]
        start, end = self._element_ends(inputs["nodes"])
        self._check_geometry(_lengths(start, end))
        k_loc, lam = self._element_stiffness(
            start,
            end,
            [inputs[s[0]] for s in _SECTION_INPUTS],
            inputs["youngs_modulus"],
            inputs["shear_modulus"],
            frame="local",
        )
        vals = self._outputs_from(k_loc, lam, self._element_dofs(inputs))
        outputs["element_end_forces"] = vals[:, 0:6].reshape(ne, 2, 3)
        outputs["element_end_moments"] = vals[:, 6:12].reshape(ne, 2, 3)
        outputs["section_forces"] = vals[:, 12:15]
        outputs["section_moments"] = vals[:, 15:18]
        react = np.zeros(6 * n, dtype=vals.dtype)
        np.add.at(react, self._edofs.ravel(), vals[:, 18:].ravel())
        react -= np.concatenate([inputs["node_forces"].ravel(), inputs["node_moments"].ravel()])
        outputs["reaction_forces"] = react[: 3 * n].reshape(n, 3)
        outputs["reaction_moments"] = react[3 * n :].reshape(n, 3)

    def compute_partials(self, inputs, partials):
        props = [inputs[s[0]].real for s in _SECTION_INPUTS]
        modulus = inputs["youngs_modulus"].real
        shear = inputs["shear_modulus"].real
        start, end = self._element_ends(inputs["nodes"].real)
        k_loc, lam = self._element_stiffness(start, end, props, modulus, shear, frame="local")
        u_e = self._element_dofs(inputs).real
        ne = u_e.shape[0]

        eye = np.broadcast_to(np.eye(12), (ne, 12, 12))
        _set_blocks(partials, self._u_blocks, self._u_sum.sum(self._outputs_from(k_loc, lam, eye)))

        length, _ = element_frames(start, end)
        ones, zeros = np.ones_like(length), np.zeros_like(length)
        blocks = []
        for i in range(4):
            unit = [ones if j == i else zeros for j in range(4)]
            blocks.append(
                self._outputs_from(local_stiffness(length, *unit, modulus, shear), lam, u_e)
            )
        _set_blocks(partials, self._prop_blocks, self._prop_sum.sum(np.stack(blocks, axis=-1)))

        mat = np.stack(
            [
                self._outputs_from(local_stiffness(length, *props, 1.0, 0.0), lam, u_e),
                self._outputs_from(local_stiffness(length, *props, 0.0, 1.0), lam, u_e),
            ],
            axis=-1,
        )
        _set_blocks(partials, self._mat_blocks, self._mat_sum.sum(mat))

        def element_outputs(s, e, area, inertia_v, inertia_i, torsion, u_e):
            props = (area, inertia_v, inertia_i, torsion)
            k, lm = self._element_stiffness(s, e, props, modulus, shear, frame="local")
            return self._outputs_from(k, lm, u_e)

        node_blocks = self._coordinate_blocks(
            start, end, element_outputs, **dict(zip(_PROP_ARGS, props, strict=True)), u_e=u_e
        )
        _set_blocks(partials, self._node_blocks, self._node_sum.sum(node_blocks))


class BeamMassComp(_FrameMixin, om.ExplicitComponent):
    """
    Element masses, total mass and centre of gravity of the frame.

    See docs theory/structures 'Box section'.

    m_e = ρ A_e L_e; mass = Σ m_e; cg = Σ m_e (x_a + x_b)/2 / mass. Analytic partials.

    Inputs
    ------
    nodes : float, (num_nodes, 3), m
    area : float, (num_elements,), m**2
    density : float, scalar, kg/m**3

    Outputs
    -------
    element_mass : float, (num_elements,), kg
    beam_mass : float, scalar, kg
        Mass of the modelled frame (one half wing for the wing box).
    beam_cg : float, (3,), m
        Centre of gravity, global frame.

    Options
    -------
    num_nodes : int
    connectivity : array (num_elements, 2) of int or None
    """

    def initialize(self):
        self._declare_frame_options()

    def setup(self):
        n, ne = self._setup_frame()
        self.add_input(
            "nodes",
            val=default_nodes(n),
            units="m",
            desc="node coordinates in the global (body) frame",
        )
        self.add_input(
            "area", val=np.ones(ne), units="m**2", desc="cross-section area, per element"
        )
        self.add_input("density", val=DEFAULT_DENSITY, units="kg/m**3", desc="material density")
        self.add_output("element_mass", val=np.ones(ne), units="kg", desc="mass of each element")
        self.add_output("beam_mass", val=1.0, units="kg", desc="total mass of the frame")
        self.add_output(
            "beam_cg",
            val=np.zeros(3),
            units="m",
            desc="centre of gravity of the frame, global frame",
        )

        ar = np.arange(ne)
        self.declare_partials("element_mass", "area", diagonal=True)
        self.declare_partials("element_mass", "density")
        self.declare_partials(
            "element_mass", "nodes", rows=np.repeat(ar, 6), cols=self._ecoords.ravel()
        )
        self.declare_partials("beam_mass", ["area", "density", "nodes"])
        self.declare_partials("beam_cg", ["area", "density", "nodes"])

    def compute(self, inputs, outputs):
        start, end = self._element_ends(inputs["nodes"])
        length = _lengths(start, end)
        self._check_geometry(length)
        m_e = inputs["density"] * inputs["area"] * length
        mass = np.sum(m_e)
        outputs["element_mass"] = m_e
        outputs["beam_mass"] = mass
        outputs["beam_cg"] = np.sum(m_e[:, None] * 0.5 * (start + end), axis=0) / mass

    def compute_partials(self, inputs, partials):
        n = self.options["num_nodes"]
        rho = inputs["density"]
        area = inputs["area"]
        start, end = self._element_ends(inputs["nodes"])
        d = end - start
        length = np.sqrt(np.sum(d * d, axis=1))
        unit = d / length[:, None]
        m_e = rho * area * length
        mass = np.sum(m_e)
        mid = 0.5 * (start + end)
        cg = np.sum(m_e[:, None] * mid, axis=0) / mass

        dm_dnode = (rho * area)[:, None] * np.concatenate([-unit, unit], axis=1)  # (ne, 6)
        partials["element_mass", "area"] = rho * length
        partials["element_mass", "density"] = (area * length)[:, None]
        partials["element_mass", "nodes"] = dm_dnode.ravel()

        dm_dnodes = np.zeros(3 * n)
        np.add.at(dm_dnodes, self._ecoords.ravel(), dm_dnode.ravel())
        partials["beam_mass", "area"] = rho * length
        partials["beam_mass", "density"] = np.sum(area * length)
        partials["beam_mass", "nodes"] = dm_dnodes

        # cg = Σ m_e mid_e / M: dcg/dm_e = (mid_e - cg)/M, plus the explicit mid-point term.
        lever = (mid - cg) / mass  # (ne, 3)
        partials["beam_cg", "area"] = (lever * (rho * length)[:, None]).T
        partials["beam_cg", "density"] = np.sum(lever * (area * length)[:, None], axis=0)[:, None]
        dcg = np.zeros((3, 3 * n))
        # via the element masses
        contrib = lever[:, :, None] * dm_dnode[:, None, :]  # (ne, 3, 6)
        cols = np.broadcast_to(self._ecoords[:, None, :], contrib.shape)
        rows = np.broadcast_to(np.arange(3)[None, :, None], contrib.shape)
        np.add.at(dcg, (rows.ravel(), cols.ravel()), contrib.ravel())
        # via the mid-points: d mid_e / d x_a = d mid_e / d x_b = I/2, weighted by m_e/M
        comp = np.broadcast_to(np.tile(np.arange(3), 2), self._ecoords.shape)
        np.add.at(dcg, (comp.ravel(), self._ecoords.ravel()), np.repeat(0.5 * m_e / mass, 6))
        partials["beam_cg", "nodes"] = dcg
