"""Observer position and rotor-observer geometry for the acoustic models."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.common import check_input_range
from lpc_mdo.core.constants import SEA_LEVEL_SPEED_OF_SOUND

# Small squared lengths/speeds under square roots (smooth, complex-step safe magnitudes):
# in-plane distance (m**2, as lsdo_acoustics) and in-plane speed ((m/s)**2).
_EPS_DISTANCE2 = 1.0e-12
_EPS_SPEED2 = 1.0e-12


def _cross_matrix(v):
    """Skew matrices [v]x of shape (..., 3, 3) with [v]x @ u = v x u."""
    zero = np.zeros_like(v[..., 0])
    return np.stack(
        [
            np.stack([zero, -v[..., 2], v[..., 1]], axis=-1),
            np.stack([v[..., 2], zero, -v[..., 0]], axis=-1),
            np.stack([-v[..., 1], v[..., 0], zero], axis=-1),
        ],
        axis=-2,
    )


class ObserverPositionComp(om.ExplicitComponent):
    """
    Observer positions in the body frame from distance, elevation and azimuth about the rotors.

    Observer j sits at ``observer_distance[j]`` from the centroid of the rotor hubs, at
    ``observer_elevation[j]`` below the body x-y plane (the lift-rotor plane in hover) and at
    ``observer_azimuth[j]`` about the body z axis measured from +x (forward) towards +y (right):

        x_o,j = mean_k(x_h,k) + d_j (cos e_j cos az_j, cos e_j sin az_j, sin e_j)
        (body frame, z down)

    Defaults are the paper's hover observer, 100 m away and 45 deg below the rotor plane
    (docs theory/acoustics 'Observer and constraint'), placed aft of the vehicle (azimuth 180 deg)
    as in the reference geometry (vehicle at (70.71, 0, -70.71) m seen from the observer).

    Inputs
    ------
    hub_position : float, (num_rotors, 3), m
        Rotor hub positions in the body frame (x forward, y right, z down, origin at the nose).
    observer_distance : float, (num_observers,), m
        Distance from the hub centroid to each observer (> 0). Default 100 m.
    observer_elevation : float, (num_observers,), rad
        Angle below the body x-y plane, in [-pi/2, pi/2]. Default 45 deg.
    observer_azimuth : float, (num_observers,), rad
        Azimuth from +x towards +y. Default 180 deg (aft).

    Outputs
    -------
    observer_position : float, (3,) or (num_observers, 3) if num_observers > 1, m
        Observer positions in the body frame.

    Options
    -------
    num_rotors : int
        Number of rotors (>= 1).
    num_observers : int
        Number of observers (>= 1). Default 1.
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_observers", default=1, types=int, lower=1, desc="Number of observers"
        )

    def setup(self):
        nr, no = self.options["num_rotors"], self.options["num_observers"]
        self.add_input(
            "hub_position",
            val=np.zeros((nr, 3)),
            units="m",
            desc="Rotor hub positions, body frame (x fwd, y right, z down)",
        )
        self.add_input(
            "observer_distance",
            val=np.full(no, 100.0),
            units="m",
            desc="Distance from the rotor-hub centroid to each observer",
        )
        self.add_input(
            "observer_elevation",
            val=np.full(no, np.radians(45.0)),
            units="rad",
            desc="Observer angle below the body x-y (rotor) plane",
        )
        self.add_input(
            "observer_azimuth",
            val=np.full(no, np.pi),
            units="rad",
            desc="Observer azimuth from +x (forward) towards +y (right)",
        )
        self.add_output(
            "observer_position",
            val=np.zeros(3 if no == 1 else (no, 3)),
            units="m",
            desc="Observer positions, body frame",
        )

        self.declare_partials(
            "observer_position",
            "hub_position",
            rows=np.tile(np.arange(3 * no), nr),
            cols=np.tile(np.arange(3 * nr).reshape(nr, 1, 3), (1, no, 1)).ravel(),
            val=np.full(3 * nr * no, 1.0 / nr),
        )
        for name in ("observer_distance", "observer_elevation", "observer_azimuth"):
            self.declare_partials(
                "observer_position", name, rows=np.arange(3 * no), cols=np.repeat(np.arange(no), 3)
            )

    @staticmethod
    def _direction(elev, azim):
        """Return the unit vectors (num_observers, 3) of the observer directions."""
        return np.stack(
            [np.cos(elev) * np.cos(azim), np.cos(elev) * np.sin(azim), np.sin(elev)], axis=-1
        )

    def compute(self, inputs, outputs):
        check_input_range(self, "observer_distance", inputs["observer_distance"], lower=0.0)
        check_input_range(
            self,
            "observer_elevation",
            inputs["observer_elevation"],
            lower=-0.5 * np.pi,
            upper=0.5 * np.pi,
            lower_open=False,
            upper_open=False,
        )
        direction = self._direction(inputs["observer_elevation"], inputs["observer_azimuth"])
        centroid = np.mean(inputs["hub_position"], axis=0)
        position = centroid + inputs["observer_distance"][:, None] * direction
        outputs["observer_position"] = position.reshape(outputs["observer_position"].shape)

    def compute_partials(self, inputs, partials):
        dist = inputs["observer_distance"][:, None]
        elev = inputs["observer_elevation"]
        azim = inputs["observer_azimuth"]
        zero = np.zeros_like(elev)
        partials["observer_position", "observer_distance"] = self._direction(elev, azim).ravel()
        partials["observer_position", "observer_elevation"] = (
            dist
            * np.stack(
                [-np.sin(elev) * np.cos(azim), -np.sin(elev) * np.sin(azim), np.cos(elev)], axis=-1
            )
        ).ravel()
        partials["observer_position", "observer_azimuth"] = (
            dist
            * np.stack([-np.cos(elev) * np.sin(azim), np.cos(elev) * np.cos(azim), zero], axis=-1)
        ).ravel()


