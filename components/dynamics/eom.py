"""Six-degree-of-freedom rigid-body equations of motion (paper eq. 29, 34)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range

# GRAVITY is defined once in lpc_mdo.core.constants; importing it from this module keeps working.
from lpc_mdo.core.constants import GRAVITY


def _skew(v):
    """Cross-product matrices of vectors v (..., 3): skew(v) @ x = v x x."""
    s = np.zeros(v.shape + (3,), dtype=v.dtype)
    s[..., 0, 1], s[..., 0, 2] = -v[..., 2], v[..., 1]
    s[..., 1, 0], s[..., 1, 2] = v[..., 2], -v[..., 0]
    s[..., 2, 0], s[..., 2, 1] = -v[..., 1], v[..., 0]
    return s


def _block_pattern(nn, rows_per_node, cols_per_node, shared_cols=False):
    """rows/cols of per-node dense blocks (or of a dense block on an input shared by nodes)."""
    r, c = np.meshgrid(np.arange(rows_per_node), np.arange(cols_per_node), indexing="ij")
    node = np.arange(nn)[:, None, None]
    rows = node * rows_per_node + r
    cols = c + (0 if shared_cols else node * cols_per_node) + 0 * node
    return rows.ravel(), cols.ravel()


class EquationsOfMotionComp(om.ExplicitComponent):
    """
    Accelerations of the rigid vehicle from forces and moments (Newton–Euler about the cg).

    Paper eq. 34 (docs theory/dynamics 'Gravity', 'Equations of motion'), body frame x forward, y
    right, z down, gravity m g n along the local vertical (n the load factor):

    - (X, Y, Z) + m g n (-sin th, cos th sin ph, cos th cos ph) = m (a + omega x V)
    - I omega_dot + omega x (I omega) = M_cg,  M_cg = M_ref - r_cg x F_aero

    where F_aero and M_ref are the aerodynamic and propulsive resultant and its moment about the
    body origin (the nose), r_cg the cg position and I the inertia about the cg. Trim (paper
    eq. 29) constrains these accelerations: zero in steady conditions, the prescribed u_dot and
    w_dot in the transition points.

    Inputs
    ------
    force : (num_nodes, 3), N
        Aerodynamic plus propulsive force in the body frame (without gravity).
    moment : (num_nodes, 3), N*m
        Moment of those forces about the body origin.
    mass : scalar, kg
    cg : (3,), m
        Centre of gravity in the body frame.
    inertia : (3, 3), kg*m**2
        Inertia tensor about the cg (the full matrix; products of inertia with the sign of the
        tensor, I_xz = -sum m x z).
    roll, pitch : (num_nodes,), rad
        Euler angles phi and theta.
    load_factor : (num_nodes,)
        Multiplies gravity (1, or 3 and -1 in the structural cases).
    velocity : (num_nodes, 3), m/s
        Body-axis velocity (u, v, w).
    angular_rate : (num_nodes, 3), rad/s
        Body rates (p, q, r).

    Outputs
    -------
    linear_acceleration : (num_nodes, 3), m/s**2
        (u_dot, v_dot, w_dot).
    angular_acceleration : (num_nodes, 3), rad/s**2
        (p_dot, q_dot, r_dot).

    Options
    -------
    num_nodes : int
        Number of flight conditions.
    """

    def initialize(self):
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )

    def setup(self):
        nn = self.options["num_nodes"]
        self.add_input(
            "force",
            np.zeros((nn, 3)),
            units="N",
            desc="aerodynamic and propulsive force, body frame",
        )
        self.add_input(
            "moment",
            np.zeros((nn, 3)),
            units="N*m",
            desc="moment of the force about the body origin",
        )
        self.add_input("mass", 3724.0, units="kg", desc="vehicle mass")
        self.add_input("cg", np.zeros(3), units="m", desc="centre of gravity, body frame")
        self.add_input(
            "inertia", np.diag([1e4, 1e4, 1e4]), units="kg*m**2", desc="inertia tensor about the cg"
        )
        self.add_input("roll", np.zeros(nn), units="rad", desc="roll angle phi")
        self.add_input("pitch", np.zeros(nn), units="rad", desc="pitch angle theta")
        self.add_input("load_factor", np.ones(nn), units=None, desc="gravity multiplier n")
        self.add_input("velocity", np.zeros((nn, 3)), units="m/s", desc="body velocity u, v, w")
        self.add_input("angular_rate", np.zeros((nn, 3)), units="rad/s", desc="body rates p, q, r")
        self.add_output(
            "linear_acceleration", np.zeros((nn, 3)), units="m/s**2", desc="u_dot, v_dot, w_dot"
        )
        self.add_output(
            "angular_acceleration", np.zeros((nn, 3)), units="rad/s**2", desc="p_dot, q_dot, r_dot"
        )

        lin, ang = "linear_acceleration", "angular_acceleration"
        ar3 = np.arange(3 * nn)
        self.declare_partials(lin, "force", rows=ar3, cols=ar3)
        self.declare_partials(lin, "mass", rows=ar3, cols=np.zeros(3 * nn, dtype=int))
        node_col = np.repeat(np.arange(nn), 3)
        self.declare_partials(lin, ["roll", "pitch", "load_factor"], rows=ar3, cols=node_col)
        rows, cols = _block_pattern(nn, 3, 3)
        self.declare_partials(lin, ["velocity", "angular_rate"], rows=rows, cols=cols)
        self.declare_partials(ang, ["force", "moment", "angular_rate"], rows=rows, cols=cols)
        rows, cols = _block_pattern(nn, 3, 3, shared_cols=True)
        self.declare_partials(ang, "cg", rows=rows, cols=cols)
        rows, cols = _block_pattern(nn, 3, 9, shared_cols=True)
        self.declare_partials(ang, "inertia", rows=rows, cols=cols)

    def _inverse_inertia(self, inertia):
        if np.linalg.cond(inertia.real) > 1e12:
            raise om.AnalysisError(
                f"{self.msginfo}: inertia = {inertia.real.tolist()} kg*m**2 "
                "is singular; it must be invertible."
            )
        return np.linalg.inv(inertia)

    def _gravity_direction(self, inputs):
        ph, th = inputs["roll"], inputs["pitch"]
        return np.stack([-np.sin(th), np.cos(th) * np.sin(ph), np.cos(th) * np.cos(ph)], axis=-1)

    def compute(self, inputs, outputs):
        mass = inputs["mass"][0]
        check_range(
            "mass",
            mass,
            lower=0.0,
            lower_open=True,
            units="kg",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        force, moment = inputs["force"], inputs["moment"]
        inertia = inputs["inertia"]
        inv = self._inverse_inertia(inertia)
        omega, vel = inputs["angular_rate"], inputs["velocity"]
        n = inputs["load_factor"][:, None]

        outputs["linear_acceleration"] = (
            force / mass + GRAVITY * n * self._gravity_direction(inputs) - np.cross(omega, vel)
        )
        moment_cg = moment - np.cross(inputs["cg"], force)
        gyro = np.cross(omega, omega @ inertia.T)
        outputs["angular_acceleration"] = (moment_cg - gyro) @ inv.T

    def compute_partials(self, inputs, partials):
        nn = self.options["num_nodes"]
        mass = inputs["mass"][0]
        force = inputs["force"]
        inertia = inputs["inertia"]
        inv = self._inverse_inertia(inertia)
        omega, vel = inputs["angular_rate"], inputs["velocity"]
        ph, th = inputs["roll"], inputs["pitch"]
        n = inputs["load_factor"]
        lin, ang = "linear_acceleration", "angular_acceleration"

        partials[lin, "force"] = np.full(3 * nn, 1.0 / mass)
        partials[lin, "mass"] = (-force / mass**2).ravel()
        g_n = GRAVITY * n
        partials[lin, "pitch"] = (
            g_n[:, None]
            * np.stack([-np.cos(th), -np.sin(th) * np.sin(ph), -np.sin(th) * np.cos(ph)], axis=-1)
        ).ravel()
        partials[lin, "roll"] = (
            g_n[:, None]
            * np.stack([0.0 * th, np.cos(th) * np.cos(ph), -np.cos(th) * np.sin(ph)], axis=-1)
        ).ravel()
        partials[lin, "load_factor"] = (GRAVITY * self._gravity_direction(inputs)).ravel()
        partials[lin, "velocity"] = -_skew(omega).ravel()
        partials[lin, "angular_rate"] = _skew(vel).ravel()

        moment_cg = inputs["moment"] - np.cross(inputs["cg"], force)
        i_omega = omega @ inertia.T
        omega_dot = (moment_cg - np.cross(omega, i_omega)) @ inv.T
        inv_b = np.broadcast_to(inv, (nn, 3, 3))
        partials[ang, "moment"] = inv_b.ravel()
        partials[ang, "force"] = np.broadcast_to(-inv @ _skew(inputs["cg"]), (nn, 3, 3)).ravel()
        partials[ang, "cg"] = (inv @ _skew(force)).ravel()
        dgyro = _skew(omega) @ inertia - _skew(i_omega)
        partials[ang, "angular_rate"] = (-inv @ dgyro).ravel()
        # d omega_dot / d I_kl = -inv[:, k] omega_dot_l - (inv skew(omega))[:, k] omega_l
        inv_skew = inv @ _skew(omega)
        d_inertia = (
            -inv[None, :, :, None] * omega_dot[:, None, None, :]
            - inv_skew[:, :, :, None] * omega[:, None, None, :]
        )
        partials[ang, "inertia"] = d_inertia.reshape(nn, 3, 9).ravel()
