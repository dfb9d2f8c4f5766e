"""Relative wind seen by the vortex lattice: wind axes and the velocities at the panel points."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import cross, skew
from lpc_mdo.core.checks import check_range


class VLMFreestreamComp(om.ExplicitComponent):
    """
    Free stream in body axes from speed, angle of attack, sideslip and body rates.

    The vehicle moves with V_b = V (cos a cos b, sin b, sin a cos b) and rotates with the body
    rates w about ``rotation_center`` (body frame x forward, y right, z down). The air velocity
    relative to a point r of the vehicle is (docs theory/aerodynamics 'Lattice', the negative of the
    mesh velocity)

        v(r) = V e_D - w x (r - r_c),   e_D = -(cos a cos b, sin b, sin a cos b).

    Wind axes: e_D (drag, along the relative wind; also the wake direction, docs theory/aerodynamics
    'Wake'), e_L = (sin a, 0, -cos a) (lift, up, normal to e_D in the body x-z plane) and e_Y =
    (-cos a sin b, cos b, -sin a sin b) (side force, to the right).

    Inputs
    ------
    speed : float, (nn,), m/s
        Airspeed V >= 0 (0 is allowed: no circulation, wake along the alpha, beta direction).
    angle_of_attack : float, (nn,), rad
    sideslip_angle : float, (nn,), rad
        Positive with the relative wind from the right (V_b,y > 0).
    angular_velocity : float, (nn, 3), rad/s
        Body rates (p, q, r).
    rotation_center : float, (3,), m
        Point about which the body rates act (the cg).
    collocation_points : float, (np, 3), m
    force_points : float, (np, 3), m

    Outputs
    -------
    freestream_direction : float, (nn, 3)
        e_D, unit vector along the relative wind (wake direction).
    lift_direction : float, (nn, 3)
    side_direction : float, (nn, 3)
    collocation_velocities : float, (nn, np, 3), m/s
    force_point_velocities : float, (nn, np, 3), m/s

    Options
    -------
    num_nodes : int
        Flight conditions nn.
    num_panels : int
        Panels np of the lattice.
    """

    def initialize(self):
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )
        self.options.declare("num_panels", types=int, lower=1, desc="number of lattice panels")

    def setup(self):
        nn, npn = self.options["num_nodes"], self.options["num_panels"]
        self.add_input("speed", np.zeros(nn), units="m/s", desc="airspeed")
        self.add_input("angle_of_attack", np.zeros(nn), units="rad", desc="angle of attack")
        self.add_input(
            "sideslip_angle",
            np.zeros(nn),
            units="rad",
            desc="sideslip angle, positive with the wind from the right",
        )
        self.add_input(
            "angular_velocity", np.zeros((nn, 3)), units="rad/s", desc="body rates (p, q, r)"
        )
        self.add_input(
            "rotation_center", np.zeros(3), units="m", desc="point about which the body rates act"
        )
        self.add_input(
            "collocation_points", np.zeros((npn, 3)), units="m", desc="collocation points"
        )
        self.add_input("force_points", np.zeros((npn, 3)), units="m", desc="force points")

        for name, desc in (
            ("freestream_direction", "unit vector along the relative wind"),
            ("lift_direction", "unit lift direction (wind axes)"),
            ("side_direction", "unit side-force direction (wind axes)"),
        ):
            self.add_output(name, np.zeros((nn, 3)), units=None, desc=desc)
        self.add_output(
            "collocation_velocities",
            np.zeros((nn, npn, 3)),
            units="m/s",
            desc="relative wind at the collocation points",
        )
        self.add_output(
            "force_point_velocities",
            np.zeros((nn, npn, 3)),
            units="m/s",
            desc="relative wind at the force points",
        )

        node3 = np.repeat(np.arange(nn), 3)
        for name in ("freestream_direction", "lift_direction", "side_direction"):
            wrt = (
                "angle_of_attack"
                if name == "lift_direction"
                else ["angle_of_attack", "sideslip_angle"]
            )
            self.declare_partials(name, wrt, rows=np.arange(3 * nn), cols=node3)
        # (n, k, c) rows
        rows_nk = np.arange(nn * npn * 3)
        node_of_row = np.repeat(np.arange(nn), npn * 3)
        rows_blk = np.repeat(rows_nk, 3)  # (n, k, c, d)
        n_blk = np.repeat(node_of_row, 3)
        d_blk = np.tile(np.arange(3), nn * npn * 3)
        k_blk = np.tile(np.repeat(np.arange(npn), 9), nn)
        for out, pts in (
            ("collocation_velocities", "collocation_points"),
            ("force_point_velocities", "force_points"),
        ):
            self.declare_partials(
                out, ["speed", "angle_of_attack", "sideslip_angle"], rows=rows_nk, cols=node_of_row
            )
            self.declare_partials(out, "angular_velocity", rows=rows_blk, cols=3 * n_blk + d_blk)
            self.declare_partials(out, "rotation_center", rows=rows_blk, cols=d_blk)
            self.declare_partials(out, pts, rows=rows_blk, cols=3 * k_blk + d_blk)

    @staticmethod
    def _axes(alpha, beta):
        ca, sa, cb, sb = np.cos(alpha), np.sin(alpha), np.cos(beta), np.sin(beta)
        zero = np.zeros_like(alpha)
        e_d = -np.stack([ca * cb, sb, sa * cb], axis=-1)
        e_l = np.stack([sa, zero, -ca], axis=-1)
        e_y = np.stack([-ca * sb, cb, -sa * sb], axis=-1)
        # d/dalpha and d/dbeta
        de_d = (
            -np.stack([-sa * cb, zero, ca * cb], axis=-1),
            -np.stack([-ca * sb, cb, -sa * sb], axis=-1),
        )
        de_l = (np.stack([ca, zero, sa], axis=-1), np.stack([zero, zero, zero], axis=-1))
        de_y = (
            np.stack([sa * sb, zero, -ca * sb], axis=-1),
            np.stack([-ca * cb, -sb, -sa * cb], axis=-1),
        )
        return (e_d, e_l, e_y), (de_d, de_l, de_y)

    def compute(self, inputs, outputs):
        speed = inputs["speed"]
        check_range(
            "speed", speed, lower=0.0, units="m/s", error=om.AnalysisError, where=self.msginfo
        )
        (e_d, e_l, e_y), _ = self._axes(inputs["angle_of_attack"], inputs["sideslip_angle"])
        outputs["freestream_direction"] = e_d
        outputs["lift_direction"] = e_l
        outputs["side_direction"] = e_y
        omega = inputs["angular_velocity"][:, None, :]
        center = inputs["rotation_center"]
        uniform = (speed[:, None] * e_d)[:, None, :]
        for out, pts in (
            ("collocation_velocities", "collocation_points"),
            ("force_point_velocities", "force_points"),
        ):
            arm = (inputs[pts] - center)[None, :, :]
            outputs[out] = uniform - cross(omega, arm)

    def compute_partials(self, inputs, partials):
        nn, npn = self.options["num_nodes"], self.options["num_panels"]
        speed = inputs["speed"]
        (e_d, _, _), (de_d, de_l, de_y) = self._axes(
            inputs["angle_of_attack"], inputs["sideslip_angle"]
        )
        for name, de in (
            ("freestream_direction", de_d),
            ("lift_direction", de_l),
            ("side_direction", de_y),
        ):
            partials[name, "angle_of_attack"] = de[0].ravel()
            if name != "lift_direction":
                partials[name, "sideslip_angle"] = de[1].ravel()
        omega = inputs["angular_velocity"]
        center = inputs["rotation_center"]
        skew_w = np.broadcast_to(skew(omega)[:, None], (nn, npn, 3, 3))
        for out, pts in (
            ("collocation_velocities", "collocation_points"),
            ("force_point_velocities", "force_points"),
        ):
            arm = inputs[pts] - center
            partials[out, "speed"] = np.broadcast_to(e_d[:, None, :], (nn, npn, 3)).ravel()
            partials[out, "angle_of_attack"] = np.broadcast_to(
                (speed[:, None] * de_d[0])[:, None, :], (nn, npn, 3)
            ).ravel()
            partials[out, "sideslip_angle"] = np.broadcast_to(
                (speed[:, None] * de_d[1])[:, None, :], (nn, npn, 3)
            ).ravel()
            # v = ... + arm x omega
            partials[out, "angular_velocity"] = np.broadcast_to(
                skew(arm)[None], (nn, npn, 3, 3)
            ).ravel()
            partials[out, pts] = -skew_w.ravel()
            partials[out, "rotation_center"] = skew_w.ravel()
