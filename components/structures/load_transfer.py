"""Load and displacement transfer between aerodynamic mesh points and the beam nodes."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.structures.beam import default_nodes
from lpc_mdo.core.constants import GRAVITY

_AXES = ("x", "y", "z")


def _skew(a):
    """Cross-product matrices [a]_x (..., 3, 3) with [a]_x b = a x b."""
    out = np.zeros(a.shape[:-1] + (3, 3), dtype=a.dtype)
    out[..., 0, 1], out[..., 0, 2] = -a[..., 2], a[..., 1]
    out[..., 1, 0], out[..., 1, 2] = a[..., 2], -a[..., 0]
    out[..., 2, 0], out[..., 2, 1] = -a[..., 1], a[..., 0]
    return out


def span_weights(points_span, nodes_span):
    """
    Linear (hat-function) weights of points on the beam nodes along one span coordinate.

    A point between nodes a and a + 1 gets w_a = 1 - t, w_(a+1) = t with
    t = (s - Y_a)/(Y_(a+1) - Y_a); a point beyond the first or last node goes entirely to that
    node. The weights of each point sum to 1, which makes the transfers conservative.

    Parameters
    ----------
    points_span : ndarray, (num_points,)
        Span coordinate s of the points (real or complex).
    nodes_span : ndarray, (num_nodes,)
        Span coordinate Y of the nodes, strictly increasing.

    Returns
    -------
    w : ndarray, (num_nodes, num_points)
        Weights.
    dw_ds : ndarray, (num_nodes, num_points)
        Derivative of w[j, q] with respect to s_q.
    dw_dy : ndarray, (num_nodes, num_points, num_nodes)
        Derivative of w[j, q] with respect to Y_k.
    """
    s, y = points_span, nodes_span
    n, q = y.size, s.size
    seg = np.clip(np.searchsorted(y.real, s.real, side="right") - 1, 0, n - 2)
    inside = (s.real >= y.real[0]) & (s.real <= y.real[-1])
    below = s.real < y.real[0]
    ya, yb = y[seg], y[seg + 1]
    delta = yb - ya
    t = np.where(inside, (s - ya) / delta, np.where(below, 0.0, 1.0))
    cols = np.arange(q)
    w = np.zeros((n, q), dtype=np.result_type(s, y))
    w[seg, cols] = 1.0 - t
    w[seg + 1, cols] += t

    dt_ds = np.where(inside, 1.0 / delta.real, 0.0)
    dt_dya = np.where(inside, -(1.0 - t.real) / delta.real, 0.0)
    dt_dyb = np.where(inside, -t.real / delta.real, 0.0)
    dw_ds = np.zeros((n, q))
    dw_ds[seg, cols] = -dt_ds
    dw_ds[seg + 1, cols] = dt_ds
    dw_dy = np.zeros((n, q, n))
    for node, sign in ((seg, -1.0), (seg + 1, 1.0)):  # w_a = 1 - t, w_b = t
        dw_dy[node, cols, seg] += sign * dt_dya
        dw_dy[node, cols, seg + 1] += sign * dt_dyb
    return w, dw_ds, dw_dy


def _check_nodes(comp, nodes, axis):
    y = nodes[:, axis].real
    if np.any(np.diff(y) <= 0.0):
        raise om.AnalysisError(
            f"{comp.msginfo}: input 'nodes' must be strictly increasing along the span axis "
            f"{_AXES[axis]} (root to tip) for the load transfer; got {y.tolist()}."
        )


def _gravity_direction(pitch, roll):
    """Return the body-frame unit vector of gravity (3-2-1 Euler angles) and its partials."""
    st, ct, sp, cp = np.sin(pitch), np.cos(pitch), np.sin(roll), np.cos(roll)
    g = np.array([-st, sp * ct, cp * ct]).ravel()
    dg_dpitch = np.array([-ct, -sp * st, -cp * st]).ravel()
    dg_droll = np.array([np.zeros_like(sp), cp * ct, -sp * ct]).ravel()
    return g, dg_dpitch, dg_droll


class LoadTransferComp(om.ExplicitComponent):
    """
    Transfer of point forces (aerodynamic panel forces, weights) to beam nodal forces and moments.

    Each point q with force F_q is shared between the two beam nodes that bracket it along the
    span axis with linear weights w_qj (see :func:`span_weights`; a point outside the beam goes to
    the end node), and the moment of the force about each node is carried as a nodal moment:

        F_j = Σ_q w_qj F_q,    M_j = Σ_q w_qj (x_q - X_j) × F_q.

    Because Σ_j w_qj = 1, the nodal loads have exactly the resultant force and the resultant
    moment (about any point) of the point forces. With the same weights,
    DisplacementTransferComp moves the points with the beam; the pair conserves virtual work.

    The interface to the aerodynamics is a set of force vectors at given points (e.g. VLM
    panel forces at their force points, body frame) for the half wing that the beam models;
    panel arrays such as (num_chordwise, num_spanwise, 3) connect with flat src_indices.

    Weight and inertial relief: with ``include_weight`` the beam's own element masses are lumped
    half to each end node, and optional point masses (``num_point_masses``, e.g. booms, rotors)
    are transferred like the aerodynamic forces. Their load is m n g ĝ: load factor n (the
    condition's, so a +3 g pull-up loads the structure with 3 g of weight, i.e. inertial
    relief) and gravity direction in body axes ĝ = (-sin θ, sin φ cos θ, cos φ cos θ)
    (docs theory/dynamics 'Gravity').

    Analytic partials (dense between nodes and points, which may move between beam segments as
    the geometry changes).

    Inputs
    ------
    nodes : float, (num_nodes, 3), m
        Beam nodes, strictly increasing along the span axis.
    aero_points : float, (num_points, 3), m
        Points of application of the aerodynamic forces (if num_points > 0).
    aero_forces : float, (num_points, 3), N
        Aerodynamic forces, body frame (if num_points > 0).
    element_mass : float, (num_nodes - 1,), kg
        Beam element masses (if include_weight).
    point_masses : float, (num_point_masses,), kg
        Extra masses carried by the beam (if num_point_masses > 0).
    point_mass_locations : float, (num_point_masses, 3), m
    load_factor : float, scalar
        Load factor n (if include_weight or num_point_masses > 0).
    pitch, roll : float, scalar, rad
        Attitude for the gravity direction (if include_weight or num_point_masses > 0).

    Outputs
    -------
    node_forces : float, (num_nodes, 3), N
    node_moments : float, (num_nodes, 3), N*m

    Options
    -------
    num_nodes : int
        Beam nodes (>= 2), a chain root to tip.
    num_points : int
        Aerodynamic force points (>= 0).
    num_point_masses : int
        Point masses (>= 0). Default 0.
    include_weight : bool
        Add the beam's own weight at the load factor. Default True.
    span_axis : int
        Coordinate used for the weights: 0, 1 (default, y) or 2.
    gravity : float
        g in m/s**2 (> 0). Default :data:`lpc_mdo.core.constants.GRAVITY` (9.81).
    """

    def initialize(self):
        self.options.declare("num_nodes", types=int, lower=2, desc="Number of beam nodes")
        self.options.declare("num_points", types=int, lower=0, desc="Aerodynamic force points")
        self.options.declare(
            "num_point_masses",
            default=0,
            types=int,
            lower=0,
            desc="Point masses carried by the beam",
        )
        self.options.declare(
            "include_weight",
            default=True,
            types=bool,
            desc="Add the beam's own weight at the load factor",
        )
        self.options.declare(
            "span_axis",
            default=1,
            values=(0, 1, 2),
            desc="Coordinate along the span used for the weights",
        )
        self.options.declare(
            "gravity",
            default=GRAVITY,
            types=float,
            lower=1e-12,
            desc="Gravitational acceleration g, m/s**2",
        )

    def setup(self):
        n = self.options["num_nodes"]
        p = self.options["num_points"]
        k = self.options["num_point_masses"]
        weight = self.options["include_weight"]
        self.add_input(
            "nodes",
            val=default_nodes(n),
            units="m",
            desc="beam nodes, body frame, increasing along the span axis",
        )
        if p:
            self.add_input(
                "aero_points",
                val=np.zeros((p, 3)),
                units="m",
                desc="points of application of the aerodynamic forces",
            )
            self.add_input(
                "aero_forces",
                val=np.zeros((p, 3)),
                units="N",
                desc="aerodynamic forces, body frame",
            )
        if weight:
            self.add_input(
                "element_mass", val=np.zeros(n - 1), units="kg", desc="beam element masses"
            )
        if k:
            self.add_input(
                "point_masses", val=np.zeros(k), units="kg", desc="point masses carried by the beam"
            )
            self.add_input(
                "point_mass_locations",
                val=np.zeros((k, 3)),
                units="m",
                desc="locations of the point masses",
            )
        if weight or k:
            self.add_input("load_factor", val=1.0, units=None, desc="load factor n")
            self.add_input("pitch", val=0.0, units="rad", desc="pitch angle")
            self.add_input("roll", val=0.0, units="rad", desc="roll angle")
        self.add_output(
            "node_forces", val=np.zeros((n, 3)), units="N", desc="nodal forces, body frame"
        )
        self.add_output(
            "node_moments", val=np.zeros((n, 3)), units="N*m", desc="nodal moments, body frame"
        )

        ax = self.options["span_axis"]
        j3 = np.arange(3 * n)
        if p or k:
            self.declare_partials(
                "node_forces",
                "nodes",
                rows=np.repeat(j3, n),
                cols=np.tile(3 * np.arange(n) + ax, 3 * n),
            )
            self.declare_partials("node_moments", "nodes")
        for q, force, point in (
            (p, "aero_forces", "aero_points"),
            (k, "point_masses", "point_mass_locations"),
        ):
            if not q:
                continue
            # node_forces wrt point coordinates: only the span coordinate moves the weights.
            self.declare_partials(
                "node_forces",
                point,
                rows=np.repeat(j3, q),
                cols=np.tile(3 * np.arange(q) + ax, 3 * n),
            )
            self.declare_partials("node_moments", point)
            if force == "aero_forces":
                rows = 3 * np.arange(n)[:, None, None] + np.arange(3)[None, None, :]
                cols = 3 * np.arange(p)[None, :, None] + np.arange(3)[None, None, :]
                rows, cols = np.broadcast_arrays(rows, cols)  # (n, p, 3) -> (j, k) x (q, k)
                self.declare_partials(
                    "node_forces",
                    force,
                    rows=np.transpose(rows, (0, 2, 1)).ravel(),
                    cols=np.transpose(cols, (0, 2, 1)).ravel(),
                )
            else:
                self.declare_partials("node_forces", force)
            self.declare_partials("node_moments", force)
        if weight:
            # element e loads nodes e and e + 1
            e = np.arange(n - 1)
            rows = np.concatenate(
                [3 * e[:, None] + np.arange(3), 3 * (e + 1)[:, None] + np.arange(3)], axis=1
            ).ravel()
            self.declare_partials("node_forces", "element_mass", rows=rows, cols=np.repeat(e, 6))
        if weight or k:
            self.declare_partials("node_forces", ["load_factor", "pitch", "roll"])
            if k:
                self.declare_partials("node_moments", ["load_factor", "pitch", "roll"])

    def _point_loads(self, inputs):
        """Points (q, 3) and forces (q, 3) of all point loads, and the weight acceleration."""
        pts, frc = [], []
        acc = None
        if self.options["include_weight"] or self.options["num_point_masses"]:
            g, _, _ = _gravity_direction(inputs["pitch"], inputs["roll"])
            acc = inputs["load_factor"] * self.options["gravity"] * g
        if self.options["num_points"]:
            pts.append(inputs["aero_points"])
            frc.append(inputs["aero_forces"])
        if self.options["num_point_masses"]:
            pts.append(inputs["point_mass_locations"])
            frc.append(inputs["point_masses"][:, None] * acc[None, :])
        if pts:
            return np.concatenate(pts), np.concatenate(frc), acc
        return np.zeros((0, 3)), np.zeros((0, 3)), acc

    def compute(self, inputs, outputs):
        ax = self.options["span_axis"]
        nodes = inputs["nodes"]
        _check_nodes(self, nodes, ax)
        points, forces, acc = self._point_loads(inputs)
        w, _, _ = span_weights(points[:, ax], nodes[:, ax])
        lever = points[None, :, :] - nodes[:, None, :]  # (n, q, 3)
        node_forces = w @ forces
        node_moments = np.einsum("jq,jqk->jk", w, np.cross(lever, forces[None, :, :]))
        if self.options["include_weight"]:
            m = inputs["element_mass"]
            lumped = np.zeros(nodes.shape[0], dtype=np.result_type(m, acc))
            lumped[:-1] += 0.5 * m
            lumped[1:] += 0.5 * m
            node_forces = node_forces + lumped[:, None] * acc[None, :]
        outputs["node_forces"] = node_forces
        outputs["node_moments"] = node_moments

    def compute_partials(self, inputs, partials):
        n = self.options["num_nodes"]
        p = self.options["num_points"]
        k = self.options["num_point_masses"]
        ax = self.options["span_axis"]
        grav = self.options["gravity"]
        nodes = inputs["nodes"]
        points, forces, acc = self._point_loads(inputs)
        q = points.shape[0]
        w, dw_ds, dw_dy = span_weights(points[:, ax], nodes[:, ax])
        lever = points[None, :, :] - nodes[:, None, :]
        moment = np.cross(lever, forces[None, :, :])  # (n, q, 3)
        skew_f = _skew(forces)  # (q, 3, 3)

        if q:
            # nodes: forces move through the weights (span coordinate of the nodes only)
            partials["node_forces", "nodes"] = np.einsum("jqm,qk->jkm", dw_dy, forces).ravel()
            dm = np.zeros((n, 3, n, 3))
            dm[:, :, :, ax] = np.einsum("jqm,jqk->jkm", dw_dy, moment)
            # d(x_q - X_j) x F_q / dX_j = [F_q]_x
            dm[np.arange(n), :, np.arange(n), :] += np.einsum("jq,qab->jab", w, skew_f)
            partials["node_moments", "nodes"] = dm.reshape(3 * n, 3 * n)

            # point coordinates
            d_pf = np.einsum("jq,qk->jkq", dw_ds, forces)  # (n, 3, q): column ax of point q
            d_pm = np.zeros((n, 3, q, 3))
            d_pm += -np.einsum("jq,qab->jaqb", w, skew_f)
            d_pm[:, :, :, ax] += np.einsum("jq,jqk->jkq", dw_ds, moment)
            # forces: dM_j/dF_q = w_qj [x_q - X_j]_x
            d_mf = np.einsum("jq,jqab->jaqb", w, _skew(lever))  # (n, 3, q, 3)

            sl = slice(0, p)
            if p:
                partials["node_forces", "aero_points"] = d_pf[:, :, sl].ravel()
                partials["node_moments", "aero_points"] = d_pm[:, :, sl, :].reshape(3 * n, 3 * p)
                partials["node_forces", "aero_forces"] = np.repeat(
                    w[:, None, :p], 3, axis=1
                ).ravel()
                partials["node_moments", "aero_forces"] = d_mf[:, :, sl, :].reshape(3 * n, 3 * p)
            if k:
                sl = slice(p, p + k)
                partials["node_forces", "point_mass_locations"] = d_pf[:, :, sl].ravel()
                partials["node_moments", "point_mass_locations"] = d_pm[:, :, sl, :].reshape(
                    3 * n, 3 * k
                )
                # F_q = m_q acc
                partials["node_forces", "point_masses"] = np.einsum(
                    "jq,k->jkq", w[:, sl], acc
                ).reshape(3 * n, k)
                partials["node_moments", "point_masses"] = np.einsum(
                    "jqab,b->jaq", d_mf[:, :, sl, :].transpose(0, 2, 1, 3), acc
                ).reshape(3 * n, k)

        if self.options["include_weight"] or k:
            g, dg_dpitch, dg_droll = _gravity_direction(inputs["pitch"], inputs["roll"])
            nf = inputs["load_factor"]
            dacc = {
                "load_factor": grav * g,
                "pitch": nf * grav * dg_dpitch,
                "roll": nf * grav * dg_droll,
            }
            lumped = np.zeros(n)
            if self.options["include_weight"]:
                m = inputs["element_mass"]
                lumped[:-1] += 0.5 * m
                lumped[1:] += 0.5 * m
                partials["node_forces", "element_mass"] = np.tile(0.5 * acc, 2 * (n - 1))
            mass_q = np.zeros(q)
            if k:
                mass_q[p:] = inputs["point_masses"]
            carried = lumped + w @ mass_q  # mass per node whose force is m acc
            for name, da in dacc.items():
                partials["node_forces", name] = np.outer(carried, da).reshape(3 * n, 1)
                if k:
                    # M_j = Σ_q w_qj m_q (x_q - X_j) x acc
                    arm = np.einsum("jq,q,jqa->ja", w, mass_q, lever)
                    partials["node_moments", name] = np.cross(arm, da).reshape(3 * n, 1)


class DisplacementTransferComp(om.ExplicitComponent):
    """
    Beam displacements carried to the aerodynamic mesh points (two-way coupling).

    Each point q moves rigidly with the beam nodes that bracket it, with the same weights w_qj as
    LoadTransferComp: d_q = Σ_j w_qj (u_j + θ_j × (x_q - X_j)). The two transfers are adjoint,
    so Σ_q F_q·d_q = Σ_j (F_j·u_j + M_j·θ_j): the aerodynamic loads do the same virtual work on
    the mesh as the transferred loads do on the beam. Analytic partials.

    Inputs
    ------
    nodes : float, (num_nodes, 3), m
        Undeformed beam nodes, strictly increasing along the span axis.
    displacements : float, (num_nodes, 3), m
    rotations : float, (num_nodes, 3), rad
    aero_points : float, (num_points, 3), m
        Undeformed mesh points.

    Outputs
    -------
    aero_displacements : float, (num_points, 3), m
        Displacements of the mesh points (add them to the undeformed points).

    Options
    -------
    num_nodes : int
    num_points : int (>= 1)
    span_axis : int
        0, 1 (default, y) or 2.
    """

    def initialize(self):
        self.options.declare("num_nodes", types=int, lower=2, desc="Number of beam nodes")
        self.options.declare("num_points", types=int, lower=1, desc="Number of mesh points")
        self.options.declare(
            "span_axis",
            default=1,
            values=(0, 1, 2),
            desc="Coordinate along the span used for the weights",
        )

    def setup(self):
        n = self.options["num_nodes"]
        p = self.options["num_points"]
        self.add_input("nodes", val=default_nodes(n), units="m", desc="undeformed beam nodes")
        self.add_input(
            "displacements", val=np.zeros((n, 3)), units="m", desc="nodal translations, body frame"
        )
        self.add_input(
            "rotations", val=np.zeros((n, 3)), units="rad", desc="nodal small rotations, body frame"
        )
        self.add_input(
            "aero_points",
            val=np.zeros((p, 3)),
            units="m",
            desc="undeformed aerodynamic mesh points",
        )
        self.add_output(
            "aero_displacements",
            val=np.zeros((p, 3)),
            units="m",
            desc="displacements of the aerodynamic mesh points",
        )
        rows = 3 * np.arange(p)[:, None, None] + np.arange(3)[None, None, :]  # (q, 1, k)
        cols = 3 * np.arange(n)[None, :, None] + np.arange(3)[None, None, :]  # (1, j, k)
        rows, cols = np.broadcast_arrays(rows, cols)
        self.declare_partials(
            "aero_displacements", "displacements", rows=rows.ravel(), cols=cols.ravel()
        )
        self.declare_partials("aero_displacements", "rotations")
        # each point's displacement depends on its own coordinates only
        blk_r = np.repeat(np.arange(3 * p), 3)
        blk_c = (
            3 * np.arange(p)[:, None, None] + np.zeros((1, 3, 1), int) + np.arange(3)[None, None, :]
        ).ravel()
        self.declare_partials("aero_displacements", "aero_points", rows=blk_r, cols=blk_c)
        self.declare_partials("aero_displacements", "nodes")

    def compute(self, inputs, outputs):
        ax = self.options["span_axis"]
        nodes = inputs["nodes"]
        _check_nodes(self, nodes, ax)
        pts = inputs["aero_points"]
        w, _, _ = span_weights(pts[:, ax], nodes[:, ax])
        lever = pts[None, :, :] - nodes[:, None, :]
        motion = inputs["displacements"][:, None, :] + np.cross(
            inputs["rotations"][:, None, :], lever
        )
        outputs["aero_displacements"] = np.einsum("jq,jqk->qk", w, motion)

    def compute_partials(self, inputs, partials):
        n = self.options["num_nodes"]
        p = self.options["num_points"]
        ax = self.options["span_axis"]
        nodes = inputs["nodes"]
        pts = inputs["aero_points"]
        rot = inputs["rotations"]
        w, dw_ds, dw_dy = span_weights(pts[:, ax], nodes[:, ax])
        lever = pts[None, :, :] - nodes[:, None, :]
        motion = inputs["displacements"][:, None, :] + np.cross(rot[:, None, :], lever)
        skew_rot = _skew(rot)  # (n, 3, 3)

        partials["aero_displacements", "displacements"] = np.repeat(
            w.T[:, :, None], 3, axis=2
        ).ravel()
        # θ × r = -[r]_x θ
        partials["aero_displacements", "rotations"] = -np.einsum(
            "jq,jqab->qajb", w, _skew(lever)
        ).reshape(3 * p, 3 * n)
        dpt = np.einsum("jq,jab->qab", w, skew_rot)
        dpt[:, :, ax] += np.einsum("jq,jqa->qa", dw_ds, motion)
        partials["aero_displacements", "aero_points"] = dpt.ravel()
        dnd = np.zeros((p, 3, n, 3))
        dnd[:, :, :, ax] = np.einsum("jqm,jqa->qam", dw_dy, motion)
        dnd -= np.einsum("jq,jab->qajb", w, skew_rot)
        partials["aero_displacements", "nodes"] = dnd.reshape(3 * p, 3 * n)
