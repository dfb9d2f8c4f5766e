"""Steady Pitt–Peters rotor: blade-element loads over radius and azimuth, and their integrals.

docs theory/rotors 'Pitt-Peters inflow' (items 1-4 and 9) and paper eq. 14 (with the reference's
correction: the last term is lambda_c r/R cos psi). This module holds

- :class:`PittPetersBladeElements`, the blade-element field of every station (rotor, operating
  point, radial station, azimuth) for given inflow states, its integrals (thrust, moments,
  torque, in-plane forces, Prandtl area factor) and their exact partials; shared by the inflow
  solve (``pitt_peters_inflow.py``) and the loads component here;
- :class:`PittPetersLoadsComp`, the sectional loads over (r, psi) and the hub loads at the
  converged inflow states.

Disk frame and azimuth (the frame of ``hub_loads.rotor_frames`` and docs theory/rotors 'Stations and
disk frame'): n is the thrust axis, e_y the body y axis projected on the disk, e_x = n x e_y; the
rotor spins with
angular velocity s Omega n (s = spin_direction). The azimuth psi_k = 2 pi k/N_psi of a blade is
measured in the direction of rotation from the -e_x position, so the blade sits at
r (-cos psi e_x + s sin psi e_y) and moves along t = sin psi e_x + s cos psi e_y. For a lift rotor
in forward flight psi = 0 is the downstream (aft) blade and psi = 90 deg the advancing blade.

Station equations (per blade, per unit span):

- inflow (eq. 14): lambda = lambda_0 + (r/R)(lambda_c cos psi + lambda_s sin psi);
- velocities: U_P = V_x + Omega R lambda (through the disk), U_T = Omega r + v_x sin psi
  + s v_y cos psi (tangential; (V_x, v_x, v_y) = the hub's velocity relative to the air along
  (n, e_x, e_y), so V_x > 0 is climb for a lift rotor);
- tangential induction (wake swirl; option tangential_induction, default on; docs theory/rotors
  'Pitt-Peters inflow' neglects it, the BEM has it): the blade sees U_T - v_t, where v_t balances
  the angular
  momentum of the annulus, v_t U_m F_m = B d/(4 pi rho r), with the mass-flow velocity
  U_m = sqrt(U_P^2 + v_x^2 + v_y^2) (so the swirl fades in fast edgewise flight) and F_m = F
  with loss_placement='momentum' (else 1); solved per station by Newton from v_t = 0, its
  partials by the implicit-function theorem. Without it Pitt–Peters overpredicts the BEM's
  hover thrust by 2.4-6.5 % on the LPC blade; with it (and F on the momentum side) it agrees
  to 0.02 % (tests/test_pitt_peters_validation.py);
- phi = atan2(U_P, U_T - v_t) (four-quadrant: reverse flow on the retreating side is included;
  the polar covers -pi..pi), alpha = twist - phi;
- Reynolds and Mach numbers from the undisturbed resultant U = sqrt(V_x^2 + U_T^2), as the BEM
  (docs theory/rotors 'Stations and disk frame'): Re = rho U c/mu, M = U/a;
- C_x = C_l cos phi - C_d sin phi, C_theta = C_l sin phi + C_d cos phi;
- thrust_per_span t = (rho/2)(U_P^2 + (U_T - v_t)^2) c C_x F_l and drag_per_span
  d = (rho/2)(U_P^2 + (U_T - v_t)^2) c C_theta F_l (drag opposes the rotation;
  dQ/dr = B r d), where F_l = 1 with the default loss_placement='momentum' (F, Prandtl tip and
  hub loss in the docs theory/rotors 'BEM inflow residual' classical form, then scales the momentum
  side of the inflow equation, as in the BEM; see ``pitt_peters_inflow.py``) and F_l = F with
  loss_placement='blade_element'
  (docs theory/rotors 'Pitt-Peters inflow').

Integrals (docs theory/rotors 'Loads and coefficients' rule, (1/N_psi) sum over the azimuth, dr_i =
station_width):

- thrust T = (B/N_psi) sum dr t; torque Q = (B/N_psi) sum dr r d;
- moments M_c = (B/N_psi) sum dr r cos psi t and M_s = (B/N_psi) sum dr r sin psi t (the
  forcing of the cosine and sine inflow states, eq. 15);
- hub moment about (e_x, e_y): (-s M_s, -M_c); in-plane hub force along (e_x, e_y):
  (-(B/N_psi) sum dr sin psi d, -s (B/N_psi) sum dr cos psi d);
- Prandtl area factor F_A = (2/(N_psi R^2)) sum dr r F (the loss-weighted disk area over pi R^2).
"""

from collections import OrderedDict
from types import SimpleNamespace

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.polar import LinearQuadraticPolar, Polar
from lpc_mdo.components.geometry.blade import azimuth_angles, per_rotor
from lpc_mdo.components.rotor.bem_inflow import check_section_inputs
from lpc_mdo.core.checks import check_choice
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

#: Where Prandtl's loss factor acts: on the momentum (inflow) side or on the blade loads.
LOSS_PLACEMENTS = ("momentum", "blade_element")

_TWO_OVER_PI = 2.0 / np.pi
_ABS_SIN_FLOOR = 1.0e-9  # |sin phi| floor in the Prandtl exponent (F = 1 to all digits there)
_SWIRL_MAX_ITERATIONS = 30
_SWIRL_TOLERANCE = 1.0e-12  # Newton step on v_t left, relative to max |U_T| + 1 m/s

#: Inputs: name -> (kind, units, default, description). Kinds: 'op' (num_rotors, num_nodes),
#: 'rotor' (num_rotors,), 'radial' (num_rotors, num_radial), 'node' (num_nodes,).
PITT_PETERS_INPUTS = {
    "rpm": ("op", "rpm", 1000.0, "Rotor speed"),
    "axial_velocity": (
        "op",
        "m/s",
        0.0,
        "Velocity of the hub relative to the air along the thrust axis (> 0: "
        "flow through the disk as in climb)",
    ),
    "inplane_velocity": (
        "op2",
        "m/s",
        0.0,
        "Velocity of the hub relative to the air along the disk e_x and e_y",
    ),
    "radius": ("rotor", "m", 1.0, "Rotor tip radius"),
    "hub_radius": ("rotor", "m", 0.2, "Hub radius"),
    "station_radius": ("radial", "m", None, "Radius of the blade-element centres"),
    "station_width": ("radial", "m", None, "Radial quadrature width of each blade element"),
    "chord": ("radial", "m", 0.1, "Blade chord at the stations"),
    "twist": ("radial", "rad", 0.2, "Blade pitch relative to the rotor plane at the stations"),
    "density": ("node", "kg/m**3", SEA_LEVEL_DENSITY, "Air density"),
    "speed_of_sound": ("node", "m/s", SEA_LEVEL_SPEED_OF_SOUND, "Speed of sound"),
    "dynamic_viscosity": ("node", "Pa*s", 1.7894e-5, "Dynamic viscosity of air"),
}

