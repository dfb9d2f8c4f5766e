"""Blade-element momentum (BEM) theory: sectional equations and the inflow-angle solve.

docs theory/rotors 'Blade-element momentum' and paper eq. 12–13. This module holds

- :class:`BEMSections`, the sectional BEM equations of every station of several rotors at
  several operating points (one flat array), with their exact forward derivatives; shared by
  the inflow-angle component here and the loads component in ``bem_loads.py``;
- :class:`BEMInflowComp`, the ImplicitComponent whose state is the inflow angle of every
  station, solved by a vectorized bracketed Newton–bisection in ``solve_nonlinear``.

Residual (propeller convention: V_x > 0 is flow through the disk as for a propeller moving
forward, V_t = Omega r, sigma = B c/(2 pi r), alpha = theta - phi)::

    C_x = C_l cos(phi) - C_d sin(phi),        C_theta = C_l sin(phi) + C_d cos(phi)
    R(phi) = sigma C_x - 4 F sin(phi)abs(sin(phi))
             + (V_x/V_t) (4 F abs(sin(phi)) cos(phi) + sigma C_theta)

For phi > 0 (flow down through the disk, every normal operating point) this is paper eq. 13
with Prandtl's F and the local advance ratio V_x/V_t = J/(pi r/R) written out (docs theory/rotors
'BEM inflow residual'; the paper's eq. 13 drops F and the r/R), i.e. V_t (sigma C_x - 4 F sin^2) +
V_x (2 F sin 2phi +
sigma C_theta) of docs theory/rotors 'BEM inflow residual' divided by V_t. It is Ning's
guaranteed-convergence residual (Ning 2014, Wind Energy 17, "A simple solution method for the blade
element momentum equations with
guaranteed convergence") in propeller form, R_N = sin(phi)(1 - k) - (V_x/V_t) cos(phi)(1 + k')
with k = sigma C_x/(4 F sin^2 phi), k' = sigma C_theta/(4 F sin phi cos phi) (axial and swirl
induction a = k/(1 - k), a' = k'/(1 + k'): wake rotation and drag in both inductions),
multiplied by -4 F sin(phi). The product keeps every root and removes the 1/sin(phi) pole, so R
is continuous on the whole circle and hover (V_x = 0) is not a special case. For phi < 0 (flow
up through the disk) the momentum mass flux is rho abs(u_x) (sin^2 -> sin abs(sin),
sin cos -> abs(sin) cos), which is Ning's sign flip of k in that region; without it the momentum
thrust would have the wrong sign there and those stations would have no root.
F = F_tip F_hub with F_tip = (2/pi) arccos(exp(-(B/2)(R - r)/(r abs(sin phi)))) and
F_hub = (2/pi) arccos(exp(-(B/2)(r - r_h)/(r_h abs(sin phi)))) (classical Prandtl, docs
theory/rotors 'BEM inflow residual').

Bracket: R(0) = sigma (C_l(theta) + (V_x/V_t) C_d(theta)), and
R(+-pi/2) = -+(4 F + sigma C_d(theta -+ pi/2)) +- (V_x/V_t) sigma C_l(theta -+ pi/2), whose
first terms dominate at any practical advance ratio. So [0, pi/2] holds a root whenever the
section lifts at zero inflow angle (Ning's guarantee; windmilling stations, with negative lift
and thrust at high advance ratio, have their root there too), and [-pi/2, 0] holds one when it
does not (a blade pitched below zero lift pushes the air up). The quadrants are searched in
the order [0, pi/2], [-pi/2, 0], [pi/2, pi], [-pi, -pi/2] (the polar is defined on -pi..pi);
within a quadrant the first sign change on a 12-interval grid is taken (nearest the quadrant's
start, as CCBlade does) and refined by safeguarded Newton steps (bisection whenever a Newton
step leaves the bracket or converges slowly). A station without any sign change raises
om.AnalysisError.

Limitation: in descent (V_x < 0) the momentum equations have several roots (vortex-ring state,
where momentum theory does not hold); the search returns the root nearest phi = 0+, which is
continuous with hover. The reference model (docs theory/rotors 'BEM inflow residual') excludes V_x <
0 altogether.
"""

from collections import OrderedDict

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.polar import LinearQuadraticPolar, Polar
from lpc_mdo.components.geometry.blade import per_rotor
from lpc_mdo.core.checks import check_range
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND
from lpc_mdo.core.numerics import safeguarded_newton

