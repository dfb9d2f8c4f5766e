"""Rotor disk frames in the body frame: freestream velocity at each rotor, hub loads to the body.

Body frame x forward, y right, z down, origin at the fuselage nose (docs
getting_started 'Conventions'). Each rotor's disk frame (docs theory/rotors 'Stations and disk
frame'):

- n = thrust axis (unit; (0, 0, -1) for a lift rotor, (1, 0, 0) for the pusher);
- e_y = the body y axis projected onto the disk plane, normalised;
- e_x = n x e_y (forward for a lift rotor, down for the pusher);

so (e_x, e_y, -n) is right-handed (for a lift rotor it is the body frame).

A rotor spins with angular velocity spin_direction * Omega * n (spin_direction +1:
right-handed about the thrust axis). :class:`RotorVelocityComp` resolves the vehicle velocity in
each disk frame (inputs of BEM and Pitt–Peters); :class:`HubLoadsComp` turns each rotor's thrust,
torque and (edgewise) in-plane forces and hub moments into body-frame forces and moments about a
reference point, summed over the rotors for trim.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.geometry.blade import per_rotor
from lpc_mdo.core.checks import check_choice


def rotor_frames(thrust_axis, owner=""):
    """
    Disk frames (e_x, e_y, n) of each rotor from its thrust axis.

    Parameters
    ----------
    thrust_axis : array_like, (num_rotors, 3)
        Thrust directions in the body frame (normalised here).
    owner : str
        Prefix of the error message.

    Returns
    -------
    ndarray, (num_rotors, 3, 3)
        frames[i, l] is e_x (l = 0), e_y (l = 1) or n (l = 2) of rotor i.

    Raises
    ------
    ValueError
        If an axis is not finite, has zero length or lies along the body y axis.
    """
    where = f"{owner}: " if owner else ""
    axis = np.asarray(thrust_axis, dtype=float)
    if axis.ndim != 2 or axis.shape[1] != 3:
        raise ValueError(
            f"{where}option 'thrust_axis' has shape {axis.shape}; expected (num_rotors, 3)."
        )
    length = np.linalg.norm(axis, axis=1)
    bad = ~np.isfinite(length) | (length < 1e-12)
    if np.any(bad):
        raise ValueError(
            f"{where}option 'thrust_axis' rows {np.flatnonzero(bad).tolist()} = "
            f"{axis[bad].tolist()}; allowed: finite, non-zero vectors."
        )
    n = axis / length[:, None]
    y = np.array([0.0, 1.0, 0.0])
    e_y = y - n[:, 1:2] * n
    norm_y = np.linalg.norm(e_y, axis=1)
    bad = norm_y < 1e-6
    if np.any(bad):
        raise ValueError(
            f"{where}option 'thrust_axis' rows {np.flatnonzero(bad).tolist()} = "
            f"{axis[bad].tolist()} lie along the body y axis; allowed: an angle of "
            "more than 1e-6 rad from it (the disk frame is undefined)."
        )
    e_y /= norm_y[:, None]
    e_x = np.cross(n, e_y)
    return np.stack([e_x, e_y, n], axis=1)


def _skew(v):
    """Cross-product matrices: _skew(v) @ x = v x x, for v (..., 3)."""
    s = np.zeros(v.shape + (3,), dtype=v.dtype)
    s[..., 0, 1], s[..., 0, 2] = -v[..., 2], v[..., 1]
    s[..., 1, 0], s[..., 1, 2] = v[..., 2], -v[..., 0]
    s[..., 2, 0], s[..., 2, 1] = -v[..., 1], v[..., 0]
    return s


def _declare_frame_options(options):
    options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
    options.declare(
        "num_nodes",
        default=1,
        types=int,
        lower=1,
        desc="Number of operating points (flight conditions)",
    )
    options.declare(
        "thrust_axis",
        default=None,
        types=(list, tuple, np.ndarray),
        allow_none=True,
        desc="Thrust direction of each rotor in the body frame (num_rotors, 3); "
        "None: (0, 0, -1) for every rotor (lift rotors)",
    )


def _frames(comp):
    nr = comp.options["num_rotors"]
    axis = comp.options["thrust_axis"]
    if axis is None:
        axis = np.tile([0.0, 0.0, -1.0], (nr, 1))
    axis = np.asarray(axis, dtype=float)
    if axis.shape != (nr, 3):
        raise ValueError(
            f"{comp.msginfo}: option 'thrust_axis' has shape {axis.shape}; expected "
            f"(num_rotors, 3) = ({nr}, 3)."
        )
    return rotor_frames(axis, comp.msginfo)


class RotorVelocityComp(om.ExplicitComponent):
    """
    Freestream velocity of each rotor resolved in its disk frame.

    See docs theory/rotors 'Stations and disk frame'.

    V_x = V . n (axial, positive through the disk as for a propeller moving forward, i.e. in
    climb for a lift rotor), and the in-plane components (V . e_x, V . e_y). V is the vehicle's
    velocity relative to the air in body axes (u, v, w), the same at every hub (quasi-steady
    conditions without body rates). The map is linear with constant partials.

    Inputs
    ------
    velocity : float, (num_nodes, 3), m/s
        Body-axis velocity (u, v, w) of the vehicle relative to the air.

    Outputs
    -------
    axial_velocity : float, (num_rotors, num_nodes), m/s
        V . n.
    inplane_velocity : float, (num_rotors, num_nodes, 2), m/s
        (V . e_x, V . e_y).

    Options
    -------
    num_rotors, num_nodes : int
        Array sizes (>= 1).
    thrust_axis : array (num_rotors, 3) or None
        Thrust directions in the body frame (normalised); None: (0, 0, -1) for every rotor.
    """

    def initialize(self):
        _declare_frame_options(self.options)

    def setup(self):
        nr, nn = self.options["num_rotors"], self.options["num_nodes"]
        self._frames = _frames(self)
        self.add_input(
            "velocity",
            val=np.zeros((nn, 3)),
            units="m/s",
            desc="Body-axis velocity (u, v, w) relative to the air",
        )
        self.add_output(
            "axial_velocity",
            val=np.zeros((nr, nn)),
            units="m/s",
            desc="Freestream velocity along each thrust axis",
        )
        self.add_output(
            "inplane_velocity",
            val=np.zeros((nr, nn, 2)),
            units="m/s",
            desc="Freestream velocity along each disk e_x and e_y",
        )
        i, j, m = np.meshgrid(np.arange(nr), np.arange(nn), np.arange(3), indexing="ij")
        self.declare_partials(
            "axial_velocity",
            "velocity",
            rows=(i * nn + j).ravel(),
            cols=(j * 3 + m).ravel(),
            val=self._frames[i, 2, m].ravel(),
        )
        i, j, ll, m = np.meshgrid(
            np.arange(nr), np.arange(nn), np.arange(2), np.arange(3), indexing="ij"
        )
        self.declare_partials(
            "inplane_velocity",
            "velocity",
            rows=((i * nn + j) * 2 + ll).ravel(),
            cols=(j * 3 + m).ravel(),
            val=self._frames[i, ll, m].ravel(),
        )

    def compute(self, inputs, outputs):
        v = inputs["velocity"]
        outputs["axial_velocity"] = np.einsum("jm,im->ij", v, self._frames[:, 2])
        outputs["inplane_velocity"] = np.einsum("jm,ilm->ijl", v, self._frames[:, :2])


class HubLoadsComp(om.ExplicitComponent):
    """
    Each rotor's force and moment in the body frame about a reference point, and their sums.

    With the disk frame (e_x, e_y, n) of each rotor (module docstring), spin direction s and
    hub position p:

    - F = T n + H_x e_x + H_y e_y
    - M = (p - p_ref) x F - s Q n + M_x e_x + M_y e_y

    T is the thrust along n, Q the shaft torque the rotor needs (the air's torque on the rotor,
    transmitted to the airframe, is -s Q n), and (H_x, H_y), (M_x, M_y) are the optional in-plane
    hub force and hub moment components along e_x and e_y (edgewise models such as Pitt–Peters;
    give signed components, e.g. an H-force opposing an edgewise velocity along +e_x has
    H_x < 0). The sums over the rotors are what trim needs (reference point default: the body
    origin, as the equations of motion expect). Analytic sparse partials.

    Inputs
    ------
    thrust : float, (num_rotors, num_nodes), N
    torque : float, (num_rotors, num_nodes), N*m
    inplane_force : float, (num_rotors, num_nodes, 2), N
        (H_x, H_y); only with option inplane_loads.
    hub_moment : float, (num_rotors, num_nodes, 2), N*m
        (M_x, M_y); only with option inplane_loads.
    hub_position : float, (num_rotors, 3), m
        Hub centres, body frame.
    reference_point : float, (3,), m
        Point the moments are taken about, body frame.

    Outputs
    -------
    force : float, (num_rotors, num_nodes, 3), N
        Each rotor's force, body frame.
    moment : float, (num_rotors, num_nodes, 3), N*m
        Each rotor's moment about the reference point, body frame.
    total_force : float, (num_nodes, 3), N
        Sum of the rotor forces.
    total_moment : float, (num_nodes, 3), N*m
        Sum of the rotor moments about the reference point.

    Options
    -------
    num_rotors, num_nodes : int
        Array sizes (>= 1).
    thrust_axis : array (num_rotors, 3) or None
        Thrust directions (normalised); None: (0, 0, -1) for every rotor.
    spin_direction : int or sequence of int
        +1 (right-handed about the thrust axis) or -1 per rotor. Default 1.
    inplane_loads : bool
        Add the inputs inplane_force and hub_moment. Default False (axial BEM).
    """

    def initialize(self):
        _declare_frame_options(self.options)
        self.options.declare(
            "spin_direction",
            default=1,
            types=(int, list, tuple, np.ndarray),
            desc="+1 (right-handed about the thrust axis) or -1, per rotor",
        )
        self.options.declare(
            "inplane_loads",
            default=False,
            types=bool,
            desc="Add in-plane hub force and hub moment inputs (edgewise models)",
        )

    def setup(self):
        nr, nn = self.options["num_rotors"], self.options["num_nodes"]
        self._frames = _frames(self)
        spin = per_rotor(
            self.options["spin_direction"],
            nr,
            "spin_direction",
            kind=int,
            lower=-1,
            upper=1,
            owner=self.msginfo,
        )
        for i, s in enumerate(spin.tolist()):
            check_choice(f"spin_direction[{i}]", s, (1, -1), where=self.msginfo)
        self._spin = spin
        inplane = self.options["inplane_loads"]

        self.add_input("thrust", val=np.zeros((nr, nn)), units="N", desc="Rotor thrust")
        self.add_input("torque", val=np.zeros((nr, nn)), units="N*m", desc="Rotor shaft torque")
        if inplane:
            self.add_input(
                "inplane_force",
                val=np.zeros((nr, nn, 2)),
                units="N",
                desc="In-plane hub force along the disk e_x and e_y",
            )
            self.add_input(
                "hub_moment",
                val=np.zeros((nr, nn, 2)),
                units="N*m",
                desc="Hub moment about the disk e_x and e_y",
            )
        self.add_input(
            "hub_position", val=np.zeros((nr, 3)), units="m", desc="Hub centres, body frame"
        )
        self.add_input(
            "reference_point", val=np.zeros(3), units="m", desc="Moment reference point, body frame"
        )
        self.add_output(
            "force", val=np.zeros((nr, nn, 3)), units="N", desc="Rotor force, body frame"
        )
        self.add_output(
            "moment",
            val=np.zeros((nr, nn, 3)),
            units="N*m",
            desc="Rotor moment about the reference point, body frame",
        )
        self.add_output(
            "total_force",
            val=np.zeros((nn, 3)),
            units="N",
            desc="Sum of the rotor forces, body frame",
        )
        self.add_output(
            "total_moment",
            val=np.zeros((nn, 3)),
            units="N*m",
            desc="Sum of the rotor moments about the reference point, body frame",
        )

        fr = self._frames
        grid = np.meshgrid(np.arange(nr), np.arange(nn), np.arange(3), indexing="ij")
        i, j, m = (g.ravel() for g in grid)
        row_rot, row_tot = (i * nn + j) * 3 + m, j * 3 + m
        ij = i * nn + j
        # Force (and total force) wrt thrust, torque: one entry per (i, j, m).
        for of, rows in (("force", row_rot), ("total_force", row_tot)):
            self.declare_partials(of, "thrust", rows=rows, cols=ij, val=fr[i, 2, m])
        for of, rows in (("moment", row_rot), ("total_moment", row_tot)):
            self.declare_partials(of, "thrust", rows=rows, cols=ij)
            self.declare_partials(
                of, "torque", rows=rows, cols=ij, val=-self._spin[i] * fr[i, 2, m]
            )
        # wrt in-plane loads and hub positions: (i, j, m, l) with l = 0..1 or k = 0..2.
        grid = np.meshgrid(np.arange(nr), np.arange(nn), np.arange(3), np.arange(2), indexing="ij")
        i2, j2, m2, l2 = (g.ravel() for g in grid)
        rows2 = {"rot": (i2 * nn + j2) * 3 + m2, "tot": j2 * 3 + m2}
        cols2 = (i2 * nn + j2) * 2 + l2
        self._idx2 = (i2, m2, l2)
        if inplane:
            for of, key in (("force", "rot"), ("total_force", "tot")):
                self.declare_partials(
                    of, "inplane_force", rows=rows2[key], cols=cols2, val=fr[i2, l2, m2]
                )
            for of, key in (("moment", "rot"), ("total_moment", "tot")):
                self.declare_partials(of, "inplane_force", rows=rows2[key], cols=cols2)
                self.declare_partials(
                    of, "hub_moment", rows=rows2[key], cols=cols2, val=fr[i2, l2, m2]
                )
        grid = np.meshgrid(np.arange(nr), np.arange(nn), np.arange(3), np.arange(3), indexing="ij")
        i3, j3, m3, k3 = (g.ravel() for g in grid)
        self.declare_partials(
            "moment", "hub_position", rows=(i3 * nn + j3) * 3 + m3, cols=i3 * 3 + k3
        )
        self.declare_partials("total_moment", "hub_position", rows=j3 * 3 + m3, cols=i3 * 3 + k3)
        self.declare_partials("moment", "reference_point", rows=(i3 * nn + j3) * 3 + m3, cols=k3)
        j4, m4, k4 = (
            g.ravel() for g in np.meshgrid(np.arange(nn), np.arange(3), np.arange(3), indexing="ij")
        )
        self.declare_partials("total_moment", "reference_point", rows=j4 * 3 + m4, cols=k4)

    def _forces(self, inputs):
        fr = self._frames
        force = inputs["thrust"][:, :, None] * fr[:, None, 2, :]
        hub = -(self._spin[:, None, None] * inputs["torque"][:, :, None]) * fr[:, None, 2, :]
        if self.options["inplane_loads"]:
            force = force + np.einsum("ijl,ilm->ijm", inputs["inplane_force"], fr[:, :2])
            hub = hub + np.einsum("ijl,ilm->ijm", inputs["hub_moment"], fr[:, :2])
        arm = inputs["hub_position"] - inputs["reference_point"]
        return force, hub, arm

    def compute(self, inputs, outputs):
        force, hub, arm = self._forces(inputs)
        moment = np.cross(np.broadcast_to(arm[:, None, :], force.shape), force) + hub
        outputs["force"] = force
        outputs["moment"] = moment
        outputs["total_force"] = force.sum(axis=0)
        outputs["total_moment"] = moment.sum(axis=0)

    def compute_partials(self, inputs, partials):
        force, _, arm = self._forces(inputs)
        nr, nn = self.options["num_rotors"], self.options["num_nodes"]
        fr = self._frames
        # d(arm x (T n))/dT = arm x n, per (i, m), repeated over nodes.
        arm_n = np.broadcast_to(np.cross(arm, fr[:, 2])[:, None, :], (nr, nn, 3)).ravel()
        partials["moment", "thrust"] = arm_n
        partials["total_moment", "thrust"] = arm_n
        if self.options["inplane_loads"]:
            i2, m2, l2 = self._idx2
            arm_e = np.cross(arm[:, None, :], fr[:, :2])  # (nr, 2, 3): arm x e_l
            val = np.broadcast_to(np.transpose(arm_e, (0, 2, 1))[:, None], (nr, nn, 3, 2)).ravel()
            partials["moment", "inplane_force"] = val
            partials["total_moment", "inplane_force"] = val
        # d(arm x F)/d arm = -skew(F); arm = hub - reference.
        skew_f = _skew(force)  # (nr, nn, 3, 3)
        partials["moment", "hub_position"] = -skew_f.ravel()
        partials["total_moment", "hub_position"] = -skew_f.ravel()
        partials["moment", "reference_point"] = skew_f.ravel()
        partials["total_moment", "reference_point"] = skew_f.sum(axis=0).ravel()
