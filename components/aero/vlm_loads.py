"""Total VLM loads: force and moment in body axes, lift, drag, side force and coefficients."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import skew
from lpc_mdo.core.checks import check_range
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY

#: Dynamic-pressure floor (Pa) of the coefficients, so that hover (V = 0) gives 0, not NaN.
Q_FLOOR = 1.0e-10


class VLMLoadsComp(om.ExplicitComponent):
    """
    Sum of the panel forces and their moments, projected on wind axes.

    With F_k the inviscid Kutta–Joukowski force and F_v,k the strip-theory profile drag of panel
    k, applied at its force point x_k (docs theory/aerodynamics 'Forces and induced drag'; paper eq.
    11):

    - force = sum_k (F_k + F_v,k);  moment = sum_k (x_k - x_ref) x (F_k + F_v,k)
    - lift = force . e_L; drag = force . e_D; side_force = force . e_Y;
      induced_drag = (sum_k F_k) . e_D (near field); profile_drag = (sum_k F_v,k) . e_D
    - CL, CDi, CD = lift, induced_drag, drag / (q S_ref), q = rho V^2/2 (+1e-10 Pa, so that a
      node with V = 0 gives zeros instead of NaN)

    Inputs
    ------
    panel_forces : float, (nn, np, 3), N
    viscous_panel_forces : float, (nn, np, 3), N
    force_points : float, (np, 3), m
    reference_point : float, (3,), m
        Moment reference point (e.g. the cg), body frame.
    freestream_direction, lift_direction, side_direction : float, (nn, 3)
        Wind axes e_D, e_L, e_Y.
    speed : float, (nn,), m/s
    density : float, (nn,), kg/m**3
    reference_area : float, scalar, m**2

    Outputs
    -------
    force : float, (nn, 3), N
        Total aerodynamic force of the lattice, body axes.
    moment : float, (nn, 3), N*m
        Moment about the reference point, body axes.
    lift, drag, induced_drag, profile_drag, side_force : float, (nn,), N
    CL, CDi, CD : float, (nn,)

    Options
    -------
    num_nodes : int
    num_panels : int
    """

    def initialize(self):
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )
        self.options.declare("num_panels", types=int, lower=1, desc="number of lattice panels")

    def setup(self):
        nn, npn = self.options["num_nodes"], self.options["num_panels"]
        self.add_input(
            "panel_forces", np.zeros((nn, npn, 3)), units="N", desc="inviscid panel forces"
        )
        self.add_input(
            "viscous_panel_forces",
            np.zeros((nn, npn, 3)),
            units="N",
            desc="profile-drag panel forces",
        )
        self.add_input("force_points", np.zeros((npn, 3)), units="m", desc="force points")
        self.add_input(
            "reference_point", np.zeros(3), units="m", desc="moment reference point, body frame"
        )
        self.add_input(
            "freestream_direction", np.zeros((nn, 3)), units=None, desc="drag direction e_D"
        )
        self.add_input("lift_direction", np.zeros((nn, 3)), units=None, desc="lift direction e_L")
        self.add_input(
            "side_direction", np.zeros((nn, 3)), units=None, desc="side-force direction e_Y"
        )
        self.add_input("speed", np.zeros(nn), units="m/s", desc="airspeed")
        self.add_input(
            "density", np.full(nn, SEA_LEVEL_DENSITY), units="kg/m**3", desc="air density"
        )
        self.add_input(
            "reference_area", 1.0, units="m**2", desc="reference area of the coefficients"
        )

        self.add_output(
            "force",
            np.zeros((nn, 3)),
            units="N",
            desc="total aerodynamic force of the lattice, body axes",
        )
        self.add_output(
            "moment",
            np.zeros((nn, 3)),
            units="N*m",
            desc="aerodynamic moment about the reference point, body axes",
        )
        for name, desc in (
            ("lift", "lift (force along e_L)"),
            ("drag", "drag (force along e_D), induced plus profile"),
            ("induced_drag", "near-field induced drag"),
            ("profile_drag", "strip-theory profile drag"),
            ("side_force", "side force (along e_Y)"),
        ):
            self.add_output(name, np.zeros(nn), units="N", desc=desc)
        for name, desc in (
            ("CL", "lift coefficient"),
            ("CDi", "induced-drag coefficient"),
            ("CD", "drag coefficient, induced plus profile"),
        ):
            self.add_output(name, np.zeros(nn), units=None, desc=desc)

        n_r, k_r, c_r = (
            a.ravel()
            for a in np.meshgrid(np.arange(nn), np.arange(npn), np.arange(3), indexing="ij")
        )
        col_f = (n_r * npn + k_r) * 3 + c_r
        forces = ["panel_forces", "viscous_panel_forces"]
        self.declare_partials("force", forces, rows=3 * n_r + c_r, cols=col_f, val=1.0)
        # moment (n, c) wrt F (n, k, d): skew(arm_k)[c, d]
        m_rows = np.repeat(3 * n_r + c_r, 3)
        m_cols = 3 * np.repeat(n_r * npn + k_r, 3) + np.tile(np.arange(3), nn * npn * 3)
        self.declare_partials("moment", forces, rows=m_rows, cols=m_cols)
        self.declare_partials(
            "moment",
            "force_points",
            rows=m_rows,
            cols=3 * np.repeat(k_r, 3) + np.tile(np.arange(3), nn * npn * 3),
        )
        rows33 = np.repeat(np.arange(3 * nn), 3)
        self.declare_partials(
            "moment", "reference_point", rows=rows33, cols=np.tile(np.arange(3), 3 * nn)
        )
        scalar_outputs = (
            "lift",
            "drag",
            "induced_drag",
            "profile_drag",
            "side_force",
            "CL",
            "CDi",
            "CD",
        )
        rows3 = np.repeat(np.arange(nn), 3)
        cols3 = np.arange(3 * nn)
        for name in scalar_outputs:
            wrt = {"induced_drag": forces[:1], "CDi": forces[:1], "profile_drag": forces[1:]}.get(
                name, forces
            )
            self.declare_partials(name, wrt, rows=n_r, cols=col_f)
        for name, axis in (
            ("lift", "lift_direction"),
            ("drag", "freestream_direction"),
            ("induced_drag", "freestream_direction"),
            ("profile_drag", "freestream_direction"),
            ("side_force", "side_direction"),
            ("CL", "lift_direction"),
            ("CDi", "freestream_direction"),
            ("CD", "freestream_direction"),
        ):
            self.declare_partials(name, axis, rows=rows3, cols=cols3)
        ar = np.arange(nn)
        self.declare_partials(["CL", "CDi", "CD"], ["speed", "density"], diagonal=True)
        self.declare_partials(
            ["CL", "CDi", "CD"], "reference_area", rows=ar, cols=np.zeros(nn, int)
        )

    def compute(self, inputs, outputs):
        check_range(
            "reference_area",
            inputs["reference_area"][0],
            lower=0.0,
            lower_open=True,
            units="m**2",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        f_inv = np.sum(inputs["panel_forces"], axis=1)
        f_vis = np.sum(inputs["viscous_panel_forces"], axis=1)
        total = f_inv + f_vis
        arm = inputs["force_points"] - inputs["reference_point"]
        per_panel = inputs["panel_forces"] + inputs["viscous_panel_forces"]
        outputs["force"] = total
        outputs["moment"] = np.einsum("kcd,nkd->nc", skew(arm), per_panel)
        e_d = inputs["freestream_direction"]
        outputs["lift"] = np.sum(total * inputs["lift_direction"], axis=1)
        outputs["drag"] = np.sum(total * e_d, axis=1)
        outputs["induced_drag"] = np.sum(f_inv * e_d, axis=1)
        outputs["profile_drag"] = np.sum(f_vis * e_d, axis=1)
        outputs["side_force"] = np.sum(total * inputs["side_direction"], axis=1)
        qs = self._qs(inputs)
        outputs["CL"] = outputs["lift"] / qs
        outputs["CDi"] = outputs["induced_drag"] / qs
        outputs["CD"] = outputs["drag"] / qs

    def _qs(self, inputs):
        return (0.5 * inputs["density"] * inputs["speed"] ** 2 + Q_FLOOR) * inputs["reference_area"]

    def compute_partials(self, inputs, partials):
        nn, npn = self.options["num_nodes"], self.options["num_panels"]
        f_inv = np.sum(inputs["panel_forces"], axis=1)
        f_vis = np.sum(inputs["viscous_panel_forces"], axis=1)
        total = f_inv + f_vis
        per_panel = inputs["panel_forces"] + inputs["viscous_panel_forces"]
        arm = inputs["force_points"] - inputs["reference_point"]
        # entries ordered (n, k, c, d): moment component c, force component d
        d_mom = np.broadcast_to(skew(arm)[None], (nn, npn, 3, 3))
        for name in ("panel_forces", "viscous_panel_forces"):
            partials["moment", name] = d_mom.ravel()
        # arm x F = -F x arm: d/darm = -skew(F)
        partials["moment", "force_points"] = (-skew(per_panel)).ravel()
        partials["moment", "reference_point"] = np.sum(skew(per_panel), axis=1).ravel()

        e_d, e_l, e_y = (
            inputs[n] for n in ("freestream_direction", "lift_direction", "side_direction")
        )
        qs = self._qs(inputs)

        def spread(axis):
            return np.broadcast_to(axis[:, None, :], (nn, npn, 3)).ravel()

        specs = {  # name: (axis wrt inviscid forces, axis wrt viscous forces, force, scale)
            "lift": (e_l, e_l, total, 1.0),
            "drag": (e_d, e_d, total, 1.0),
            "induced_drag": (e_d, None, f_inv, 1.0),
            "profile_drag": (None, e_d, f_vis, 1.0),
            "side_force": (e_y, e_y, total, 1.0),
            "CL": (e_l, e_l, total, 1.0 / qs[:, None]),
            "CDi": (e_d, None, f_inv, 1.0 / qs[:, None]),
            "CD": (e_d, e_d, total, 1.0 / qs[:, None]),
        }
        for name, (ax_inv, ax_vis, _, scale) in specs.items():
            if ax_inv is not None:
                partials[name, "panel_forces"] = spread(ax_inv * scale)
            if ax_vis is not None:
                partials[name, "viscous_panel_forces"] = spread(ax_vis * scale)
        axis_inputs = {
            "lift": "lift_direction",
            "drag": "freestream_direction",
            "induced_drag": "freestream_direction",
            "profile_drag": "freestream_direction",
            "side_force": "side_direction",
            "CL": "lift_direction",
            "CDi": "freestream_direction",
            "CD": "freestream_direction",
        }
        for name, (_, _, force, scale) in specs.items():
            partials[name, axis_inputs[name]] = (force * scale).ravel()
        rho, speed, area = inputs["density"], inputs["speed"], inputs["reference_area"]
        dims = {
            "CL": np.sum(total * e_l, axis=1),
            "CDi": np.sum(f_inv * e_d, axis=1),
            "CD": np.sum(total * e_d, axis=1),
        }
        for name, dim in dims.items():
            c = -dim / qs**2
            partials[name, "speed"] = c * rho * speed * area
            partials[name, "density"] = c * 0.5 * speed**2 * area
            partials[name, "reference_area"] = c * (0.5 * rho * speed**2 + Q_FLOOR)