#: Tip-loss forms (docs theory/rotors 'BEM inflow residual'; 'bladead' divides by R instead of r,
#: docs theory/rotors 'Public-code compatibility').
TIP_LOSS_FORMS = ("classical", "bladead")

_RPM_TO_RAD_S = RPM_TO_RAD_S
_TWO_OVER_PI = 2.0 / np.pi
_ABS_SIN_FLOOR = 1.0e-9  # |sin phi| floor in the Prandtl exponent (F = 1 to all digits there)
_GRID_INTERVALS = 12  # bracket-search intervals per quadrant (7.5 deg)
_MAX_ITER = 100
_PHI_TOL = 1.0e-13  # rad, Newton step / bracket width at convergence
_RES_TOL = 1.0e-9  # accepted |R| after convergence (R is dimensionless, O(1))

#: Search order of the bracket: (start, end) of each quadrant, searched from start.
QUADRANTS = ((0.0, 0.5 * np.pi), (0.0, -0.5 * np.pi), (0.5 * np.pi, np.pi), (-0.5 * np.pi, -np.pi))

#: Inputs of the sectional equations: name -> (kind, units, default, description). The kind
#: says which indices of a station (rotor i, node j, radial k) the input is indexed by.
SECTION_INPUTS = {
    "axial_velocity": (
        "rotor_node",
        "m/s",
        0.0,
        "Freestream velocity through the disk along the thrust axis (V_x > 0: "
        "flow as for a propeller moving forward, climb)",
    ),
    "rpm": ("rotor_node", "rpm", 1000.0, "Rotor speed"),
    "station_radius": ("rotor_station", "m", None, "Radius of the blade-element centres"),
    "radius": ("rotor", "m", 1.0, "Rotor tip radius"),
    "hub_radius": ("rotor", "m", 0.2, "Hub radius"),
    "chord": ("rotor_station", "m", 0.1, "Blade chord at the stations"),
    "twist": (
        "rotor_station",
        "rad",
        0.2,
        "Blade twist (pitch to the rotor plane) at the stations",
    ),
    "density": ("node", "kg/m**3", SEA_LEVEL_DENSITY, "Air density"),
    "speed_of_sound": ("node", "m/s", SEA_LEVEL_SPEED_OF_SOUND, "Speed of sound"),
    "dynamic_viscosity": ("node", "Pa*s", 1.7894e-5, "Dynamic viscosity of air"),
}


def declare_bem_options(options):
    """Declare the options shared by the BEM components (and the rotor group)."""
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
        "num_blades",
        default=2,
        types=(int, list, tuple, np.ndarray),
        desc="Blades per rotor: one int for all rotors or one per rotor",
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
        "tip_loss_form",
        default="classical",
        values=TIP_LOSS_FORMS,
        desc="'classical' (B/2)(R - r)/(r sin phi), or 'bladead' with R in place of "
        "r (docs theory/rotors 'Public-code compatibility')",
    )


def station_shapes(num_rotors, num_nodes, num_radial):
    """Broadcast shape of each input kind within the station array (rotor, node, radial)."""
    return {
        "rotor_node": (num_rotors, num_nodes, 1),
        "rotor_station": (num_rotors, 1, num_radial),
        "rotor": (num_rotors, 1, 1),
        "node": (1, num_nodes, 1),
    }


def input_shape(kind, num_rotors, num_nodes, num_radial):
    """Shape of an input of the given kind."""
    return {
        "rotor_node": (num_rotors, num_nodes),
        "rotor_station": (num_rotors, num_radial),
        "rotor": (num_rotors,),
        "node": (num_nodes,),
    }[kind]


def station_columns(kind, num_rotors, num_nodes, num_radial):
    """Flat index of the input element each station (rotor, node, radial; flattened) uses."""
    shape = station_shapes(num_rotors, num_nodes, num_radial)[kind]
    idx = np.arange(int(np.prod(shape))).reshape(shape)
    return np.broadcast_to(idx, (num_rotors, num_nodes, num_radial)).ravel()


#: Linearized section states shared between components (:func:`linearized_sections`): the last
#: few, keyed by configuration, inputs and inflow angle (exact bytes).
_SHARED_LINEARIZATIONS = OrderedDict()
_SHARED_LINEARIZATIONS_SIZE = 2