#: Per-operating-point vector inputs (and the states) and their sizes.
_OP_VECTOR = {"inflow_states": 3, "inplane_velocity": 2}

#: Inputs (and the states) the station field depends on, in the row order of the chained
#: partials (PittPetersBladeElements.chain); station_width enters only the integrals.
CHAIN_INPUTS = (
    "inflow_states",
    "rpm",
    "axial_velocity",
    "inplane_velocity",
    "radius",
    "hub_radius",
    "station_radius",
    "chord",
    "twist",
    "density",
    "dynamic_viscosity",
    "speed_of_sound",
)

#: Partial dict of PittPetersBladeElements.evaluate -> the station field it differentiates.
_FIELD_OF_PARTIALS = {"dt": "t", "dd": "d", "dphi": "phi", "dF": "F"}

#: Azimuth factor of an integral -> column of PittPetersBladeElements.trig.
_TRIG_INDEX = {None: 0, "cos": 1, "sin": 2}


def declare_pitt_peters_options(options):
    """Declare the options shared by the Pitt–Peters components (and the rotor group)."""
    options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
    options.declare(
        "num_nodes",
        default=1,
        types=int,
        lower=1,
        desc="Number of operating points (flight conditions) per rotor",
    )
    options.declare(
        "num_radial", default=25, types=int, lower=1, desc="Number of radial stations per blade"
    )
    options.declare(
        "num_azimuth",
        default=25,
        types=int,
        lower=3,
        desc="Number of equally spaced azimuthal stations (>= 3, so that the first "
        "harmonics of the loading are resolved)",
    )
    options.declare(
        "num_blades",
        default=2,
        types=(int, list, tuple, np.ndarray),
        desc="Blades per rotor: one int for all rotors or one per rotor",
    )
    options.declare(
        "spin_direction",
        default=1,
        types=(int, list, tuple, np.ndarray),
        desc="+1 (right-handed about the thrust axis) or -1, one for all or per rotor",
    )
    options.declare(
        "polar",
        default=LinearQuadraticPolar(),
        types=Polar,
        desc="Sectional airfoil polar (lpc_mdo.components.aero.polar.Polar)",
    )
    options.declare("tip_loss", default=True, types=bool, desc="Apply Prandtl's tip loss")
    options.declare("hub_loss", default=True, types=bool, desc="Apply Prandtl's hub loss")
    options.declare(
        "loss_placement",
        default="momentum",
        values=LOSS_PLACEMENTS,
        desc="Prandtl factor on the blade-element loads ('blade_element', docs "
        "theory/rotors 'Pitt-Peters inflow') or on the momentum side of the "
        "inflow equation ('momentum')",
    )
    options.declare(
        "tangential_induction",
        default=True,
        types=bool,
        desc="Include the wake swirl v_t = B d/(4 pi rho r U_m) per station (as the "
        'BEM does); False: neglect it (docs theory/rotors "Pitt-Peters inflow")',
    )


def input_shape(kind, nr, nn, nrad):
    """Shape of a Pitt–Peters input of the given kind."""
    return {
        "op": (nr, nn),
        "op2": (nr, nn, 2),
        "rotor": (nr,),
        "radial": (nr, nrad),
        "node": (nn,),
    }[kind]


def add_pitt_peters_inputs(comp, nr, nn, nrad):
    """Add the inputs of :data:`PITT_PETERS_INPUTS` to a component."""
    eta = (np.arange(nrad) + 0.5) / nrad
    defaults = {
        "station_radius": np.tile(0.2 + 0.8 * eta, (nr, 1)),
        "station_width": np.full((nr, nrad), 0.8 / nrad),
    }
    for name, (kind, units, default, desc) in PITT_PETERS_INPUTS.items():
        shape = input_shape(kind, nr, nn, nrad)
        val = defaults[name] if default is None else np.full(shape, default)
        comp.add_input(name, val=val, units=units, desc=desc)


def check_pitt_peters_inputs(comp, inputs, hub_loss):
    """
    Check the physical range of the inputs (real parts) with the BEM section check.

    The check is :func:`~lpc_mdo.components.rotor.bem_inflow.check_section_inputs`:
    om.AnalysisError names the input, the first offending entry and the allowed range.
    """
    check_section_inputs(
        comp,
        inputs,
        hub_loss,
        names=PITT_PETERS_INPUTS,
        positive=(
            "rpm",
            "radius",
            "chord",
            "station_width",
            "density",
            "speed_of_sound",
            "dynamic_viscosity",
        ),
    )


def _exact_key(x, states=()):
    """Hashable key of inputs ``x`` (name -> array) and states: dtypes and exact bytes."""
    return (
        np.asarray(states).dtype.str,
        np.asarray(states).tobytes(),
        *(np.asarray(x[name]).dtype.str for name in sorted(x)),
        *(np.asarray(x[name]).tobytes() for name in sorted(x)),
    )


def pitt_peters_values(comp, inputs):
    """
    Return the inputs of :data:`PITT_PETERS_INPUTS` of a component (name -> array), checked.

    :func:`check_pitt_peters_inputs` runs only when the inputs differ (exact bytes) from those
    the component last checked: its linearization and the repeated evaluations of its nonlinear
    solve come at inputs already checked.
    """
    x = {name: inputs[name] for name in PITT_PETERS_INPUTS}
    key = _exact_key(x)
    if key != getattr(comp, "_checked_inputs", None):
        check_pitt_peters_inputs(comp, x, comp.options["hub_loss"])
        comp._checked_inputs = key
    return x


def atan2_cs(y, x):
    """arctan2(y, x), complex-step safe (the imaginary part carries the first derivative)."""
    if np.iscomplexobj(y) or np.iscomplexobj(x):
        yr, xr = np.real(y), np.real(x)
        return np.arctan2(yr, xr) + 1j * (xr * np.imag(y) - yr * np.imag(x)) / (xr**2 + yr**2)
    return np.arctan2(y, x)


def rotor_blade_options(comp):
    """Blade counts and spin directions (num_rotors,) of a component's options, checked."""
    nr = comp.options["num_rotors"]
    blades = per_rotor(
        comp.options["num_blades"], nr, "num_blades", kind=int, lower=1, owner=comp.msginfo
    )
    spin = per_rotor(
        comp.options["spin_direction"],
        nr,
        "spin_direction",
        kind=int,
        lower=-1,
        upper=1,
        owner=comp.msginfo,
    )
    for i, s in enumerate(spin.tolist()):
        check_choice(f"spin_direction[{i}]", s, (1, -1), where=comp.msginfo)
    return blades.astype(float), spin.astype(float)


