"""Hover control reserve: roll, pitch and yaw acceleration the rotors' torque headroom allows."""

import numpy as np
import openmdao.api as om

#: Axes of :class:`ControlReserveComp`'s output, in order.
CONTROL_AXES = ("roll", "pitch", "yaw")


def _cross_matrix(u):
    """Return [u]x, (..., 3, 3), with [u]x v = u x v."""
    z = np.zeros(u.shape[:-1], dtype=u.dtype)
    return np.stack(
        [
            np.stack([z, -u[..., 2], u[..., 1]], axis=-1),
            np.stack([u[..., 2], z, -u[..., 0]], axis=-1),
            np.stack([-u[..., 1], u[..., 0], z], axis=-1),
        ],
        axis=-2,
    )


class ControlReserveComp(om.ExplicitComponent):
    """
    Angular acceleration about each body axis that the rotors can add at a trimmed hover point.

    See docs theory/dynamics 'Hover control reserve'. At the trimmed point rotor i produces
    thrust T_i along its axis n_i and shaft torque Q_i. A fixed-pitch, speed-controlled rotor in
    hover has thrust and torque coefficients that do not change with its speed, so along its
    speed line T_i/Q_i is constant: the torque its motor can still add maps to thrust as
    dT = (T_i/Q_i) dQ. With the motor's torque margin m_i = T_pk/T_em - 1 (the peak torque
    over the operating EM torque) and the motor efficiency taken as constant over the step, the
    rotor can add h_up = m_i T_i of thrust and shed at most h_down = T_i (down to zero thrust).

    A thrust increment dT_i changes the vertical force by -n_iz dT_i and the moment about the
    cg by b_i dT_i, b_i = (p_i - cg) x n_i - s_i (Q_i/T_i) n_i (the second term the torque
    reaction of a rotor of spin s_i, as :class:`~lpc_mdo.components.rotor.hub_loads.HubLoadsComp`
    has it). With B = [-n_z; b] (4 x num_rotors), an angular acceleration alpha about body axis
    a needs the moment alpha I e_a (Euler's equation at zero rates, I the inertia about the cg)
    and no change of the vertical force; the minimum-norm allocation is
    dT = B^T (B B^T)^-1 [0; I e_a] alpha = g_a alpha. The acceleration available along it, in
    either sense, is the largest alpha at which every rotor stays within its headroom:

        alpha_a = min over i, j of h_ij / abs(g_ia),   j in {up, down},

    aggregated smoothly by KS (paper eq. 7) on h/(abs(g) s_a) with the scale s_a of option
    ``acceleration_scale``, so alpha_a is at most ln(2 num_rotors)/rho s_a below the exact
    minimum. The allocation is a sufficient one: another allocation may reach more where one
    rotor saturates first (the attainable set is a polytope), so alpha_a is a lower bound of the
    acceleration available about that axis alone. Rotors with abs(g_ia) below 1e-12 of the
    largest do not take part in that axis.

    Partials: analytic (the derivative of the pseudo-inverse allocation by the adjoint of
    B B^T, chained to thrust, torque, margin, hub positions, cg and inertia).

    Inputs
    ------
    thrust : (num_rotors, 1), N
        Thrust of each running rotor along its axis; must be > 0.
    torque : (num_rotors, 1), N*m
        Shaft torque of each rotor.
    torque_margin : (num_rotors, 1)
        Its motor's torque margin T_pk/T_em - 1.
    hub_position : (num_rotors, 3), m
    cg : (3,), m
    inertia : (3, 3), kg*m**2
        Inertia tensor about the cg.

    Outputs
    -------
    control_acceleration : (3,), rad/s**2
        Roll, pitch and yaw acceleration available (:data:`CONTROL_AXES`).

    Options
    -------
    spin_direction : sequence of int
        +1 or -1 per rotor (rotation along or against its thrust axis).
    thrust_axis : sequence of 3 float or (num_rotors, 3)
        Unit thrust axis, body frame; default (0, 0, -1), upwards.
    acceleration_scale : sequence of 3 float
        Scale s_a of the KS aggregation per axis, rad/s**2 (the required accelerations).
    ks_rho : float
        KS parameter on the dimensionless ratios.

    Raises
    ------
    om.AnalysisError
        When a thrust is not > 0 or the rotors cannot produce independent vertical force, roll,
        pitch and yaw moments (B B^T singular).
    """

    def initialize(self):
        self.options.declare("spin_direction", desc="+1/-1 per rotor")
        self.options.declare(
            "thrust_axis", default=(0.0, 0.0, -1.0), desc="unit thrust axis per rotor, body frame"
        )
        self.options.declare(
            "acceleration_scale", default=(1.0, 1.0, 1.0), desc="KS scale per axis, rad/s**2"
        )
        self.options.declare("ks_rho", default=50.0, types=float, lower=1e-6, desc="KS parameter")

    def setup(self):
        spin = np.asarray(self.options["spin_direction"], dtype=float)
        if spin.ndim != 1 or not np.all(np.abs(spin) == 1.0):
            raise ValueError(
                f"{self.msginfo}: option 'spin_direction' = {spin.tolist()}; allowed: +-1 each"
            )
        n = spin.size
        axis = np.broadcast_to(np.asarray(self.options["thrust_axis"], dtype=float), (n, 3))
        norm = np.linalg.norm(axis, axis=1)
        if np.any(norm < 1e-9):
            raise ValueError(f"{self.msginfo}: option 'thrust_axis' has a zero vector")
        scale = np.asarray(self.options["acceleration_scale"], dtype=float)
        if scale.shape != (3,) or np.any(scale <= 0.0):
            raise ValueError(
                f"{self.msginfo}: option 'acceleration_scale' = {scale.tolist()}; allowed: "
                f"3 numbers > 0"
            )
        self._spin, self._axis, self._scale = spin, axis / norm[:, None], scale
        self._axis_cross = _cross_matrix(self._axis)

        self.add_input("thrust", np.ones((n, 1)), units="N", desc="rotor thrust")
        self.add_input("torque", np.ones((n, 1)), units="N*m", desc="rotor shaft torque")
        self.add_input("torque_margin", np.zeros((n, 1)), desc="motor torque margin")
        self.add_input("hub_position", np.zeros((n, 3)), units="m", desc="rotor hubs")
        self.add_input("cg", np.zeros(3), units="m", desc="centre of gravity")
        self.add_input("inertia", np.eye(3), units="kg*m**2", desc="inertia about the cg")
        self.add_output(
            "control_acceleration",
            np.zeros(3),
            units="rad/s**2",
            desc="roll, pitch, yaw acceleration available at the trimmed point",
        )
        for name in ("thrust", "torque", "torque_margin", "hub_position", "cg"):
            self.declare_partials("control_acceleration", name)
        # Axis a reads column a of the inertia: entries (k, a), flat 3 k + a.
        self.declare_partials(
            "control_acceleration",
            "inertia",
            rows=np.repeat(np.arange(3), 3),
            cols=(3 * np.arange(3)[None, :] + np.arange(3)[:, None]).ravel(),
        )

    def _evaluate(self, inputs):
        """Allocation, ratios and KS weights (everything compute and compute_partials need)."""
        thrust = inputs["thrust"][:, 0]
        torque = inputs["torque"][:, 0]
        margin = inputs["torque_margin"][:, 0]
        if np.any(thrust.real <= 0.0):
            raise om.AnalysisError(
                f"{self.msginfo}: thrust = {thrust.real.tolist()} N; allowed: > 0 (a rotor's "
                f"torque-to-thrust ratio maps its torque headroom to thrust)"
            )
        kappa = torque / thrust
        arm = inputs["hub_position"] - inputs["cg"][None, :]
        moment = np.cross(arm, self._axis) - (self._spin * kappa)[:, None] * self._axis
        b = np.vstack([-self._axis[:, 2][None, :], moment.T])  # (4, n)
        gram = b @ b.T
        if np.linalg.cond(gram.real) > 1e12:
            raise om.AnalysisError(
                f"{self.msginfo}: the rotors cannot produce independent vertical force, roll, "
                f"pitch and yaw moments (B B^T singular); hub_position = "
                f"{inputs['hub_position'].real.tolist()} m"
            )
        gram_inv = np.linalg.inv(gram)
        demand = np.vstack([np.zeros((1, 3)), inputs["inertia"]])  # (4, 3): [0; I e_a]
        lam = gram_inv @ demand  # (4, 3)
        g = b.T @ lam  # (n, 3): thrust per rad/s**2 about each axis
        headroom = np.stack([margin * thrust, thrust], axis=1)  # (n, 2): up, down
        absg = np.where(g.real >= 0.0, g, -g)  # abs, complex-step safe
        active = absg.real > 1e-12 * np.max(absg.real, axis=0, keepdims=True)
        safe = np.where(active, absg, 1.0)
        # ratio[a, i, j] = h_ij / (abs(g_ia) s_a)
        ratio = headroom[None, :, :] / (safe.T[:, :, None] * self._scale[:, None, None])
        rho = self.options["ks_rho"]
        mask = np.repeat(active.T[:, :, None], 2, axis=2)
        low = np.min(np.where(mask, ratio.real, np.inf), axis=(1, 2))
        expo = np.where(mask, np.exp(-rho * (ratio - low[:, None, None])), 0.0)
        total = np.sum(expo, axis=(1, 2))
        ks = low - np.log(total) / rho
        return {
            "thrust": thrust,
            "torque": torque,
            "margin": margin,
            "b": b,
            "gram_inv": gram_inv,
            "lam": lam,
            "g": g,
            "safe": safe,
            "active": active,
            "headroom": headroom,
            "weights": expo / total[:, None, None],
            "ks": ks,
        }

    def compute(self, inputs, outputs):
        e = self._evaluate(inputs)
        outputs["control_acceleration"] = self._scale * e["ks"]

    def compute_partials(self, inputs, partials):
        e = self._evaluate(inputs)
        thrust, torque, margin = e["thrust"], e["torque"], e["margin"]
        b, gram_inv, lam, g = e["b"], e["gram_inv"], e["lam"], e["g"]
        w, h, safe, active = e["weights"], e["headroom"], e["safe"], e["active"]
        n = thrust.size
        # d alpha_a / d h_ij = w_aij / abs(g_ia);  d alpha_a / d g_ia = -sum_j w_aij h_ij/(abs(g) g)
        d_h = np.where(active.T[:, :, None], w / safe.T[:, :, None], 0.0)  # (3, n, 2)
        gsafe = np.where(active, g, 1.0)
        d_g = np.where(active.T, -np.sum(w * h[None], axis=2) / (safe.T * gsafe.T), 0.0)  # (3, n)
        # Adjoint of g = B^T G^-1 d: d alpha/d B[k, i] = lam_k v_i - wt_k g_i,
        # wt = G^-1 B gamma, v = gamma - B^T wt; d alpha / d d = wt.
        wt = (gram_inv @ (b @ d_g.T)).T  # (3, 4)
        v = d_g - wt @ b  # (3, n)
        d_b = lam.T[:, :, None] * v[:, None, :] - wt[:, :, None] * g.T[:, None, :]  # (3, 4, n)
        d_moment = np.transpose(d_b[:, 1:, :], (0, 2, 1))  # (3, n, 3): d alpha / d b_i
        # b_i = (p_i - cg) x n_i - s_i kappa_i n_i: d/d arm = [n]x^T... d(arm x n)/d arm = -[n]x.
        d_arm = -np.einsum("ank,nkj->anj", d_moment, self._axis_cross)
        d_kappa = -np.einsum("ank,nk->an", d_moment, self._spin[:, None] * self._axis)
        partials["control_acceleration", "thrust"] = (
            d_h[:, :, 0] * margin + d_h[:, :, 1] - d_kappa * torque / thrust**2
        )
        partials["control_acceleration", "torque"] = d_kappa / thrust
        partials["control_acceleration", "torque_margin"] = d_h[:, :, 0] * thrust
        partials["control_acceleration", "hub_position"] = d_arm.reshape(3, 3 * n)
        partials["control_acceleration", "cg"] = -np.sum(d_arm, axis=1)
        partials["control_acceleration", "inertia"] = wt[:, 1:].ravel()