def linearized_sections(comp, inputs, inflow_angle, names):
    """
    Sections, their state and local partials with the loads (``local_partials(loads=True)``).

    BEMInflowComp and BEMLoadsComp linearize at the same inputs and inflow angle, so the second
    takes the first's result from a small cache keyed by the component's configuration (the
    polar by identity, kept alive by the entry) and the exact bytes of every section input and
    of the inflow angle.
    """
    opts = comp.options
    phi = np.asarray(inflow_angle)
    key = (
        comp._shape,
        np.asarray(comp._blades).tobytes(),
        id(opts["polar"]),
        opts["tip_loss"],
        opts["hub_loss"],
        opts["tip_loss_form"],
        tuple(names),
        phi.dtype.str,
        phi.tobytes(),
        *(np.asarray(inputs[name]).tobytes() for name in SECTION_INPUTS),
    )
    hit = _SHARED_LINEARIZATIONS.get(key)
    if hit is None:
        sections = comp._sections(inputs)
        st = sections.evaluate(phi.ravel())
        local = sections.local_partials(st, names, loads=True)
        hit = _SHARED_LINEARIZATIONS[key] = (opts["polar"], sections, st, local)
        while len(_SHARED_LINEARIZATIONS) > _SHARED_LINEARIZATIONS_SIZE:
            _SHARED_LINEARIZATIONS.popitem(last=False)
    return hit[1:]


def station_flow(rpm, station_radius, axial_velocity, chord, density, speed_of_sound, viscosity):
    """
    In-plane speed, undisturbed resultant U, chord Reynolds number and Mach number of stations.

    V_t = Omega r, U = sqrt(V_x^2 + V_t^2), Re = rho U c / mu, M = U / a (docs theory/rotors
    'Stations and disk frame'); the arguments broadcast against each other (complex-step safe).
    """
    vt = _RPM_TO_RAD_S * rpm * station_radius
    u = np.sqrt(axial_velocity**2 + vt**2)
    return vt, u, density * u * chord / viscosity, u / speed_of_sound


def add_section_inputs(comp, num_rotors, num_nodes, num_radial, names=None):
    """
    Add the inputs of the sectional equations (SECTION_INPUTS) to a component.

    ``names`` selects some of them (default: all).
    """
    for name in SECTION_INPUTS if names is None else names:
        kind, units, default, desc = SECTION_INPUTS[name]
        shape = input_shape(kind, num_rotors, num_nodes, num_radial)
        if default is None:  # station radius: element centres of a unit rotor with a 0.2 hub
            val = np.broadcast_to(0.2 + 0.8 * (np.arange(num_radial) + 0.5) / num_radial, shape)
        else:
            val = np.full(shape, default)
        comp.add_input(name, val=np.array(val, dtype=float), units=units, desc=desc)


def check_section_inputs(
    comp,
    inputs,
    hub_loss,
    names=None,
    positive=("rpm", "radius", "chord", "density", "speed_of_sound", "dynamic_viscosity"),
):
    """
    Check the physical range of the sectional inputs of a rotor component (BEM or Pitt-Peters).

    Every input of ``names`` (a table like :data:`SECTION_INPUTS`, the default) must be finite,
    those of ``positive`` > 0, ``0 < hub_radius < radius`` (``0 <=`` without hub loss) and
    ``hub_radius < station_radius < radius``; otherwise om.AnalysisError names the input, the
    first offending entry and the allowed range (:func:`lpc_mdo.core.checks.check_range`; the
    values may come from an optimizer).
    """

    def check(name, **bounds):
        check_range(name, inputs[name], error=om.AnalysisError, where=comp.msginfo, **bounds)

    table = SECTION_INPUTS if names is None else names
    for name in table:
        check(name)
    for name in positive:
        check(name, lower=0.0, lower_open=True, units=table[name][1])
    rh, big_r = np.real(inputs["hub_radius"]), np.real(inputs["radius"])
    check("hub_radius", lower=0.0, upper=big_r, lower_open=hub_loss, upper_open=True, units="m")
    check(
        "station_radius",
        lower=rh[:, None],
        upper=big_r[:, None],
        lower_open=True,
        upper_open=True,
        units="m",
    )


def _cs_sign(x):
    """Sign of the real part (complex-step safe: a constant under the perturbation)."""
    return np.sign(np.real(x))