class PittPetersBladeElements:
    """
    Blade-element field of several rotors at several operating points (module docstring).

    Arrays have the station shape (num_rotors, num_nodes, num_radial, num_azimuth). The partials
    are hand-derived (forward chain rule) and exact; everything is complex-step safe.

    Parameters
    ----------
    shape : tuple of int
        (num_rotors, num_nodes, num_radial, num_azimuth).
    blades, spin : ndarray, (num_rotors,)
        Blade counts and spin directions (+1 or -1).
    polar : Polar
        Sectional polar.
    tip_loss, hub_loss : bool
        Prandtl tip and hub losses.
    loss_placement : str
        'momentum' or 'blade_element'.
    owner : str
        Prefix of error messages.
    """

    #: Integrals: name -> (field, radius power, azimuth factor, times B).
    INTEGRALS = {
        "thrust": ("t", 0, None, True),
        "moment_cos": ("t", 1, "cos", True),
        "moment_sin": ("t", 1, "sin", True),
        "torque": ("d", 1, None, True),
        "drag_sin": ("d", 0, "sin", True),
        "drag_cos": ("d", 0, "cos", True),
        "loss_area": ("F", 1, None, False),
    }

    def __init__(
        self,
        shape,
        blades,
        spin,
        polar,
        tip_loss,
        hub_loss,
        loss_placement,
        tangential_induction=True,
        owner="",
    ):
        nr, nn, nrad, naz = shape
        self.shape = shape
        self.polar = polar
        self.tip_loss, self.hub_loss = tip_loss, hub_loss
        self.loads_have_loss = loss_placement == "blade_element" and (tip_loss or hub_loss)
        self.momentum_loss = loss_placement == "momentum" and (tip_loss or hub_loss)
        self.swirl = tangential_induction
        self._vt_guess = 0.0
        # The last swirl solution (v_t and its section), keyed by the exact inputs and states:
        # the Newton Jacobian and the linearization evaluate where the residual last did.
        self._last_swirl = (None, None)
        self._layouts = {}  # _layout() by the keys asked for
        # What the station field depends on besides the inputs (the polar by identity; the
        # cache entry holds the polar, so its id is not reused while the entry lives).
        self._signature = (
            tuple(shape),
            np.asarray(blades).tobytes(),
            np.asarray(spin).tobytes(),
            id(polar),
            tip_loss,
            hub_loss,
            loss_placement,
            tangential_induction,
        )
        self.owner = owner
        psi = azimuth_angles(naz)
        self.cos = np.cos(psi)[None, None, None, :]
        self.sin = np.sin(psi)[None, None, None, :]
        self.half_b = 0.5 * blades[:, None, None, None]
        self.spin = spin
        self.spin4 = spin[:, None, None, None]
        # Azimuth weights (1, cos psi, sin psi), (N_psi, 3), and dU_T/d(inplane_velocity),
        # (2, nr, 1, 1, N_psi).
        self.trig = np.stack([np.ones(naz), np.cos(psi), np.sin(psi)], axis=1)
        self.dut_dvip = np.stack(np.broadcast_arrays(self.sin, self.spin4 * self.cos))
        # Integral prefactor B/N_psi (or 1/N_psi without B), shape (nr, 1, 1).
        self.b_fac = (blades / naz)[:, None, None]
        self.one_fac = np.full((nr, 1, 1), 1.0 / naz)

    # ---------------------------------------------------------------- station values
    def evaluate(self, x, states, partials=False, shared=False):
        """
        Station field for inputs ``x`` (name -> array) and inflow states (nr, nn, 3).

        With ``shared``, the field is kept (and looked up) in a small cache shared by every
        field of the same configuration: the inflow and loads components of a rotor group
        linearize at the same inputs and states, so the second reuses the first's field.

        Returns a namespace with the fields t, d, phi, F, the tangential induction v_t (station
        shape) and, with ``partials``, their partials with respect to the station primitives
        at fixed U_T - v_t (dicts ``dt``, ``dd``, ``dphi``, ``dF``; keys 'up', 'ut', 'vx',
        'theta', 'chord', 'r', 'radius', 'hub_radius', 'density', 'dynamic_viscosity',
        'speed_of_sound', as far as the field depends on them, and 'ute', the partial with
        respect to U_T - v_t) and ``dute``, the partials of U_T - v_t with respect to the
        primitives (the same keys and 'vip2' = norm(inplane_velocity)^2, through the swirl's
        mass flow); :meth:`chain` adds the two paths up.

        The swirl solution of the last evaluation is kept (per field object, keyed by the
        exact inputs and states): where the nonlinear solve last evaluated, its Newton Jacobian
        and the linearization reuse it instead of solving again.
        """
        if not shared:
            return self._evaluate(x, states, partials)
        key = (self._signature, partials, *_exact_key(x, states))
        hit = _SHARED_FIELDS.get(key)
        if hit is None:
            hit = _SHARED_FIELDS[key] = (self.polar, self._evaluate(x, states, partials))
            while len(_SHARED_FIELDS) > _SHARED_FIELDS_SIZE:
                _SHARED_FIELDS.popitem(last=False)
        return hit[1]

    def _evaluate(self, x, states, partials):
        st = SimpleNamespace()
        big_r = x["radius"][:, None, None, None]
        rh = x["hub_radius"][:, None, None, None]
        r = x["station_radius"][:, None, :, None]
        chord = x["chord"][:, None, :, None]
        theta = x["twist"][:, None, :, None]
        rho = x["density"][None, :, None, None]
        mu = x["dynamic_viscosity"][None, :, None, None]
        a = x["speed_of_sound"][None, :, None, None]
        omega = (RPM_TO_RAD_S * x["rpm"])[:, :, None, None]
        v_ax = x["axial_velocity"][:, :, None, None]
        v_ip = x["inplane_velocity"]
        lam0, lam_c, lam_s = (states[..., k][:, :, None, None] for k in range(3))
        g = lam_c * self.cos + lam_s * self.sin

        up = v_ax + omega * big_r * lam0 + omega * r * g
        ut = (
            omega * r
            + v_ip[..., 0][:, :, None, None] * self.sin
            + (self.spin[:, None] * v_ip[..., 1])[:, :, None, None] * self.cos
        )
        u = np.sqrt(v_ax * v_ax + ut * ut)
        if np.any(np.real(u) <= 0.0):
            raise om.AnalysisError(
                f"{self.owner}: zero relative velocity at a blade station "
                "(U_P = U_T = 0); the blade-element model is undefined there."
            )
        re = rho * u * chord / mu
        mach = u / a
        geo = SimpleNamespace(
            up=up, r=r, big_r=big_r, rh=rh, chord=chord, theta=theta, rho=rho, re=re, mach=mach
        )
        if self.swirl:
            vip2 = np.sum(v_ip * v_ip, axis=-1)[:, :, None, None]
            um = np.sqrt(up * up + vip2)
            kappa = self.half_b / (2.0 * np.pi * rho * r)  # B/(4 pi rho r)
            key = _exact_key(x, states)
            if self._last_swirl[0] == key:  # e.g. the linearization at the solved point
                vt, sec = self._last_swirl[1]
            else:
                vt, sec = self._solve_swirl(geo, ut, um, kappa)
                self._last_swirl = (key, (vt, sec))
        else:
            vt = np.zeros_like(ut)
            sec = self._section(geo, ut, derivatives=partials)
        st.t, st.d, st.phi, st.F, st.vt = sec.t, sec.d, sec.phi, sec.F, vt
        st.v_ip = v_ip[:, :, None, None, :]
        st.r = r
        st.width = x["station_width"][:, None, :, None]
        st.omega, st.big_r, st.lam0, st.g = omega, big_r, lam0, g
        if not partials:
            return st

        # Partials with respect to the primitives; 'ute' = through U_T - v_t (phi and W^2),
        # 'ut' = through the undisturbed U (Reynolds and Mach numbers) only.
        w2, ute, q, f_l = sec.w2, sec.ute, sec.q, sec.f_l
        pv, cphi, sphi, cx, ct, df = sec.pv, sec.cphi, sec.sphi, sec.cx, sec.ct, sec.df
        ptd = {"up": ute / w2, "ute": -up / w2}  # dphi/dU_P, dphi/d(U_T - v_t)
        raw = {
            "dphi": ptd,
            "dF": {
                "up": df["phi"] * ptd["up"],
                "ute": df["phi"] * ptd["ute"],
                "r": df["r"],
                "radius": df["radius"],
                "hub_radius": df["hub_radius"],
            },
        }
        for name, coeff, c_a, c_re, c_m, geo_c in (
            (
                "dt",
                cx,
                pv.dcl_dalpha * cphi - pv.dcd_dalpha * sphi,
                pv.dcl_dreynolds * cphi - pv.dcd_dreynolds * sphi,
                pv.dcl_dmach * cphi - pv.dcd_dmach * sphi,
                -ct,
            ),
            (
                "dd",
                ct,
                pv.dcl_dalpha * sphi + pv.dcd_dalpha * cphi,
                pv.dcl_dreynolds * sphi + pv.dcd_dreynolds * cphi,
                pv.dcl_dmach * sphi + pv.dcd_dmach * cphi,
                cx,
            ),
        ):
            field = q * coeff * f_l
            base = q * f_l
            f_phi = base * (geo_c - c_a)
            if self.loads_have_loss:
                f_phi = f_phi + q * coeff * df["phi"]
            f_u = base * (c_re * re + c_m * mach) / u  # through Re and M
            p = {
                "up": 2.0 * up / w2 * field + f_phi * ptd["up"],
                "ute": 2.0 * ute / w2 * field + f_phi * ptd["ute"],
                "ut": f_u * ut / u,
                "vx": f_u * v_ax / u,
                "theta": base * c_a,
                "chord": field / chord + base * c_re * re / chord,
                "density": field / rho + base * c_re * re / rho,
                "dynamic_viscosity": -base * c_re * re / mu,
                "speed_of_sound": -base * c_m * mach / a,
            }
            if self.loads_have_loss:
                for key in ("r", "radius", "hub_radius"):
                    p[key] = q * coeff * df[key]
            raw[name] = p
        if self.swirl:
            st.dute = self._swirl_partials(raw, sec, vt, um, kappa, rho, r, up)
        else:
            st.dute = {"ut": 1.0}
        for name, p in raw.items():
            setattr(st, name, p)
        st.chained, st.moments = {}, {}  # memos of chain() and of the azimuth moments
        return st

    def _section(self, geo, ute, derivatives=True):
        """
        Evaluate the blade-element loads at the stations for the tangential velocity ``ute``.

        ``ute`` = U_T - v_t. With ``derivatives``, also the loss partials and d/d(ute) of the
        drag and of F (the swirl Newton and the partials need them, a plain evaluation without
        swirl does not).
        """
        sec = SimpleNamespace(ute=ute)
        up = geo.up
        sec.w2 = up * up + ute * ute
        if np.any(np.real(sec.w2) <= 0.0):
            raise om.AnalysisError(
                f"{self.owner}: zero relative velocity at a blade station "
                "(U_P = U_T = 0); the blade-element model is undefined there."
            )
        sec.phi = atan2_cs(up, ute)
        sec.pv = self.polar.evaluate(geo.theta - sec.phi, geo.re, geo.mach)
        sec.cphi, sec.sphi = np.cos(sec.phi), np.sin(sec.phi)
        sec.cx = sec.pv.cl * sec.cphi - sec.pv.cd * sec.sphi
        sec.ct = sec.pv.cl * sec.sphi + sec.pv.cd * sec.cphi
        sec.q = 0.5 * geo.rho * sec.w2 * geo.chord
        sec.F, sec.df = self._loss(sec.phi, geo.r, geo.big_r, geo.rh, derivatives)
        sec.f_l = sec.F if self.loads_have_loss else 1.0
        sec.t = sec.q * sec.cx * sec.f_l
        sec.d = sec.q * sec.ct * sec.f_l
        if not derivatives:
            return sec
        # d(drag_per_span)/d(ute) and dF/d(ute), for the swirl Newton step
        dphi = -up / sec.w2
        c_a = sec.pv.dcl_dalpha * sec.sphi + sec.pv.dcd_dalpha * sec.cphi
        f_phi = sec.q * sec.f_l * (sec.cx - c_a)
        if self.loads_have_loss:
            f_phi = f_phi + sec.q * sec.ct * sec.df["phi"]
        sec.d_ute = 2.0 * ute / sec.w2 * sec.d + f_phi * dphi
        sec.F_ute = sec.df["phi"] * dphi
        return sec

    def _swirl_residual(self, sec, vt, um, kappa):
        """
        Return the annulus angular-momentum residual and its derivative in v_t.

        The residual is v_t U_m F_m - B d/(4 pi rho r), with F_m = F on the momentum side with
        loss_placement='momentum', else 1.
        """
        f_m = sec.F if self.momentum_loss else 1.0
        res = vt * um * f_m - kappa * sec.d
        jac = um * f_m + kappa * sec.d_ute
        if self.momentum_loss:
            jac = jac - vt * um * sec.F_ute
        return res, jac

    def _solve_swirl(self, geo, ut, um, kappa):
        """
        Solve for the tangential induction v_t per station by Newton.

        Newton starts from the last solution (the inflow Newton and the optimizer evaluate
        nearby points; ~4x fewer steps), then, if that fails, from v_t = 0.
        """
        starts = [0.0] if np.isscalar(self._vt_guess) else [self._vt_guess, 0.0]
        for k, guess in enumerate(starts):
            try:
                vt, sec = self._swirl_newton(geo, ut, um, kappa, np.zeros_like(ut) + guess)
            except om.AnalysisError:
                if k == len(starts) - 1:
                    raise
                continue
            self._vt_guess = np.real(vt)
            return vt, sec

    def _swirl_newton(self, geo, ut, um, kappa, vt):
        scale = np.max(np.abs(np.real(ut))) + 1.0
        for _ in range(_SWIRL_MAX_ITERATIONS):
            sec = self._section(geo, ut - vt)
            res, jac = self._swirl_residual(sec, vt, um, kappa)
            if np.any(np.real(jac) <= 0.0):
                bad = np.argwhere(np.real(jac) <= 0.0)[:5].tolist()
                raise om.AnalysisError(
                    f"{self.owner}: the tangential-induction (swirl) equation has no unique "
                    f"solution at stations (rotor, node, radial, azimuth) {bad} (through-flow "
                    "U_m near zero, e.g. axial descent into the vortex-ring state); set option "
                    "tangential_induction=False to neglect the swirl."
                )
            step = res / jac
            if not np.all(np.isfinite(step)):
                break
            if np.max(np.abs(np.real(step))) <= _SWIRL_TOLERANCE * scale:
                if not np.iscomplexobj(step):
                    return vt, sec  # converged: the step left is below the tolerance
                # complex step: the imaginary part (the derivative) takes one more step
                vt = vt - step
                return vt, self._section(geo, ut - vt)
            vt = vt - step
        raise om.AnalysisError(
            f"{self.owner}: the tangential-induction (swirl) Newton did not converge in "
            f"{_SWIRL_MAX_ITERATIONS} iterations (last step {np.max(np.abs(step)):.3g} m/s)."
        )

    def _swirl_partials(self, raw, sec, vt, um, kappa, rho, r, up):
        """d(U_T - v_t)/d(primitive) by the implicit-function theorem on the swirl residual."""
        _, jac = self._swirl_residual(sec, vt, um, kappa)
        f_m = sec.F if self.momentum_loss else 1.0
        dd, d_f = raw["dd"], raw["dF"]
        dres = {key: -kappa * val for key, val in dd.items() if key != "ute"}
        dres["up"] = dres["up"] + vt * f_m * up / um
        dres["vip2"] = vt * f_m / (2.0 * um)
        dres["r"] = dres.get("r", 0.0) + kappa * sec.d / r
        dres["density"] = dres["density"] + kappa * sec.d / rho
        if self.momentum_loss:
            for key, val in d_f.items():
                if key != "ute":
                    dres[key] = dres.get(key, 0.0) + vt * um * val
        # ute = U_T - v_t: d v_t/dy = -dR/dy / dR/dv_t, with U_T entering R through ute too.
        dres["ut"] = (
            dres.get("ut", 0.0)
            - kappa * dd["ute"]
            + (vt * um * d_f["ute"] if self.momentum_loss else 0.0)
        )
        dute = {key: val / jac for key, val in dres.items()}
        dute["ut"] = dute["ut"] + 1.0
        return dute

    def _loss(self, phi, r, big_r, rh, partials):
        """
        Return the Prandtl factor F = F_tip F_hub and its partials.

        Classical; see docs theory/rotors 'BEM inflow residual'.
        """
        ones = np.ones(np.broadcast_shapes(phi.shape, r.shape), dtype=phi.dtype)
        zero = np.zeros(ones.shape)
        d = {"phi": zero, "r": zero, "radius": zero, "hub_radius": zero}
        if not (self.tip_loss or self.hub_loss):
            return ones, d
        s = np.sin(phi)
        sgn = np.sign(np.real(s))
        abs_s = s * sgn
        floored = np.real(abs_s) < _ABS_SIN_FLOOR
        abs_s = np.where(floored, _ABS_SIN_FLOOR, abs_s)
        factors = []
        if self.tip_loss:
            k = self.half_b * (big_r - r) / r
            factors.append(("tip", k))
        if self.hub_loss:
            k = self.half_b * (r - rh) / rh
            factors.append(("hub", k))
        values, slopes = [], []
        for _, k in factors:
            f = k / abs_s
            e = np.exp(-f)
            values.append(_TWO_OVER_PI * np.arccos(e))
            one_minus = np.where(np.real(e) < 1.0 - 1e-15, 1.0 - e * e, 2e-15)
            slopes.append((f, _TWO_OVER_PI * e / np.sqrt(one_minus)))  # dF_x/df
        big_f = ones
        for v in values:
            big_f = big_f * v
        if not partials:
            return big_f, d
        # d|sin phi|/dphi / |sin phi| = cos(phi)/sin(phi) (0 where floored: f is constant there)
        with np.errstate(divide="ignore", invalid="ignore"):
            cot = np.where(floored, 0.0, np.cos(phi) / np.where(floored, 1.0, s))
        d_phi, d_r, d_big_r, d_rh = zero, zero, zero, zero
        for idx, ((kind, _), (f, slope)) in enumerate(zip(factors, slopes, strict=True)):
            other = values[1 - idx] if len(values) == 2 else 1.0
            scale = other * slope
            d_phi = d_phi - scale * f * cot
            if kind == "tip":
                d_r = d_r - scale * self.half_b * big_r / (r * r * abs_s)
                d_big_r = d_big_r + scale * self.half_b / (r * abs_s)
            else:
                d_r = d_r + scale * self.half_b / (rh * abs_s)
                d_rh = d_rh - scale * self.half_b * r / (rh * rh * abs_s)
        d = {"phi": d_phi, "r": d_r, "radius": d_big_r, "hub_radius": d_rh}
        return big_f, d

    # ---------------------------------------------------------------- chain rule to the inputs
    def _layout(self, keys):
        """
        Canonical order of the chained inputs ``keys`` and their row slices.

        Returns (keys, rows, n): the keys in :data:`CHAIN_INPUTS` order (station_width and other
        names the station field does not depend on are left out), key -> slice of the rows of
        the chained array, and the number of rows.
        """
        layout = self._layouts.get(tuple(keys))
        if layout is None:
            canonical = tuple(key for key in CHAIN_INPUTS if key in keys)
            rows, n = {}, 0
            for key in canonical:
                rows[key] = slice(n, n + input_size(key))
                n += input_size(key)
            layout = self._layouts[tuple(keys)] = (canonical, rows, n)
        return layout

    def _input_factors(self, st):
        """
        Return the partials of the station primitives with respect to each input.

        Returns input -> list of (primitive, d primitive/d input); the factors broadcast to
        (m,) + station shape (m = input size). Computed once per station field.
        """
        if getattr(st, "input_factors", None) is None:
            omega_r = st.omega * st.r
            st.input_factors = {
                "inflow_states": [
                    (
                        "up",
                        np.stack(
                            np.broadcast_arrays(
                                st.omega * st.big_r, omega_r * self.cos, omega_r * self.sin
                            )
                        ),
                    )
                ],
                "rpm": [
                    ("up", RPM_TO_RAD_S * (st.big_r * st.lam0 + st.r * st.g)),
                    ("ut", RPM_TO_RAD_S * st.r),
                ],
                "axial_velocity": [("up", 1.0), ("vx", 1.0)],
                "inplane_velocity": [
                    ("ut", self.dut_dvip),
                    ("vip2", 2.0 * np.moveaxis(st.v_ip, -1, 0)),
                ],
                "radius": [("up", st.omega * st.lam0), ("radius", 1.0)],
                "hub_radius": [("hub_radius", 1.0)],
                "station_radius": [("up", st.omega * st.g), ("ut", st.omega), ("r", 1.0)],
                "chord": [("chord", 1.0)],
                "twist": [("theta", 1.0)],
                "density": [("density", 1.0)],
                "dynamic_viscosity": [("dynamic_viscosity", 1.0)],
                "speed_of_sound": [("speed_of_sound", 1.0)],
            }
        return st.input_factors

    def _chain_primitives(self, st, p, rows, out):
        """out[rows[key]] = sum over the primitives of p[primitive] d primitive/d key."""
        factors = self._input_factors(st)
        for key, sl in rows.items():
            dst = out[sl]
            terms = [(p[prim], fac) for prim, fac in factors[key] if prim in p]
            if not terms:
                dst[...] = 0.0
                continue
            np.multiply(*terms[0], out=dst)
            for val, fac in terms[1:]:
                dst += val * fac

    def chain(self, st, name, keys):
        """
        Chain a station field's partials to the component inputs (and inflow states).

        ``name`` is one of the partial dicts of :meth:`evaluate` ('dt', 'dd', 'dphi', 'dF').
        The partials at fixed U_T - v_t and those through U_T - v_t (``st.dute``, chained once
        per field and shared) add up. Returns (rows, array): the array has shape
        (n + 1,) + station shape, row ``rows[key]`` (a slice of input_size(key) rows) the partial
        with respect to input ``key`` (component by component for the states and
        inplane_velocity), and its last row the field itself (for the quadrature partials).
        Memoized on ``st``.
        """
        keys, rows, n = self._layout(keys)
        memo = st.chained.get((name, keys))
        if memo is not None:
            return memo
        p = getattr(st, name)
        direct = {key: val for key, val in p.items() if key != "ute"}
        ute = st.chained.get(("dute", keys))
        if ute is None:
            ute = np.empty((n,) + self.shape, dtype=np.result_type(st.t, *st.dute.values()))
            self._chain_primitives(st, st.dute, rows, ute)
            st.chained["dute", keys] = ute
        field = getattr(st, _FIELD_OF_PARTIALS[name])
        out = np.empty((n + 1,) + self.shape, dtype=np.result_type(field, ute, *direct.values()))
        self._chain_primitives(st, direct, rows, out[:n])
        out[:n] += p["ute"] * ute
        out[n] = field
        st.chained[name, keys] = (rows, out)
        return rows, out

    # ---------------------------------------------------------------- integrals
    def _weight(self, st, name):
        _, power, trig, _ = self.INTEGRALS[name]
        m = 1.0 if trig is None else (self.cos if trig == "cos" else self.sin)
        return (st.r * m if power else m), (m if power else None)

    def _factor(self, name):
        return self.b_fac if self.INTEGRALS[name][3] else self.one_fac

    def integrate(self, st, name):
        """Integral ``name`` of :attr:`INTEGRALS`, shape (num_rotors, num_nodes)."""
        field = getattr(st, self.INTEGRALS[name][0])
        m, _ = self._weight(st, name)
        return self._factor(name)[..., 0] * np.sum(st.width * m * field, axis=(2, 3))

    def _moments(self, st, name, keys):
        """
        Azimuth moments (1, cos psi, sin psi) of a field's chained partials and of the field.

        Returns (rows, moments), moments of shape (n + 1, nr, nn, num_radial, 3): the rows of
        :meth:`chain` summed over the azimuth with the weights 1, cos psi and sin psi, all in
        one matrix product. Memoized on ``st``.
        """
        rows, chained = self.chain(st, name, keys)
        key = (name, tuple(rows))
        if key not in st.moments:
            naz = self.shape[-1]
            mom = chained.reshape(-1, naz) @ self.trig
            st.moments[key] = mom.reshape(chained.shape[:-1] + (3,))
        return rows, st.moments[key]

    def integrate_partials(self, st, terms, keys):
        """
        Return integrals and their partials with respect to their inputs.

        ``terms``: sequence of (name, coefficient), the integral ``name`` of
        :attr:`INTEGRALS` times a coefficient (scalar or per rotor, (num_rotors,)); the
        integrals of a call are stacked along an axis of length I. The inputs are ``keys``
        (those the station field depends on) plus station_radius and station_width (through
        the quadrature weights w = dr r^p trig(psi)). The chained partials are summed over the
        azimuth once per field (:meth:`_moments`); per (rotor, node, station) the moment times
        coefficient x dr r^p is the contribution of a station, summed over the radius for the
        inputs that are not per station.

        Returns (values, partials): values (nr, nn, I); partials input -> (nr, nn, I, n), n =
        input_size for the states and per-op, per-rotor and per-node inputs, num_radial for the
        per-station inputs and station_width.
        """
        nr = self.shape[0]
        moments, weights, dweights = [], [], []
        for name, coef in terms:
            field, power, trig, times_b = self.INTEGRALS[name]
            rows, mom = self._moments(st, "d" + field, keys)
            moments.append(mom[..., _TRIG_INDEX[trig]])
            fac = np.broadcast_to(coef * (self.b_fac if times_b else self.one_fac)[:, 0, 0], nr)
            weights.append(fac[:, None, None] * st.r[..., 0] ** power)  # (nr, 1, nrad)
            dweights.append(fac[:, None, None] * power * st.r[..., 0] ** (power - 1))
        n = sum(sl.stop - sl.start for sl in rows.values())
        mom = np.stack(moments, axis=-1)  # (n + 1, nr, nn, nrad, I)
        weight = np.stack(weights, axis=-1)  # coefficient B/N_psi r^p, (nr, 1, nrad, I)
        width = st.width  # (nr, 1, nrad, 1)
        d_width = mom[n] * weight  # (nr, nn, nrad, I)
        station = mom[:n] * (weight * width)  # per-station contributions (n, nr, nn, nrad, I)
        total = np.sum(station, axis=3).transpose(1, 2, 3, 0)  # (nr, nn, I, n)
        station = station.transpose(1, 2, 4, 3, 0)  # (nr, nn, I, nrad, n)
        out = {}
        for key, sl in rows.items():
            out[key] = station[..., sl.start] if input_kind(key) == "radial" else total[..., sl]
        # d w/d r through r^p (p = 1: dr trig)
        d_radius = np.swapaxes(mom[n] * (np.stack(dweights, axis=-1) * width), -1, -2)
        out["station_radius"] = out.get("station_radius", 0.0) + d_radius
        out["station_width"] = np.swapaxes(d_width, -1, -2)
        values = np.sum(d_width * width, axis=2)
        return values, out


