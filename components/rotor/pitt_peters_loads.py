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

from lpc_mdo.checks import check_choice
from lpc_mdo.components.aero.polar import LinearQuadraticPolar, Polar
from lpc_mdo.components.geometry.blade import azimuth_angles, per_rotor
from lpc_mdo.components.rotor.bem_inflow import check_section_inputs
from lpc_mdo.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

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
        (dicts ``dt``, ``dd``, ``dphi``, ``dF``; keys 'up', 'ut', 'vx', 'vip2', 'theta',
        'chord', 'r', 'radius', 'hub_radius', 'density', 'dynamic_viscosity',
        'speed_of_sound'; 'vip2' is norm(inplane_velocity)^2, through the swirl's mass flow).
        """
        if not shared:
            return self._evaluate(x, states, partials)
        key = (
            self._signature,
            partials,
            np.asarray(states).dtype.str,
            np.asarray(states).tobytes(),
            *(np.asarray(x[name]).tobytes() for name in sorted(x)),
        )
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
            vt, sec = self._solve_swirl(geo, ut, um, kappa)
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
            dute = self._swirl_partials(raw, sec, vt, um, kappa, rho, r, up)
        else:
            dute = {"ut": 1.0}
        for name, p in raw.items():
            f_ute = p.pop("ute")
            for key, val in dute.items():
                p[key] = p.get(key, 0.0) + f_ute * val
            setattr(st, name, p)
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
    def chain(self, st, p, keys):
        """
        Chain a station field's partials to the component inputs (and inflow states).

        ``p`` holds the primitive partials (from :meth:`evaluate`); returns name -> array of the
        station shape, with a trailing axis of 3 ('inflow_states') or 2 ('inplane_velocity').
        """
        shape = self.shape
        zero = np.zeros(shape)
        f_up, f_ut = p["up"], p["ut"]
        out = {}
        for key in keys:
            if key == "inflow_states":
                out[key] = np.stack(
                    [
                        f_up * st.omega * st.big_r,
                        f_up * st.omega * st.r * self.cos,
                        f_up * st.omega * st.r * self.sin,
                    ],
                    axis=-1,
                )
            elif key == "rpm":
                out[key] = RPM_TO_RAD_S * (f_up * (st.big_r * st.lam0 + st.r * st.g) + f_ut * st.r)
            elif key == "axial_velocity":
                out[key] = f_up + p.get("vx", zero)
            elif key == "inplane_velocity":
                out[key] = np.stack([f_ut * self.sin, f_ut * self.spin4 * self.cos], axis=-1)
                if "vip2" in p:
                    out[key] = out[key] + 2.0 * p["vip2"][..., None] * st.v_ip
            elif key == "radius":
                out[key] = f_up * st.omega * st.lam0 + p.get("radius", zero)
            elif key == "station_radius":
                out[key] = f_up * st.omega * st.g + f_ut * st.omega + p.get("r", zero)
            elif key == "twist":
                out[key] = p.get("theta", zero)
            else:  # hub_radius, chord, density, dynamic_viscosity, speed_of_sound
                out[key] = p.get(key, zero)
            out[key] = np.broadcast_to(out[key], shape + out[key].shape[4:])
        return out

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

    def integrate_partials(self, st, names, chained):
        """
        Return the partials of the integrals ``names`` (one field) with respect to their inputs.

        The inputs are those in ``chained`` (the field's :meth:`chain` output) plus
        station_radius and station_width (through the quadrature). All integrals and inputs in
        one batched product: the chained partials stacked along a last axis (k values), the
        integrals' weights w_i = dr r^p trig along another, and per (rotor, node, station)
        W^T V sums over the azimuth; the inputs that are not per station also over the radius.

        Returns name -> (input -> array): (nr, nn) for per-op, per-rotor and per-node inputs,
        (nr, nn, k) for inflow_states and inplane_velocity, (nr, nn, num_radial) for per-station
        inputs.
        """
        names = list(names)
        field = getattr(st, self.INTEGRALS[names[0]][0])
        shape = self.shape
        keys = list(chained)
        sizes = [_OP_VECTOR.get(key, 1) for key in keys]
        stack = np.empty(shape + (sum(sizes),), dtype=np.result_type(*chained.values()))
        col = 0
        for key, size in zip(keys, sizes, strict=True):
            stack[..., col : col + size] = chained[key].reshape(shape + (size,))
            col += size
        weights = [self._weight(st, name) for name in names]
        wm = np.empty(shape + (len(names),), dtype=np.result_type(st.width, field))
        for i, (m, _) in enumerate(weights):
            wm[..., i] = st.width * m
        # (nr, nn, nrad, I, naz) @ (nr, nn, nrad, naz, K) -> per-station azimuth sums.
        radial = np.swapaxes(wm, -1, -2) @ stack
        total = np.sum(radial, axis=2)
        out = {}
        for i, name in enumerate(names):
            fac = self._factor(name)
            res = {}
            col = 0
            for key, size in zip(keys, sizes, strict=True):
                kind = PITT_PETERS_INPUTS[key][0] if key in PITT_PETERS_INPUTS else "op"
                if key in _OP_VECTOR:
                    res[key] = fac * total[:, :, i, col : col + size]
                elif kind == "radial":
                    res[key] = fac * radial[:, :, :, i, col]
                else:
                    res[key] = fac[..., 0] * total[:, :, i, col]
                col += size
            m, dm_dr = weights[i]
            res["station_width"] = fac * np.sum(np.broadcast_to(m * field, shape), axis=3)
            if dm_dr is not None:
                extra = fac * np.sum(np.broadcast_to(st.width * dm_dr * field, shape), axis=3)
                res["station_radius"] = res.get("station_radius", 0.0) + extra
            out[name] = res
        return out


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
        Sectional thrust of one blade per unit span at each azimuth.
    drag_per_span : float, (num_rotors, num_nodes, num_radial, num_azimuth), N/m
        Sectional in-plane drag of one blade per unit span (opposing the rotation; dQ/dr/(B r)).
    inflow_angle : float, (num_rotors, num_nodes, num_radial, num_azimuth), rad
        phi = atan2(U_P, U_T).
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
    """

    def initialize(self):
        declare_pitt_peters_options(self.options)

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

        shape = (nr, nn, nrad, naz)
        self.add_output(
            "thrust_per_span",
            val=np.zeros(shape),
            units="N/m",
            desc="Sectional thrust of one blade per unit span over (r, psi)",
        )
        self.add_output(
            "drag_per_span",
            val=np.zeros(shape),
            units="N/m",
            desc="Sectional in-plane drag of one blade per unit span over (r, psi)",
        )
        self.add_output(
            "inflow_angle",
            val=np.zeros(shape),
            units="rad",
            desc="Inflow angle atan2(U_P, U_T) over (r, psi)",
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
            rows, cols = pat.station(kind, m)
            self.declare_partials(["thrust_per_span", "drag_per_span"], name, rows=rows, cols=cols)
            if name in self._phi_wrt:
                self.declare_partials("inflow_angle", name, rows=rows, cols=cols)
            for out, k in (("thrust", 1), ("torque", 1), ("inplane_force", 2), ("hub_moment", 2)):
                rows, cols = pat.op(k, kind, m)
                self.declare_partials(out, name, rows=rows, cols=cols)
        for out, k in (("thrust", 1), ("torque", 1), ("inplane_force", 2), ("hub_moment", 2)):
            rows, cols = pat.op(k, "radial")
            self.declare_partials(out, "station_width", rows=rows, cols=cols)

    def _values(self, inputs):
        check_pitt_peters_inputs(self, inputs, self.options["hub_loss"])
        return {name: inputs[name] for name in PITT_PETERS_INPUTS}

    def compute(self, inputs, outputs):
        fld = self._field
        st = fld.evaluate(self._values(inputs), inputs["inflow_states"])
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
        keys = self._wrt
        dt = fld.chain(st, st.dt, keys)
        dd = fld.chain(st, st.dd, keys)
        dphi = fld.chain(st, st.dphi, self._phi_wrt)
        for name in keys:
            partials["thrust_per_span", name] = dt[name].ravel()
            partials["drag_per_span", name] = dd[name].ravel()
            if name in self._phi_wrt:
                partials["inflow_angle", name] = dphi[name].ravel()

        spin = fld.spin[:, None]
        ints = fld.integrate_partials(st, ("thrust", "moment_cos", "moment_sin"), dt)
        ints.update(fld.integrate_partials(st, ("torque", "drag_sin", "drag_cos"), dd))
        comps = {
            "thrust": [(ints["thrust"], 1.0)],
            "torque": [(ints["torque"], 1.0)],
            "inplane_force": [(ints["drag_sin"], -1.0), (ints["drag_cos"], -spin)],
            "hub_moment": [(ints["moment_sin"], -spin), (ints["moment_cos"], -1.0)],
        }
        for out, parts in comps.items():
            for name in keys + ["station_width"]:
                if name not in parts[0][0]:
                    continue
                vals = []
                for d, sign in parts:
                    v = d[name]
                    sgn = np.reshape(sign, np.shape(sign) + (1,) * (v.ndim - np.ndim(sign)))
                    vals.append(sgn * v)
                partials[out, name] = np.stack(vals, axis=2).ravel()