class BEMSections:
    """
    Sectional BEM equations of all stations, flattened over (rotor, node, radial station).

    Built from the component inputs; phi-independent quantities are evaluated once. Then
    :meth:`evaluate` gives the phi-dependent state, :meth:`tangent` its exact directional
    derivative for a seed of input and inflow-angle perturbations (hand-derived forward-mode
    chain rule of the equations in the module docstring), and :meth:`loads` and the tangent's
    ``loads=True`` branch the blade-element loads. All of it is complex-step safe.

    Loads at the converged inflow angle (docs theory/rotors 'Loads and coefficients'; blade-element
    form, equal to the momentum form there): the resultant velocity W = u_x/sin(phi) with u_x = 4 F
    V_t sin^2 phi / H and
    H = 4 F abs(sin(phi)) cos(phi) + sigma C_theta gives W = 4 F V_t abs(sin(phi))/H, and per blade
    and
    unit span thrust t = rho W^2 c C_x / 2 and in-plane drag d = rho W^2 c C_theta / 2
    (dQ/dr = B r d).
    Reynolds and Mach numbers use the undisturbed resultant U = sqrt(V_x^2 + V_t^2) (docs
    theory/rotors 'Stations and disk frame').
    """

    def __init__(
        self,
        inputs,
        num_blades,
        polar,
        tip_loss=True,
        hub_loss=True,
        tip_loss_form="classical",
        shape=None,
    ):
        nr, nn, nrad = shape
        self.shape = shape
        self.size = nr * nn * nrad
        self.polar = polar
        self.tip_loss, self.hub_loss = tip_loss, hub_loss
        self.tip_loss_form = tip_loss_form
        kinds = station_shapes(nr, nn, nrad)

        def flat(array, kind):
            return np.broadcast_to(np.reshape(array, kinds[kind]), (nr, nn, nrad)).ravel()

        c = {name: flat(inputs[name], SECTION_INPUTS[name][0]) for name in SECTION_INPUTS}
        c["half_b"] = 0.5 * flat(np.asarray(num_blades, dtype=float), "rotor")
        c["omega"] = _RPM_TO_RAD_S * c["rpm"]
        c["vt"], c["u"], c["re"], c["mach"] = station_flow(
            c["rpm"], c["station_radius"], c["axial_velocity"], c["chord"], c["density"],
            c["speed_of_sound"], c["dynamic_viscosity"],
        )  # fmt: skip
        c["lam"] = c["axial_velocity"] / c["vt"]
        c["sigma"] = c["half_b"] * c["chord"] / (np.pi * c["station_radius"])
        r, big_r, rh = c["station_radius"], c["radius"], c["hub_radius"]
        norm = r if tip_loss_form == "classical" else big_r
        c["k_tip"] = c["half_b"] * (big_r - r) / norm
        if hub_loss:
            c["k_hub"] = c["half_b"] * (r - rh) / rh
        self.c = c

    # ------------------------------------------------------------------ values
    def _const(self, name, idx, ndim):
        value = self.c[name] if idx is None else self.c[name][idx]
        return value.reshape(value.shape + (1,) * (ndim - 1))

    @staticmethod
    def _prandtl(k, abs_s):
        """F = (2/pi) arccos(exp(-k/abs(sin phi))), its exponent f and dF/df."""
        f = k / abs_s
        e = np.exp(-f)
        big_f = _TWO_OVER_PI * np.arccos(e)
        one_minus = np.where(np.real(e) < 1.0 - 1e-15, 1.0 - e * e, 2e-15)
        return f, big_f, _TWO_OVER_PI * e / np.sqrt(one_minus)

    def evaluate(self, phi, idx=None):
        """
        Phi-dependent sectional state at inflow angles ``phi``.

        phi has shape (m,) or (m, g): one value (or g values) per selected station; idx selects
        the m stations (None: all). Returns a dict with the residual under 'res'.
        """
        nd = np.ndim(phi)

        def k(name):
            return self._const(name, idx, nd)

        st = {"phi": phi, "idx": idx}
        alpha = k("twist") - phi
        pv = self.polar.evaluate(alpha, k("re"), k("mach"))
        s, co = np.sin(phi), np.cos(phi)
        sgn = _cs_sign(s)
        abs_sin = s * sgn
        floored = np.real(abs_sin) < _ABS_SIN_FLOOR
        abs_s = np.where(floored, _ABS_SIN_FLOOR, abs_sin)
        st.update(
            alpha=alpha,
            pv=pv,
            s=s,
            co=co,
            sgn=sgn,
            abs_sin=abs_sin,
            abs_s=abs_s,
            dabs=np.where(floored, 0.0, sgn),
        )
        if self.tip_loss:
            st["f_tip"], st["F_tip"], st["g_tip"] = self._prandtl(k("k_tip"), abs_s)
        else:
            st["F_tip"] = np.ones_like(abs_s)
        if self.hub_loss:
            st["f_hub"], st["F_hub"], st["g_hub"] = self._prandtl(k("k_hub"), abs_s)
        else:
            st["F_hub"] = np.ones_like(abs_s)
        big_f = st["F_tip"] * st["F_hub"]
        cl, cd = pv.cl, pv.cd
        cx = cl * co - cd * s
        cth = cl * s + cd * co
        sigma = k("sigma")
        g = sigma * cx - 4.0 * big_f * s * abs_sin
        h = 4.0 * big_f * abs_sin * co + sigma * cth
        st.update(F=big_f, cx=cx, cth=cth, G=g, H=h, res=g + k("lam") * h)
        return st

    def residual(self, phi, idx=None):
        """Residual R(phi) (dimensionless) at the selected stations."""
        return self.evaluate(phi, idx)["res"]

    def loads(self, st):
        """Resultant velocity W (m/s) and per-blade thrust and drag per span (N/m)."""
        idx, nd = st["idx"], np.ndim(st["phi"])
        vt = self._const("vt", idx, nd)
        w = 4.0 * st["F"] * vt * st["abs_sin"] / st["H"]
        q = 0.5 * self._const("density", idx, nd) * w * w * self._const("chord", idx, nd)
        return w, q * st["cx"], q * st["cth"]

    # ------------------------------------------------------------------ derivatives
    def tangent(self, st, seed, loads=False):
        """
        Directional derivative of the residual (and the loads) for a seed.

        Parameters
        ----------
        st : dict
            State from :meth:`evaluate` (all stations, idx None, or a selection).
        seed : dict
            Perturbation of 'inflow_angle' (rad) and of any name of SECTION_INPUTS, in the
            inputs' units (rpm in rpm): a scalar (or an array per selected station).
        loads : bool
            Also return the derivatives of (thrust per span, drag per span).

        Returns
        -------
        dres or (dres, dthrust_per_span, ddrag_per_span)
        """
        idx, nd = st["idx"], np.ndim(st["phi"])

        def k(name):
            return self._const(name, idx, nd)

        def d(name):
            return seed.get(name, 0.0)

        dphi, dvx, dr, dc = d("inflow_angle"), d("axial_velocity"), d("station_radius"), d("chord")
        r, c_, vt, omega = k("station_radius"), k("chord"), k("vt"), k("omega")
        domega = _RPM_TO_RAD_S * d("rpm")
        dvt = r * domega + omega * dr
        u = k("u")
        du = (k("axial_velocity") * dvx + vt * dvt) / u
        dlam = (dvx - k("lam") * dvt) / vt
        dre = k("re") * (
            d("density") / k("density")
            + du / u
            + dc / c_
            - d("dynamic_viscosity") / k("dynamic_viscosity")
        )
        dmach = k("mach") * (du / u - d("speed_of_sound") / k("speed_of_sound"))
        sigma = k("sigma")
        dsigma = sigma * (dc / c_ - dr / r)

        pv, s, co = st["pv"], st["s"], st["co"]
        dalpha = d("twist") - dphi
        dcl = pv.dcl_dalpha * dalpha + pv.dcl_dreynolds * dre + pv.dcl_dmach * dmach
        dcd = pv.dcd_dalpha * dalpha + pv.dcd_dreynolds * dre + pv.dcd_dmach * dmach
        ds, dco = co * dphi, -s * dphi
        dabs = st["dabs"] * co * dphi
        abs_s = st["abs_s"]
        half_b = k("half_b")

        d_f_tip = 0.0
        if self.tip_loss:
            big_r, dbig_r = k("radius"), d("radius")
            if self.tip_loss_form == "classical":  # K = (B/2)(R/r - 1)
                dk = half_b * (dbig_r / r - big_r * dr / (r * r))
            else:  # K = (B/2)(1 - r/R)
                dk = half_b * (r * dbig_r / (big_r * big_r) - dr / big_r)
            d_f_tip = st["g_tip"] * (dk - st["f_tip"] * dabs) / abs_s
        d_f_hub = 0.0
        if self.hub_loss:  # K = (B/2)(r/r_h - 1)
            rh = k("hub_radius")
            dk = half_b * (dr / rh - r * d("hub_radius") / (rh * rh))
            d_f_hub = st["g_hub"] * (dk - st["f_hub"] * dabs) / abs_s
        big_f = st["F"]
        dbig_f = st["F_hub"] * d_f_tip + st["F_tip"] * d_f_hub

        cl, cd, cx, cth = pv.cl, pv.cd, st["cx"], st["cth"]
        dcx = dcl * co + cl * dco - dcd * s - cd * ds
        dcth = dcl * s + cl * ds + dcd * co + cd * dco
        a_s = st["abs_sin"]
        da_s = st["sgn"] * ds
        dg = dsigma * cx + sigma * dcx - 4.0 * (dbig_f * s * a_s + big_f * (ds * a_s + s * da_s))
        h = st["H"]
        dh = (
            4.0 * (dbig_f * a_s * co + big_f * (da_s * co + a_s * dco))
            + dsigma * cth
            + sigma * dcth
        )
        dres = dg + dlam * h + k("lam") * dh
        if not loads:
            return dres

        w = 4.0 * big_f * vt * a_s / h
        dw = 4.0 * (dbig_f * vt * a_s + big_f * dvt * a_s + big_f * vt * da_s) / h - w * dh / h
        rho = k("density")
        q = 0.5 * rho * w * w * c_
        dq = 0.5 * w * (d("density") * w * c_ + 2.0 * rho * dw * c_ + rho * w * dc)
        return dres, dq * cx + q * dcx, dq * cth + q * dcth

    def local_partials(self, st, names, loads=False):
        """
        Local derivatives wrt each name (unit seeds): dict name -> array or tuple.

        All seeds in one :meth:`tangent` pass: seed j is the unit vector e_j along a new
        leading axis, which every quantity of the pass broadcasts along (the stations are
        few, so one pass over K times the points costs about what one pass costs).
        """
        names = list(names)
        shape = (len(names),) + np.shape(st["phi"])
        eye = np.eye(len(names)).reshape((len(names), len(names)) + (1,) * np.ndim(st["phi"]))
        out = self.tangent(st, dict(zip(names, eye, strict=True)), loads=loads)
        if loads:
            out = [np.broadcast_to(o, shape) for o in out]
            return {name: tuple(o[j] for o in out) for j, name in enumerate(names)}
        out = np.broadcast_to(out, shape)
        return {name: out[j] for j, name in enumerate(names)}

    # ------------------------------------------------------------------ solve
    def solve(self, owner="", guess=None):
        """
        Inflow angle of every station by bracketing and safeguarded Newton (real inputs).

        The bracket is the first sign change of the residual on the quadrant grid, always (so
        the root does not depend on ``guess``); Newton starts from ``guess`` (e.g. the previous
        solution, flat, rad) where it lies inside that bracket, else from its regula-falsi
        point. A warm start near the root takes 1-2 Newton steps instead of about 5.

        Returns
        -------
        ndarray (size,)
            The inflow angles, rad.

        Raises
        ------
        om.AnalysisError
            If a station has no sign change on any quadrant or does not converge.
        """
        n = self.size
        lo, hi = np.zeros(n), np.zeros(n)
        f_lo, f_hi = np.zeros(n), np.zeros(n)
        todo = np.arange(n)
        frac = np.linspace(0.0, 1.0, _GRID_INTERVALS + 1)
        for start, end in QUADRANTS:
            if todo.size == 0:
                break
            grid = start + (end - start) * frac
            phi = np.broadcast_to(grid, (todo.size, grid.size))
            f = self.residual(phi, todo)
            change = f[:, :-1] * f[:, 1:] <= 0.0
            found = np.any(change, axis=1)
            first = np.argmax(change, axis=1)[found]
            sel = todo[found]
            rows = np.flatnonzero(found)
            a, b = grid[first], grid[first + 1]
            fa, fb = f[rows, first], f[rows, first + 1]
            swap = a > b
            lo[sel], hi[sel] = np.where(swap, b, a), np.where(swap, a, b)
            f_lo[sel], f_hi[sel] = np.where(swap, fb, fa), np.where(swap, fa, fb)
            todo = todo[~found]
        if todo.size:
            self._fail(todo, "no sign change of the inflow-angle residual on -pi..pi", owner)
        return self._refine(lo, hi, f_lo, f_hi, owner, guess)

    def _refine(self, lo, hi, f_lo, f_hi, owner, guess=None):
        """Safeguarded Newton (:func:`lpc_mdo.core.numerics.safeguarded_newton`) in [lo, hi]."""

        def residual(phi, idx):
            st = self.evaluate(phi, idx)
            return st["res"], self.tangent(st, {"inflow_angle": 1.0})

        def fail(stations, why):
            self._fail(stations, why, owner)

        phi = safeguarded_newton(
            residual,
            lo,
            hi,
            f_lower=f_lo,
            f_upper=f_hi,
            x0=guess,
            xtol_abs=_PHI_TOL,
            xtol_rel=0.0,
            maxiter=_MAX_ITER,
            indexed=True,
            variable="inflow_angle",
            units="rad",
            where=owner,
            fail=fail,
        )
        res = self.residual(phi)
        bad = ~(np.abs(res) <= _RES_TOL)
        if np.any(bad):
            self._fail(np.flatnonzero(bad), f"residual above {_RES_TOL:g} after the solve", owner)
        return phi

    def newton_polish(self, phi, steps=2):
        """Take a few plain Newton steps (used under complex step, from the real solution)."""
        for _ in range(steps):
            st = self.evaluate(phi)
            phi = phi - st["res"] / self.tangent(st, {"inflow_angle": 1.0})
        return phi

    def _fail(self, stations, why, owner):
        nr, nn, nrad = self.shape
        i, j, k = np.unravel_index(stations[:5], (nr, nn, nrad))
        c = self.c
        detail = ", ".join(
            f"(rotor {a}, node {b}, station {s_}: rpm {c['rpm'][q].real:.6g}, axial_velocity "
            f"{c['axial_velocity'][q].real:.6g} m/s, twist {c['twist'][q].real:.6g} rad)"
            for a, b, s_, q in zip(i, j, k, stations[:5], strict=True)
        )
        more = f" and {stations.size - 5} more" if stations.size > 5 else ""
        raise om.AnalysisError(f"{owner}: BEM inflow-angle solve failed ({why}) at {detail}{more}.")