#: Station fields with partials shared between components (PittPetersBladeElements.evaluate
#: with ``shared=True``): the last few, keyed by configuration, inputs and states (exact bytes).
_SHARED_FIELDS = OrderedDict()
_SHARED_FIELDS_SIZE = 2


class SparsityPatterns:
    """
    Row and column indices of the partials of the Pitt–Peters components.

    Outputs are either per station (num_rotors, num_nodes, num_radial, num_azimuth) or per
    operating point with ``k`` components (num_rotors, num_nodes, k). The value arrays of
    ``compute_partials`` / ``linearize`` follow the order of these patterns:

    - station output wrt an op input of size m: (nr, nn, nrad, naz, m);
    - station output wrt a rotor, radial or node input: (nr, nn, nrad, naz);
    - op output (k) wrt an op input of size m: (nr, nn, k, m);
    - op output wrt a rotor or node input: (nr, nn, k); wrt a radial input: (nr, nn, k, nrad).
    """

    def __init__(self, nr, nn, nrad, naz):
        self.nr, self.nn, self.nrad, self.naz = nr, nn, nrad, naz
        j, n, i, _ = np.meshgrid(
            np.arange(nr), np.arange(nn), np.arange(nrad), np.arange(naz), indexing="ij"
        )
        self._station = {
            "op": (j * nn + n).ravel(),
            "rotor": j.ravel(),
            "radial": (j * nrad + i).ravel(),
            "node": n.ravel(),
        }

    def station(self, kind, m=1):
        """Rows and columns of a station output wrt an input of the given kind."""
        base = self._station["op" if kind in ("op", "op2") else kind]
        size = base.size
        if kind in ("op", "op2") and m > 1:
            rows = np.repeat(np.arange(size), m)
            cols = (base[:, None] * m + np.arange(m)).ravel()
            return rows, cols
        return np.arange(size), base

    def op(self, k, kind, m=1):
        """Rows and columns of an op output with k components wrt an input of the given kind."""
        nr, nn, nrad = self.nr, self.nn, self.nrad
        o = np.arange(nr * nn)
        rotor, node = o // nn, o % nn
        if kind in ("op", "op2"):
            oo, a, b = np.meshgrid(o, np.arange(k), np.arange(m), indexing="ij")
            return (oo * k + a).ravel(), (oo * m + b).ravel()
        if kind == "radial":
            oo, a, i = np.meshgrid(o, np.arange(k), np.arange(nrad), indexing="ij")
            return (oo * k + a).ravel(), (rotor[oo] * nrad + i).ravel()
        rows = np.arange(nr * nn * k)
        col = rotor if kind == "rotor" else node
        return rows, np.repeat(col, k)