class ObserverGeometryComp(om.ExplicitComponent):
    """
    Rotor-observer geometry and rotor kinematics for each rotor (steady observer).

    Equations (docs theory/acoustics 'Observer geometry'), with P = x_o - x_h the hub-to-observer
    vector and n = d/norm(d) the unit thrust axis:

    - distance S = norm(P); axial distance z = P.n (> 0 on the thrust side); in-plane distance
      Y = sqrt(S**2 - z**2 + 1e-12 m**2). The elevation of the observer above the rotor plane is
      arcsin(z/S) (theta_0 of docs theory/acoustics 'Observer geometry').
    - Doppler (convective) distance r1 = S (1 - V.P/(S a)) = S - V.P/a, with V the vehicle velocity
      in the body frame: shorter (louder) when the hub moves towards the observer.
    - Observer azimuth phi_o in the rotor's azimuth frame (used by the edgewise Lowson path):
      e_y = normalised projection of the body y axis on the disk, e_x = n x e_y (as BladeAD,
      docs theory/rotors 'Stations and disk frame'); blade azimuth psi = 0 points aft (-e_x) and psi
      grows in the direction of rotation, right-handed about n for rotation_direction = +1
      (counter-clockwise seen from above for a
      lift rotor with n up), so the blade sits at r (-cos psi e_x + s sin psi e_y), s = +-1.
      cos phi_o = -P.e_x/Y and sin phi_o = s P.e_y/Y.
    - axial speed V.n and in-plane (edgewise) speed norm(V - (V.n) n) (with a 1e-12 (m/s)**2 floor
      under the square root).

    Inputs
    ------
    hub_position : float, (num_rotors, 3), m
        Hub positions in the body frame (x forward, y right, z down, origin at the nose).
    thrust_direction : float, (num_rotors, 3), unitless
        Thrust axis direction in the body frame (normalised here; (0, 0, -1) = up).
    observer_position : float, (3,) or (num_rotors, 3) with ``observer_per_rotor``, m
        Observer position in the body frame (one per rotor: each rotor-observer pair of a
        multi-observer evaluation is one "rotor" here).
    flight_velocity : float, (3,), m/s
        Vehicle velocity in the body frame (zero in hover).
    speed_of_sound : float, (1,), m/s
        Speed of sound.

    Outputs
    -------
    distance : float, (num_rotors,), m
        Hub-observer distance S.
    axial_distance : float, (num_rotors,), m
        Observer distance along the thrust axis z = P.n.
    inplane_distance : float, (num_rotors,), m
        Observer distance from the thrust axis Y.
    convected_distance : float, (num_rotors,), m
        Doppler-corrected distance r1.
    observer_azimuth_cos, observer_azimuth_sin : float, (num_rotors,), unitless
        cos and sin of the observer azimuth phi_o in the rotor azimuth frame.
    axial_speed : float, (num_rotors,), m/s
        Flight speed along the thrust axis V.n.
    inplane_speed : float, (num_rotors,), m/s
        Flight speed in the rotor plane (edgewise speed).

    Options
    -------
    num_rotors : int
        Number of rotors (>= 1).
    rotation_direction : tuple of int or None
        +1 (right-handed about the thrust axis) or -1 per rotor; None: all +1.
    observer_per_rotor : bool
        One observer position per rotor (input shape (num_rotors, 3)). Default False.

    Raises
    ------
    om.AnalysisError
        If an observer coincides with a hub, a thrust direction is zero or along the body y axis,
        or the flight speed towards the observer reaches the speed of sound (r1 <= 0).
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "rotation_direction",
            default=None,
            types=(tuple, list),
            allow_none=True,
            desc="+1 (right-handed about the thrust axis) or -1 per rotor",
        )
        self.options.declare(
            "observer_per_rotor",
            default=False,
            types=bool,
            desc="one observer position per rotor, shape (num_rotors, 3)",
        )

    def setup(self):
        nr = self.options["num_rotors"]
        per_rotor = self.options["observer_per_rotor"]
        rot = self.options["rotation_direction"]
        if rot is None:
            rot = (1,) * nr
        if len(rot) != nr or any(s not in (1, -1) for s in rot):
            raise ValueError(
                f"{self.msginfo}: option 'rotation_direction' must hold num_rotors = "
                f"{nr} entries of +1 or -1, got {rot!r}."
            )
        self._rot = np.asarray(rot, dtype=float)

        self.add_input(
            "hub_position",
            val=np.zeros((nr, 3)),
            units="m",
            desc="Rotor hub positions, body frame (x fwd, y right, z down)",
        )
        self.add_input(
            "thrust_direction",
            val=np.tile([0.0, 0.0, -1.0], (nr, 1)),
            units=None,
            desc="Thrust axis direction, body frame (normalised internally)",
        )
        observer = np.array([-70.71067812, 0.0, 70.71067812])
        self.add_input(
            "observer_position",
            val=np.tile(observer, (nr, 1)) if per_rotor else observer,
            units="m",
            desc="Observer position, body frame",
        )
        self.add_input(
            "flight_velocity", val=np.zeros(3), units="m/s", desc="Vehicle velocity, body frame"
        )
        self.add_input(
            "speed_of_sound", val=SEA_LEVEL_SPEED_OF_SOUND, units="m/s", desc="Speed of sound"
        )

        outs = {
            "distance": ("m", "Hub-observer distance S"),
            "axial_distance": ("m", "Observer distance along the thrust axis, z = P.n"),
            "inplane_distance": ("m", "Observer distance from the thrust axis, Y"),
            "convected_distance": ("m", "Doppler-corrected hub-observer distance r1 = S - V.P/a"),
            "observer_azimuth_cos": (None, "cos of the observer azimuth in the rotor frame"),
            "observer_azimuth_sin": (None, "sin of the observer azimuth in the rotor frame"),
            "axial_speed": ("m/s", "Flight speed along the thrust axis"),
            "inplane_speed": ("m/s", "Flight speed in the rotor plane (edgewise speed)"),
        }
        for name, (units, desc) in outs.items():
            self.add_output(name, val=np.ones(nr), units=units, desc=desc)

        ar = np.arange(nr)
        rows3 = np.repeat(ar, 3)
        cols3 = np.arange(3 * nr)
        cols_shared = np.tile(np.arange(3), nr)
        geometric = (
            "distance",
            "axial_distance",
            "inplane_distance",
            "convected_distance",
            "observer_azimuth_cos",
            "observer_azimuth_sin",
        )
        for name in geometric:
            self.declare_partials(name, "hub_position", rows=rows3, cols=cols3)
            self.declare_partials(
                name, "observer_position", rows=rows3, cols=cols3 if per_rotor else cols_shared
            )
        for name in (
            "axial_distance",
            "inplane_distance",
            "observer_azimuth_cos",
            "observer_azimuth_sin",
            "axial_speed",
            "inplane_speed",
        ):
            self.declare_partials(name, "thrust_direction", rows=rows3, cols=cols3)
        for name in ("convected_distance", "axial_speed", "inplane_speed"):
            self.declare_partials(name, "flight_velocity", rows=rows3, cols=cols_shared)
        self.declare_partials(
            "convected_distance", "speed_of_sound", rows=ar, cols=np.zeros(nr, dtype=int)
        )

    def _geometry(self, inputs):
        """All geometric quantities (complex-step safe)."""
        g = {}
        hub = inputs["hub_position"]
        d = inputs["thrust_direction"]
        vel = inputs["flight_velocity"]
        a = inputs["speed_of_sound"][0]
        g["P"] = P = inputs["observer_position"].reshape(-1, 3) - hub
        g["S"] = np.sqrt(np.sum(P * P, axis=1))
        g["dnorm"] = dnorm = np.sqrt(np.sum(d * d, axis=1))
        g["n"] = n = d / dnorm[:, None]
        g["z"] = z = np.sum(P * n, axis=1)
        g["Y"] = np.sqrt(g["S"] ** 2 - z**2 + _EPS_DISTANCE2)
        g["r1"] = g["S"] - (P @ vel) / a
        # Rotor azimuth frame (BladeAD docs theory/rotors 'Stations and disk frame'): e_y =
        # projected body y axis, e_x = n x e_y.
        u = -n[:, 1:2] * n
        u[:, 1] += 1.0
        g["u"] = u
        g["unorm"] = unorm = np.sqrt(np.sum(u * u, axis=1))
        g["ey"] = ey = u / unorm[:, None]
        g["ex"] = np.cross(n, ey)
        # psi = 0 aft (-e_x), psi increasing with rotation: e1 = -e_x, e2 = s e_y.
        g["e1"] = -g["ex"]
        g["e2"] = self._rot[:, None] * ey
        g["va"] = va = n @ vel
        g["vp"] = np.sqrt(vel @ vel - va**2 + _EPS_SPEED2)
        return g

    def compute(self, inputs, outputs):
        check_input_range(self, "speed_of_sound", inputs["speed_of_sound"], lower=0.0)
        d = inputs["thrust_direction"]
        check_input_range(
            self, "thrust_direction (norm)", np.sqrt(np.sum(d * d, axis=1)), lower=1e-12
        )
        g = self._geometry(inputs)
        check_input_range(self, "distance (observer to hub)", g["S"], lower=1e-6)
        check_input_range(
            self, "thrust_direction (component normal to the body y axis)", g["unorm"], lower=1e-9
        )
        check_input_range(
            self,
            "convected_distance (flight speed towards the observer must be "
            "below the speed of sound)",
            g["r1"],
            lower=0.0,
        )
        Y = g["Y"]
        outputs["distance"] = g["S"]
        outputs["axial_distance"] = g["z"]
        outputs["inplane_distance"] = Y
        outputs["convected_distance"] = g["r1"]
        outputs["observer_azimuth_cos"] = np.sum(g["P"] * g["e1"], axis=1) / Y
        outputs["observer_azimuth_sin"] = np.sum(g["P"] * g["e2"], axis=1) / Y
        outputs["axial_speed"] = g["va"]
        outputs["inplane_speed"] = g["vp"]

    def compute_partials(self, inputs, partials):
        g = self._geometry(inputs)
        vel = inputs["flight_velocity"]
        a = inputs["speed_of_sound"][0]
        P, S, n, z, Y = g["P"], g["S"], g["n"], g["z"], g["Y"]
        nr = P.shape[0]
        eye = np.broadcast_to(np.eye(3), (nr, 3, 3))

        # Jacobian of the unit axis n w.r.t. the raw direction d: (I - n n^T)/|d|.
        dn_dd = (eye - n[:, :, None] * n[:, None, :]) / g["dnorm"][:, None, None]

        # Derivatives w.r.t. P (observer minus hub) and w.r.t. n, each (nr, 3).
        dS_dP = P / S[:, None]
        dz_dP = n
        dz_dn = P
        dY_dP = (P - z[:, None] * n) / Y[:, None]
        dY_dn = -z[:, None] * P / Y[:, None]
        dr1_dP = dS_dP - vel[None, :] / a

        # Basis vectors e1 = -e_x, e2 = s e_y as functions of n.
        ey, ny = g["ey"], n[:, 1]
        du_dn = -ny[:, None, None] * eye
        du_dn[:, :, 1] -= n
        dey_dn = ((eye - ey[:, :, None] * ey[:, None, :]) / g["unorm"][:, None, None]) @ du_dn
        dex_dn = -_cross_matrix(ey) + _cross_matrix(n) @ dey_dn
        de1_dn = -dex_dn
        de2_dn = self._rot[:, None, None] * dey_dn

        out = {}
        for name, e, de_dn in (
            ("observer_azimuth_cos", g["e1"], de1_dn),
            ("observer_azimuth_sin", g["e2"], de2_dn),
        ):
            val = np.sum(P * e, axis=1) / Y
            dP = e / Y[:, None] - val[:, None] * dY_dP / Y[:, None]
            dn = np.einsum("ri,rij->rj", P, de_dn) / Y[:, None] - val[:, None] * dY_dn / Y[:, None]
            out[name] = (dP, dn)
        out["distance"] = (dS_dP, None)
        out["axial_distance"] = (dz_dP, dz_dn)
        out["inplane_distance"] = (dY_dP, dY_dn)
        out["convected_distance"] = (dr1_dP, None)

        for name, (dP, dn) in out.items():
            partials[name, "observer_position"] = dP.ravel()
            partials[name, "hub_position"] = -dP.ravel()
            if dn is not None:
                partials[name, "thrust_direction"] = np.einsum("ri,rij->rj", dn, dn_dd).ravel()

        va, vp = g["va"], g["vp"]
        partials["axial_speed", "thrust_direction"] = np.einsum("i,rij->rj", vel, dn_dd).ravel()
        partials["axial_speed", "flight_velocity"] = n.ravel()
        dvp_dn = -(va / vp)[:, None] * vel[None, :]
        partials["inplane_speed", "thrust_direction"] = np.einsum(
            "ri,rij->rj", dvp_dn, dn_dd
        ).ravel()
        partials["inplane_speed", "flight_velocity"] = (
            (vel[None, :] - va[:, None] * n) / vp[:, None]
        ).ravel()
        partials["convected_distance", "flight_velocity"] = (-P / a).ravel()
        partials["convected_distance", "speed_of_sound"] = (P @ vel) / a**2