class BEMInflowComp(om.ImplicitComponent):
    """
    Inflow angle of every blade station of several rotors at several operating points (BEM).

    Paper eq. 13 with F and r/R written out (docs theory/rotors 'BEM inflow residual'), in Ning's
    guaranteed-convergence form; see the module docstring for the residual and the bracket.
    ``solve_nonlinear`` brackets and refines all stations at once (vectorized);
    ``linearize`` gives the exact partials (the residual of a station depends on its own inflow
    angle only, so dR/dphi is diagonal) and ``solve_linear`` divides by that diagonal, so no
    DirectSolver is needed (LinearRunOnce in the parent group is enough). Under complex step the
    real solution is polished by two complex Newton steps, so the component is CS-safe. A failed
    solve raises om.AnalysisError.

    Inputs
    ------
    axial_velocity : float, (num_rotors, num_nodes), m/s
        Freestream velocity along the thrust axis, V_x (> 0 as for a propeller moving forward).
    rpm : float, (num_rotors, num_nodes), rpm
        Rotor speed (> 0).
    station_radius : float, (num_rotors, num_radial), m
        Radius of the element centres, in (hub_radius, radius).
    radius : float, (num_rotors,), m
        Tip radius R (tip loss).
    hub_radius : float, (num_rotors,), m
        Hub radius r_h (hub loss).
    chord : float, (num_rotors, num_radial), m
        Chord (> 0).
    twist : float, (num_rotors, num_radial), rad
        Blade pitch to the rotor plane theta.
    density, speed_of_sound, dynamic_viscosity : float, (num_nodes,), kg/m**3, m/s, Pa*s
        Atmosphere (Reynolds and Mach numbers of the polar).

    Outputs
    -------
    inflow_angle : float, (num_rotors, num_nodes, num_radial), rad
        Inflow angle phi of each station (state; residual eq. 13, dimensionless).

    Options
    -------
    num_rotors, num_nodes, num_radial : int
        Array sizes (>= 1). Defaults 1, 1, 25.
    num_blades : int or sequence of int
        Blades per rotor (>= 1). Default 2.
    polar : Polar
        Sectional airfoil model. Default LinearQuadraticPolar() (docs theory/aerodynamics
        'Linear-quadratic polar').
    tip_loss, hub_loss : bool
        Prandtl tip and hub loss. Default True.
    tip_loss_form : str
        'classical' (default) or 'bladead' (docs theory/rotors 'Public-code compatibility' switch).
    """

    def initialize(self):
        declare_bem_options(self.options)

    def setup(self):
        opts = self.options
        nr, nn, nrad = opts["num_rotors"], opts["num_nodes"], opts["num_radial"]
        self._shape = (nr, nn, nrad)
        self._blades = per_rotor(
            opts["num_blades"], nr, "num_blades", kind=int, lower=1, owner=self.msginfo
        )
        add_section_inputs(self, nr, nn, nrad)
        self.add_output(
            "inflow_angle",
            val=np.full((nr, nn, nrad), 0.1),
            units="rad",
            desc="Inflow angle of each blade station (BEM state)",
        )

        ar = np.arange(nr * nn * nrad)
        self.declare_partials("inflow_angle", "inflow_angle", diagonal=True)
        self._wrt = [name for name in SECTION_INPUTS if self._depends_on(name)]
        for name in self._wrt:
            cols = station_columns(SECTION_INPUTS[name][0], nr, nn, nrad)
            self.declare_partials("inflow_angle", name, rows=ar, cols=cols)
        self._dres_dphi = None

    def _depends_on(self, name):
        if name == "radius":
            return self.options["tip_loss"]
        if name == "hub_radius":
            return self.options["hub_loss"]
        return True

    def _sections(self, inputs):
        check_section_inputs(self, inputs, self.options["hub_loss"])
        opts = self.options
        return BEMSections(
            inputs,
            self._blades,
            opts["polar"],
            opts["tip_loss"],
            opts["hub_loss"],
            opts["tip_loss_form"],
            self._shape,
        )

    def apply_nonlinear(self, inputs, outputs, residuals):
        sections = self._sections(inputs)
        residuals["inflow_angle"] = sections.residual(outputs["inflow_angle"].ravel()).reshape(
            self._shape
        )

    def solve_nonlinear(self, inputs, outputs):
        guess = np.real(outputs["inflow_angle"]).ravel()  # non-finite entries start cold
        if self.under_complex_step:
            real = {name: inputs[name].real for name in SECTION_INPUTS}
            opts = self.options
            phi = BEMSections(
                real,
                self._blades,
                opts["polar"],
                opts["tip_loss"],
                opts["hub_loss"],
                opts["tip_loss_form"],
                self._shape,
            ).solve(self.msginfo, guess)
            phi = self._sections(inputs).newton_polish(phi.astype(complex))
        else:
            phi = self._sections(inputs).solve(self.msginfo, guess)
        outputs["inflow_angle"] = phi.reshape(self._shape)

    def linearize(self, inputs, outputs, partials):
        # With the loads' derivatives too: BEMLoadsComp, at the same inputs and inflow angle,
        # reads them from the shared cache instead of evaluating the sections again.
        sections, st, local = linearized_sections(
            self, inputs, outputs["inflow_angle"], ["inflow_angle"] + self._wrt
        )
        local = {name: value[0] for name, value in local.items()}
        diag = np.real(local["inflow_angle"])
        bad = ~np.isfinite(diag) | (diag == 0.0)
        if np.any(bad):
            idx = np.unravel_index(np.flatnonzero(bad)[:5], self._shape)
            raise om.AnalysisError(
                f"{self.msginfo}: dR/d(inflow_angle) is zero or not finite at (rotor, node, "
                f"station) {list(zip(*(i.tolist() for i in idx), strict=True))}: a double root "
                "of the BEM residual; the inflow angle is not differentiable there."
            )
        for name, value in local.items():
            partials["inflow_angle", name] = value
        self._dres_dphi = diag

    def solve_linear(self, d_outputs, d_residuals, mode):
        diag = self._dres_dphi.reshape(self._shape)
        if mode == "fwd":
            d_outputs["inflow_angle"] = d_residuals["inflow_angle"] / diag
        else:
            d_residuals["inflow_angle"] = d_outputs["inflow_angle"] / diag