def input_kind(name):
    """Kind of an input or of the inflow states ('op' with 3 components)."""
    return "op" if name == "inflow_states" else PITT_PETERS_INPUTS[name][0]


def input_size(name):
    """Per-op size of an op input (3 for the states, 2 for inplane_velocity, else 1)."""
    return _OP_VECTOR.get(name, 1)


class PittPetersLoadsComp(om.ExplicitComponent):
    """
    Sectional loads over (r, psi) and hub loads of the steady Pitt–Peters rotor model.

    docs theory/rotors 'Pitt-Peters inflow', paper eq. 14, at the inflow states solved by
    :class:`~lpc_mdo.components.rotor.pitt_peters_inflow.PittPetersInflowComp` (equations in the
    module docstring). The sectional loads over (r, psi) are what the tonal
    acoustics needs for the Fourier content of the azimuthal loading
    (:class:`~lpc_mdo.components.acoustics.loads.LoadFourierComp`, same azimuths
    psi_k = 2 pi k/N_psi). Analytic sparse partials.

    Inputs
    ------
    inflow_states : float, (num_rotors, num_nodes, 3), -
        (lambda_0, lambda_c, lambda_s), inflow normalised by Omega R.
    rpm : float, (num_rotors, num_nodes), rpm
        Rotor speed.
    axial_velocity : float, (num_rotors, num_nodes), m/s
        Hub velocity relative to the air along the thrust axis (> 0: climb for a lift rotor).
    inplane_velocity : float, (num_rotors, num_nodes, 2), m/s
        Hub velocity relative to the air along the disk e_x and e_y (RotorVelocityComp).
    radius, hub_radius : float, (num_rotors,), m
        Tip and hub radius.
    station_radius, station_width : float, (num_rotors, num_radial), m
        Element-centre radii and quadrature widths (BladeStationsComp).
    chord : float, (num_rotors, num_radial), m
        Blade chord at the stations.
    twist : float, (num_rotors, num_radial), rad
        Blade pitch relative to the rotor plane at the stations.
    density, speed_of_sound, dynamic_viscosity : float, (num_nodes,), kg/m**3, m/s, Pa*s
        Atmosphere.

    Outputs
    -------
    thrust_per_span : float, (num_rotors, num_nodes, num_radial, num_azimuth), N/m
        Sectional thrust of one blade per unit span at each azimuth (if ``sectional_loads``).
    drag_per_span : float, (num_rotors, num_nodes, num_radial, num_azimuth), N/m
        Sectional in-plane drag of one blade per unit span (opposing the rotation; dQ/dr/(B r))
        (if ``sectional_loads``).
    inflow_angle : float, (num_rotors, num_nodes, num_radial, num_azimuth), rad
        phi = atan2(U_P, U_T) (if ``sectional_loads``).
    thrust : float, (num_rotors, num_nodes), N
        Rotor thrust along the thrust axis.
    torque : float, (num_rotors, num_nodes), N*m
        Shaft torque the rotor needs (power = Omega torque, RotorPerformanceComp).
    inplane_force : float, (num_rotors, num_nodes, 2), N
        In-plane hub force along the disk e_x and e_y (signed components, HubLoadsComp
        convention: the H-force against an edgewise velocity along +e_x is negative).
    hub_moment : float, (num_rotors, num_nodes, 2), N*m
        Hub moment about the disk e_x and e_y (rolling and pitching moments of a lift rotor).

    Options
    -------
    num_rotors, num_nodes, num_radial : int
        Array sizes (>= 1). Defaults 1, 1, 25.
    num_azimuth : int
        Azimuthal stations psi_k = 2 pi k/N_psi (>= 3). Default 25.
    num_blades : int or sequence of int
        Blades per rotor (one for all or one per rotor). Default 2.
    spin_direction : int or sequence of int
        +1 (rotation right-handed about the thrust axis) or -1. Default +1.
    polar : Polar
        Sectional polar. Default LinearQuadraticPolar() (docs theory/aerodynamics 'Linear-quadratic
        polar').
    tip_loss, hub_loss : bool
        Prandtl losses (default True).
    loss_placement : str
        'momentum' (default: F acts on the inflow equation and the swirl, the loads carry no
        F, as in the BEM) or 'blade_element' (docs theory/rotors 'Pitt-Peters inflow': the loads are
        multiplied by F).
    tangential_induction : bool
        Wake swirl per station (default True; module docstring).
    sectional_loads : bool
        Output the sectional loads over (r, psi) (default True). A model whose other components
        do not read them leaves them out: with the default 25 x 25 stations they are 3 x 625
        values per rotor, 60 % of the full vehicle model's outputs, and every reverse transfer
        of a total derivative costs in proportion to the output vector's length.
    """

    def initialize(self):
        declare_pitt_peters_options(self.options)
        self.options.declare(
            "sectional_loads",
            default=True,
            types=bool,
            desc="Output the sectional loads over (r, psi)",
        )

    def setup(self):
        opts = self.options
        nr, nn = opts["num_rotors"], opts["num_nodes"]
        nrad, naz = opts["num_radial"], opts["num_azimuth"]
        blades, spin = rotor_blade_options(self)
        self._field = PittPetersBladeElements(
            (nr, nn, nrad, naz),
            blades,
            spin,
            opts["polar"],
            opts["tip_loss"],
            opts["hub_loss"],
            opts["loss_placement"],
            opts["tangential_induction"],
            owner=self.msginfo,
        )
        add_pitt_peters_inputs(self, nr, nn, nrad)
        self.add_input(
            "inflow_states",
            val=np.tile([0.05, 0.0, 0.0], (nr, nn, 1)),
            units=None,
            desc="Inflow states (lambda_0, lambda_c, lambda_s) over Omega R",
        )

        self._sectional = opts["sectional_loads"]
        if self._sectional:
            shape = (nr, nn, nrad, naz)
            for name, units, desc in (
                ("thrust_per_span", "N/m", "Sectional thrust of one blade per unit span"),
                ("drag_per_span", "N/m", "Sectional in-plane drag of one blade per unit span"),
                ("inflow_angle", "rad", "Inflow angle atan2(U_P, U_T)"),
            ):
                self.add_output(
                    name, val=np.zeros(shape), units=units, desc=f"{desc} over (r, psi)"
                )
        self.add_output("thrust", val=np.zeros((nr, nn)), units="N", desc="Rotor thrust")
        self.add_output("torque", val=np.zeros((nr, nn)), units="N*m", desc="Rotor (shaft) torque")
        self.add_output(
            "inplane_force",
            val=np.zeros((nr, nn, 2)),
            units="N",
            desc="In-plane hub force along the disk e_x and e_y",
        )
        self.add_output(
            "hub_moment",
            val=np.zeros((nr, nn, 2)),
            units="N*m",
            desc="Hub moment about the disk e_x and e_y",
        )

        pat = SparsityPatterns(nr, nn, nrad, naz)
        wrt = [
            "inflow_states",
            "rpm",
            "axial_velocity",
            "inplane_velocity",
            "station_radius",
            "chord",
            "twist",
            "density",
            "dynamic_viscosity",
            "speed_of_sound",
            "radius",
        ]
        if opts["hub_loss"] and (self._field.loads_have_loss or self._field.swirl):
            wrt.append("hub_radius")
        self._wrt = wrt
        # phi = atan2(U_P, U_T - v_t): with the swirl it depends on everything the drag does.
        self._phi_wrt = (
            wrt
            if self._field.swirl
            else [
                "inflow_states",
                "rpm",
                "axial_velocity",
                "inplane_velocity",
                "station_radius",
                "radius",
            ]
        )
        for name in wrt:
            kind, m = input_kind(name), input_size(name)
            if self._sectional:
                rows, cols = pat.station(kind, m)
                self.declare_partials(
                    ["thrust_per_span", "drag_per_span"], name, rows=rows, cols=cols
                )
                if name in self._phi_wrt:
                    self.declare_partials("inflow_angle", name, rows=rows, cols=cols)
            for out, k in (("thrust", 1), ("torque", 1), ("inplane_force", 2), ("hub_moment", 2)):
                rows, cols = pat.op(k, kind, m)
                self.declare_partials(out, name, rows=rows, cols=cols)
        for out, k in (("thrust", 1), ("torque", 1), ("inplane_force", 2), ("hub_moment", 2)):
            rows, cols = pat.op(k, "radial")
            self.declare_partials(out, "station_width", rows=rows, cols=cols)

    def _values(self, inputs):
        return pitt_peters_values(self, inputs)

    def compute(self, inputs, outputs):
        fld = self._field
        st = fld.evaluate(self._values(inputs), inputs["inflow_states"])
        if self._sectional:
            outputs["thrust_per_span"] = st.t
            outputs["drag_per_span"] = st.d
            outputs["inflow_angle"] = st.phi
        ints = {
            name: fld.integrate(st, name)
            for name in ("thrust", "torque", "moment_cos", "moment_sin", "drag_sin", "drag_cos")
        }
        outputs["thrust"] = ints["thrust"]
        outputs["torque"] = ints["torque"]
        spin = fld.spin[:, None]
        outputs["inplane_force"] = np.stack([-ints["drag_sin"], -spin * ints["drag_cos"]], -1)
        outputs["hub_moment"] = np.stack([-spin * ints["moment_sin"], -ints["moment_cos"]], -1)

    def compute_partials(self, inputs, partials):
        fld = self._field
        st = fld.evaluate(self._values(inputs), inputs["inflow_states"], partials=True, shared=True)
        sectional = (
            ("thrust_per_span", "dt", self._wrt),
            ("drag_per_span", "dd", self._wrt),
            ("inflow_angle", "dphi", self._phi_wrt),
        )
        for out, name, keys in sectional if self._sectional else ():
            rows, chained = fld.chain(st, name, keys)
            for key, sl in rows.items():
                val = (
                    chained[sl.start]
                    if sl.stop == sl.start + 1
                    else np.moveaxis(chained[sl], 0, -1)
                )
                partials[out, key] = val.ravel()

        # The hub loads' components as signed integrals (as in compute), all in one call.
        spin = fld.spin
        hub_loads = (
            ("thrust", (("thrust", 1.0),)),
            ("hub_moment", (("moment_sin", -spin), ("moment_cos", -1.0))),
            ("torque", (("torque", 1.0),)),
            ("inplane_force", (("drag_sin", -1.0), ("drag_cos", -spin))),
        )
        terms = [term for _, parts in hub_loads for term in parts]
        _, ints = fld.integrate_partials(st, terms, self._wrt)
        start = 0
        for out, parts in hub_loads:
            sl = slice(start, start + len(parts))
            start = sl.stop
            for key in self._wrt + ["station_width"]:
                partials[out, key] = ints[key][:, :, sl].ravel()
