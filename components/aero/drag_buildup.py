"""Parasite-drag build-up: skin friction, form factors, interference and wetted areas."""

import math
from dataclasses import dataclass

import numpy as np
import openmdao.api as om

from lpc_mdo.checks import check_integer, check_number, check_range
from lpc_mdo.constants import SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

#: Default interference factor Q of every component (reference/models_aero_rotor_acoustics.md §5).
DEFAULT_INTERFERENCE = 1.1
#: Rotor drag area of the public LPC model (docs theory/aerodynamics 'Drag build-up'), m**2.
LPC_ROTOR_DRAG_AREA = 0.111484
#: Boom diameter assumed for the LPC boom wetted area, m (not in the sources; 1 ft).
LPC_BOOM_DIAMETER = 0.3048


def _check_fraction(owner, field, value, low=0.0, high=1.0, open_low=False):
    check_number(field, value, lower=low, upper=high, lower_open=open_low, where=owner)


@dataclass(frozen=True)
class LiftingSurfaceDrag:
    """A wing or tail of the build-up; inputs ``{name}_area`` and ``{name}_mean_aerodynamic_chord``.

    Wetted area 2 f_exp S (1 + 0.2 t/c) (Raymer), form factor
    (1 + 0.6/(x/c)_m t/c + 100 (t/c)^4) cos(sweep)^0.28, characteristic length the MAC.

    Attributes
    ----------
    name : str
    thickness_to_chord : float
        t/c, in (0, 0.5].
    max_thickness_location : float
        (x/c)_m, in (0, 1].
    sweep : float
        Sweep of the maximum-thickness line, rad (default 0).
    laminar_fraction : float
        Laminar part of the skin friction, in [0, 1] (default 0.1).
    interference_factor : float
        Q (default 1.1).
    exposed_fraction : float
        S_exposed / S, in (0, 1] (default 1: the whole reference area is wetted).
    """

    name: str
    thickness_to_chord: float
    max_thickness_location: float
    sweep: float = 0.0
    laminar_fraction: float = 0.1
    interference_factor: float = DEFAULT_INTERFERENCE
    exposed_fraction: float = 1.0

    def __post_init__(self):
        owner = f"LiftingSurfaceDrag '{self.name}'"
        _check_fraction(owner, "thickness_to_chord", self.thickness_to_chord, 0.0, 0.5, True)
        _check_fraction(
            owner, "max_thickness_location", self.max_thickness_location, 0.0, 1.0, True
        )
        _check_fraction(owner, "laminar_fraction", self.laminar_fraction)
        _check_fraction(owner, "exposed_fraction", self.exposed_fraction, 0.0, 1.0, True)
        _check_fraction(owner, "interference_factor", self.interference_factor, 0.0, 10.0, True)
        check_number(
            "sweep",
            self.sweep,
            lower=-math.pi / 2,
            upper=math.pi / 2,
            lower_open=True,
            upper_open=True,
            units="rad",
            where=owner,
        )

    @property
    def inputs(self):
        """(suffix, units, default, desc) of the component's inputs."""
        return (
            ("area", "m**2", 1.0, "planform reference area"),
            ("mean_aerodynamic_chord", "m", 1.0, "mean aerodynamic chord"),
        )

    #: Which of (wetted area, form factor, length) each input changes.
    depends = {"area": ("wetted",), "mean_aerodynamic_chord": ("length",)}

    @property
    def form_factor(self):
        """Raymer's form factor of the section (constant)."""
        tc, xm = self.thickness_to_chord, self.max_thickness_location
        return (1.0 + 0.6 / xm * tc + 100.0 * tc**4) * math.cos(self.sweep) ** 0.28

    def evaluate(self, values):
        """Wetted area, form factor, length and their derivatives w.r.t. the inputs."""
        k = 2.0 * self.exposed_fraction * (1.0 + 0.2 * self.thickness_to_chord)
        area, mac = values["area"], values["mean_aerodynamic_chord"]
        _check_positive(self.name, (("area", area), ("mean_aerodynamic_chord", mac)))
        one, zero = np.ones_like(area), np.zeros_like(area)
        return (
            k * area,
            self.form_factor * one,
            mac,
            {"area": (k * one, zero, zero), "mean_aerodynamic_chord": (zero, zero, one)},
        )


@dataclass(frozen=True)
class BodyDrag:
    """A fuselage-like body; inputs ``{name}_length``, ``{name}_max_height``, ``{name}_max_width``.

    Fineness f = L/max(H, W), form factor 1 + 60/f^3 + f/400 (docs theory/aerodynamics 'Drag
    build-up'), characteristic length L, wetted area pi D L (1 - 2/f_e)^(2/3) (1 + 1/f_e^2) with the
    equivalent diameter
    D = sqrt(H W) and f_e = L/D (Torenbeek, Synthesis of Subsonic Airplane Design, 1982, App. F;
    valid for f_e > 2).

    Attributes
    ----------
    name : str
    laminar_fraction : float
    interference_factor : float
    """

    name: str
    laminar_fraction: float = 0.1
    interference_factor: float = DEFAULT_INTERFERENCE

    def __post_init__(self):
        owner = f"BodyDrag '{self.name}'"
        _check_fraction(owner, "laminar_fraction", self.laminar_fraction)
        _check_fraction(owner, "interference_factor", self.interference_factor, 0.0, 10.0, True)

    @property
    def inputs(self):
        """(suffix, units, default, desc) of the component's inputs."""
        return (
            ("length", "m", 1.0, "body length"),
            ("max_height", "m", 0.1, "maximum body height"),
            ("max_width", "m", 0.1, "maximum body width"),
        )

    #: Which of (wetted area, form factor, length) each input changes.
    depends = {
        "length": ("wetted", "form", "length"),
        "max_height": ("wetted", "form"),
        "max_width": ("wetted", "form"),
    }

    def evaluate(self, values):
        """Wetted area, form factor, length and their derivatives w.r.t. the inputs."""
        length, height, width = values["length"], values["max_height"], values["max_width"]
        _check_positive(
            self.name, (("length", length), ("max_height", height), ("max_width", width))
        )
        zero, one = np.zeros_like(length), np.ones_like(length)
        # Form factor with f = L/max(H, W); the selection is made on the real parts (CS-safe).
        h_larger = height.real >= width.real
        dmax = np.where(h_larger, height, width)
        f = length / dmax
        ff = 1.0 + 60.0 / f**3 + f / 400.0
        dff_df = -180.0 / f**4 + 1.0 / 400.0
        dff = {
            "length": dff_df / dmax,
            "max_height": np.where(h_larger, -dff_df * f / dmax, zero),
            "max_width": np.where(h_larger, zero, -dff_df * f / dmax),
        }
        # Torenbeek wetted area with the equivalent diameter.
        d = np.sqrt(height * width)
        fe = length / d
        if not fe.real[0] > 2.0:
            raise om.AnalysisError(
                f"{self.name}_length/sqrt({self.name}_max_height*{self.name}_max_width) = "
                f"{fe.real[0]:.6g}; the wetted-area estimate needs a fineness ratio > 2."
            )
        g1 = (1.0 - 2.0 / fe) ** (2.0 / 3.0)
        g2 = 1.0 + 1.0 / fe**2
        swet = np.pi * d * length * g1 * g2
        dg = (2.0 / 3.0) * (1.0 - 2.0 / fe) ** (-1.0 / 3.0) * 2.0 / fe**2 * g2 - g1 * 2.0 / fe**3
        # d swet = pi g1 g2 (L dd + d dL) + pi d L dg dfe; fe = L/d
        dswet_dl = np.pi * g1 * g2 * d + np.pi * d * length * dg / d
        dswet_dd = np.pi * g1 * g2 * length - np.pi * d * length * dg * length / d**2
        dd_dh, dd_dw = 0.5 * d / height, 0.5 * d / width
        return (
            swet,
            ff,
            length,
            {
                "length": (dswet_dl, dff["length"], one),
                "max_height": (dswet_dd * dd_dh, dff["max_height"], zero),
                "max_width": (dswet_dd * dd_dw, dff["max_width"], zero),
            },
        )


@dataclass(frozen=True)
class FixedFormFactorDrag:
    """Identical parts with a given form factor (e.g. the 8 booms).

    Inputs ``{name}_length`` (characteristic length) and ``{name}_wetted_area`` (of one part);
    the drag area is multiplied by ``count``.

    Attributes
    ----------
    name : str
    form_factor : float
    count : int
    laminar_fraction : float
    interference_factor : float
    """

    name: str
    form_factor: float
    count: int = 1
    laminar_fraction: float = 0.1
    interference_factor: float = DEFAULT_INTERFERENCE

    def __post_init__(self):
        owner = f"FixedFormFactorDrag '{self.name}'"
        _check_fraction(owner, "laminar_fraction", self.laminar_fraction)
        _check_fraction(owner, "interference_factor", self.interference_factor, 0.0, 10.0, True)
        _check_fraction(owner, "form_factor", self.form_factor, 0.0, 10.0, True)
        check_integer("count", self.count, lower=1, where=owner)

    @property
    def inputs(self):
        """(suffix, units, default, desc) of the component's inputs."""
        return (
            ("length", "m", 1.0, "characteristic length of one part"),
            ("wetted_area", "m**2", 1.0, "wetted area of one part"),
        )

    #: Which of (wetted area, form factor, length) each input changes.
    depends = {"length": ("length",), "wetted_area": ("wetted",)}

    def evaluate(self, values):
        """Wetted area, form factor, length and their derivatives w.r.t. the inputs."""
        length, swet = values["length"], values["wetted_area"]
        _check_positive(self.name, (("length", length), ("wetted_area", swet)))
        zero, one = np.zeros_like(length), np.ones_like(length)
        return (
            self.count * swet,
            self.form_factor * one,
            length,
            {"length": (zero, zero, one), "wetted_area": (self.count * one, zero, zero)},
        )


def _check_positive(owner, pairs):
    for field, value in pairs:
        check_range(f"{owner}_{field}", value, lower=0.0, lower_open=True, error=om.AnalysisError)


_SPEC_TYPES = (LiftingSurfaceDrag, BodyDrag, FixedFormFactorDrag)


def _check_components(name, value):
    if not isinstance(value, (tuple, list)) or len(value) == 0:
        raise ValueError(f"{name} = {value!r}; must be a non-empty tuple of drag components.")
    for spec in value:
        if not isinstance(spec, _SPEC_TYPES):
            raise ValueError(
                f"{name}: {spec!r} is not a LiftingSurfaceDrag, BodyDrag or FixedFormFactorDrag."
            )
    names = [s.name for s in value]
    if len(set(names)) != len(names):
        raise ValueError(f"{name}: component names {names} must be unique.")


class DragBuildupComp(om.ExplicitComponent):
    """
    Parasite drag of the vehicle by component build-up, vectorized over flight conditions.

    docs theory/aerodynamics 'Drag build-up' (CADDEE ``drag_buildup.py``, without its quirks Q5–Q7),
    for each component i with characteristic length L_i, wetted area S_wet,i, form factor FF_i,
    interference factor Q_i and laminar fraction p_i:

    - Re_i = rho V L_i / mu (floored smoothly: sqrt(Re^2 + Re_min^2), so V = 0 stays finite),
      M = V/a;
    - C_f,i = p_i 1.328/sqrt(Re_i) + (1 - p_i) 0.455/((log10 Re_i)^2.58 (1 + 0.144 M^2)^0.65);
    - (C_D S)_i = C_f,i FF_i Q_i S_wet,i;
    - C_D0 = k (sum_i (C_D S)_i + (C_D S)_lumped)/S_ref, D = C_D0 q S_ref, q = rho V^2/2, with the
      drag factor k (1.0; the later public script used 1.5);
    - the force acts along the relative wind: F = D e_D, e_D = -(cos a cos b, sin b, sin a cos b)
      (body axes; not the horizontal direction of quirk Q5).

    Form factors and wetted areas come from the component descriptions
    (:class:`LiftingSurfaceDrag`, :class:`BodyDrag`, :class:`FixedFormFactorDrag`) and their
    geometry inputs, so planform and fuselage design variables reach the drag. Use
    :func:`lpc_drag_components` for the LPC vehicle.

    Inputs
    ------
    {name}_{field} : float, scalar
        Geometry of each component, see the description classes (m or m**2).
    lumped_drag_area : float, scalar, m**2
        Drag area added as is (the LPC rotors: 0.111484 m**2).
    reference_area : float, scalar, m**2
    speed : float, (nn,), m/s
    density : float, (nn,), kg/m**3
    dynamic_viscosity : float, (nn,), Pa*s
    speed_of_sound : float, (nn,), m/s
    angle_of_attack, sideslip_angle : float, (nn,), rad

    Outputs
    -------
    wetted_areas : float, (nc,), m**2
    form_factors : float, (nc,)
    skin_friction_coefficients : float, (nn, nc)
    drag_areas : float, (nn, nc), m**2
        C_f FF Q S_wet of each component (without the drag factor).
    CD0 : float, (nn,)
    parasite_drag : float, (nn,), N
    parasite_drag_force : float, (nn, 3), N, body axes

    Options
    -------
    components : tuple
        Component descriptions (nc of them).
    num_nodes : int
    drag_factor : float
        Multiplier k of C_D0 and the drag (default 1.0).
    min_reynolds : float
        Re_min of the smooth Reynolds floor (default 1e3; changes C_f by < 1e-7 at Re > 1e5).
    """

    def initialize(self):
        self.options.declare(
            "components",
            types=(tuple, list),
            check_valid=_check_components,
            desc="tuple of LiftingSurfaceDrag/BodyDrag/FixedFormFactorDrag",
        )
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )
        self.options.declare(
            "drag_factor",
            default=1.0,
            types=float,
            lower=0.0,
            desc="multiplier of C_D0 and the parasite drag",
        )
        self.options.declare(
            "min_reynolds",
            default=1.0e3,
            types=float,
            lower=1.0,
            desc="smooth floor of the Reynolds number",
        )

    def setup(self):
        nn = self.options["num_nodes"]
        comps = self.options["components"]
        nc = len(comps)
        for spec in comps:
            for suffix, units, default, desc in spec.inputs:
                self.add_input(
                    f"{spec.name}_{suffix}", default, units=units, desc=f"{spec.name}: {desc}"
                )
        self.add_input("lumped_drag_area", 0.0, units="m**2", desc="drag area added as is")
        self.add_input("reference_area", 1.0, units="m**2", desc="reference area of C_D0")
        for name, units, default, desc in (
            ("speed", "m/s", 0.0, "airspeed"),
            ("density", "kg/m**3", SEA_LEVEL_DENSITY, "air density"),
            ("dynamic_viscosity", "Pa*s", 1.7894e-5, "dynamic viscosity of air"),
            ("speed_of_sound", "m/s", SEA_LEVEL_SPEED_OF_SOUND, "speed of sound"),
            ("angle_of_attack", "rad", 0.0, "angle of attack"),
            ("sideslip_angle", "rad", 0.0, "sideslip angle"),
        ):
            self.add_input(name, np.full(nn, default), units=units, desc=desc)

        self.add_output("wetted_areas", np.ones(nc), units="m**2", desc="wetted area per component")
        self.add_output("form_factors", np.ones(nc), units=None, desc="form factor per component")
        self.add_output(
            "skin_friction_coefficients",
            np.zeros((nn, nc)),
            units=None,
            desc="skin-friction coefficient per condition and component",
        )
        self.add_output(
            "drag_areas",
            np.zeros((nn, nc)),
            units="m**2",
            desc="C_f FF Q S_wet per condition and component",
        )
        self.add_output("CD0", np.zeros(nn), units=None, desc="parasite-drag coefficient")
        self.add_output("parasite_drag", np.zeros(nn), units="N", desc="parasite drag")
        self.add_output(
            "parasite_drag_force",
            np.zeros((nn, 3)),
            units="N",
            desc="parasite-drag force along the relative wind, body axes",
        )

        ar, node_i = np.arange(nn), np.repeat(np.arange(nn), nc)
        nodewise = ("speed", "density", "dynamic_viscosity", "speed_of_sound")
        for out in ("skin_friction_coefficients", "drag_areas"):
            self.declare_partials(out, nodewise, rows=np.arange(nn * nc), cols=node_i)
        for out in ("CD0", "parasite_drag"):
            self.declare_partials(out, nodewise, rows=ar, cols=ar)
            self.declare_partials(out, "lumped_drag_area", rows=ar, cols=np.zeros(nn, int))
        self.declare_partials("CD0", "reference_area", rows=ar, cols=np.zeros(nn, int))
        rows3, node3 = np.arange(3 * nn), np.repeat(ar, 3)
        self.declare_partials(
            "parasite_drag_force",
            list(nodewise) + ["angle_of_attack", "sideslip_angle"],
            rows=rows3,
            cols=node3,
        )
        self.declare_partials(
            "parasite_drag_force", "lumped_drag_area", rows=rows3, cols=np.zeros(3 * nn, int)
        )
        for i, spec in enumerate(comps):
            for suffix, *_ in spec.inputs:
                name = f"{spec.name}_{suffix}"
                dep = spec.depends[suffix]
                if "wetted" in dep:
                    self.declare_partials("wetted_areas", name, rows=[i], cols=[0])
                if "form" in dep:
                    self.declare_partials("form_factors", name, rows=[i], cols=[0])
                if "length" in dep:
                    self.declare_partials(
                        "skin_friction_coefficients", name, rows=ar * nc + i, cols=np.zeros(nn, int)
                    )
                self.declare_partials("drag_areas", name, rows=ar * nc + i, cols=np.zeros(nn, int))
                self.declare_partials(
                    ["CD0", "parasite_drag"], name, rows=ar, cols=np.zeros(nn, int)
                )
                self.declare_partials(
                    "parasite_drag_force", name, rows=rows3, cols=np.zeros(3 * nn, int)
                )

    def _evaluate(self, inputs):
        comps = self.options["components"]
        swet, ff, length, derivs = [], [], [], []
        for spec in comps:
            values = {suffix: inputs[f"{spec.name}_{suffix}"] for suffix, *_ in spec.inputs}
            s, f, length_i, d = spec.evaluate(values)
            swet.append(s[0])
            ff.append(f[0])
            length.append(length_i[0])
            derivs.append(d)
        return np.array(swet), np.array(ff), np.array(length), derivs

    def _friction(self, inputs, length):
        """C_f (nn, nc) and its derivatives w.r.t. Re (nn, nc) and M (nn, nc)."""
        comps = self.options["components"]
        lam = np.array([s.laminar_fraction for s in comps])[None, :]
        rho, speed = inputs["density"][:, None], inputs["speed"][:, None]
        mu, a = inputs["dynamic_viscosity"][:, None], inputs["speed_of_sound"][:, None]
        re_raw = rho * speed * length[None, :] / mu
        re_min = self.options["min_reynolds"]
        re = np.sqrt(re_raw**2 + re_min**2)
        mach = speed / a
        comp = (1.0 + 0.144 * mach**2) ** 0.65
        log_re = np.log10(re)
        cf = lam * 1.328 / np.sqrt(re) + (1.0 - lam) * 0.455 / (log_re**2.58 * comp)
        dcf_dre = -0.664 * lam * re**-1.5 - (1.0 - lam) * 0.455 * 2.58 / (
            log_re**3.58 * comp * re * np.log(10.0)
        )
        dcf_dre = dcf_dre * re_raw / re  # through the floor
        dcf_dm = (
            -(1.0 - lam)
            * 0.455
            / log_re**2.58
            * 0.65
            * 0.288
            * mach
            / ((1.0 + 0.144 * mach**2) ** 1.65)
        )
        return cf, re_raw, dcf_dre, dcf_dm

    def compute(self, inputs, outputs):
        comps = self.options["components"]
        swet, ff, length, _ = self._evaluate(inputs)
        q_int = np.array([s.interference_factor for s in comps])
        cf, *_ = self._friction(inputs, length)
        area = cf * (ff * q_int * swet)[None, :]
        k = self.options["drag_factor"]
        total = np.sum(area, axis=1) + inputs["lumped_drag_area"]
        q = 0.5 * inputs["density"] * inputs["speed"] ** 2
        outputs["wetted_areas"] = swet
        outputs["form_factors"] = ff
        outputs["skin_friction_coefficients"] = cf
        outputs["drag_areas"] = area
        outputs["CD0"] = k * total / inputs["reference_area"]
        drag = k * total * q
        outputs["parasite_drag"] = drag
        outputs["parasite_drag_force"] = drag[:, None] * self._direction(inputs)[0]

    @staticmethod
    def _direction(inputs):
        alpha, beta = inputs["angle_of_attack"], inputs["sideslip_angle"]
        ca, sa, cb, sb = np.cos(alpha), np.sin(alpha), np.cos(beta), np.sin(beta)
        e_d = -np.stack([ca * cb, sb, sa * cb], axis=-1)
        de_da = -np.stack([-sa * cb, np.zeros_like(sa), ca * cb], axis=-1)
        de_db = -np.stack([-ca * sb, cb, -sa * sb], axis=-1)
        return e_d, de_da, de_db

    def compute_partials(self, inputs, partials):
        comps = self.options["components"]
        k = self.options["drag_factor"]
        swet, ff, length, derivs = self._evaluate(inputs)
        q_int = np.array([s.interference_factor for s in comps])
        cf, re_raw, dcf_dre, dcf_dm = self._friction(inputs, length)
        rho, speed = inputs["density"], inputs["speed"]
        mu, a = inputs["dynamic_viscosity"], inputs["speed_of_sound"]
        geom = ff * q_int * swet  # (nc,)
        area = cf * geom[None, :]
        total = np.sum(area, axis=1) + inputs["lumped_drag_area"]
        q = 0.5 * rho * speed**2
        s_ref = inputs["reference_area"]
        e_d, de_da, de_db = self._direction(inputs)

        # Reynolds number Re = rho V L/mu, Mach number M = V/a
        re_per = (rho * length[:, None] / mu).T  # dRe/dV, (nn, nc)
        dcf = {
            "speed": dcf_dre * re_per + dcf_dm / a[:, None],
            "density": dcf_dre * re_raw / rho[:, None],
            "dynamic_viscosity": -dcf_dre * re_raw / mu[:, None],
            "speed_of_sound": -dcf_dm * (speed / a**2)[:, None],
        }
        dq = {
            "speed": rho * speed,
            "density": 0.5 * speed**2,
            "dynamic_viscosity": np.zeros_like(q),
            "speed_of_sound": np.zeros_like(q),
        }
        for name, d in dcf.items():
            d_area = d * geom[None, :]
            d_total = np.sum(d_area, axis=1)
            d_drag = k * (d_total * q + total * dq[name])
            partials["skin_friction_coefficients", name] = d.ravel()
            partials["drag_areas", name] = d_area.ravel()
            partials["CD0", name] = k * d_total / s_ref
            partials["parasite_drag", name] = d_drag
            partials["parasite_drag_force", name] = (d_drag[:, None] * e_d).ravel()
        drag = k * total * q
        partials["parasite_drag_force", "angle_of_attack"] = (drag[:, None] * de_da).ravel()
        partials["parasite_drag_force", "sideslip_angle"] = (drag[:, None] * de_db).ravel()
        partials["CD0", "lumped_drag_area"] = np.full_like(q, k) / s_ref
        partials["parasite_drag", "lumped_drag_area"] = k * q
        partials["parasite_drag_force", "lumped_drag_area"] = (k * q[:, None] * e_d).ravel()
        partials["CD0", "reference_area"] = -k * total / s_ref**2

        # Geometry: d(C_f FF Q S_wet) with C_f depending on the length through Re.
        dcf_dl = dcf_dre * (rho * speed / mu)[:, None]  # (nn, nc)
        for i, spec in enumerate(comps):
            for suffix, (d_swet, d_ff, d_len) in derivs[i].items():
                name = f"{spec.name}_{suffix}"
                d_swet, d_ff, d_len = d_swet[0], d_ff[0], d_len[0]
                d_cf = dcf_dl[:, i] * d_len
                d_area = q_int[i] * (
                    d_cf * ff[i] * swet[i] + cf[:, i] * (d_ff * swet[i] + ff[i] * d_swet)
                )
                dep = spec.depends[suffix]
                if "wetted" in dep:
                    partials["wetted_areas", name] = d_swet
                if "form" in dep:
                    partials["form_factors", name] = d_ff
                if "length" in dep:
                    partials["skin_friction_coefficients", name] = d_cf
                partials["drag_areas", name] = d_area
                partials["CD0", name] = k * d_area / s_ref
                partials["parasite_drag", name] = k * d_area * q
                partials["parasite_drag_force", name] = (k * (d_area * q)[:, None] * e_d).ravel()


def max_thickness_sweep(surface, mirrored=True):
    """Sweep of the maximum-thickness line of a ``lpc_mdo.vehicle.LiftingSurface`` (rad).

    tan L_m = tan L_le - (x/c)_m (c_root - c_tip)/b_half, with b_half = b/2 for a mirrored
    surface and b (the height) for the vertical tail.
    """
    half = surface.span / 2.0 if mirrored else surface.span
    return math.atan(
        math.tan(surface.sweep)
        - surface.max_thickness_location * (surface.root_chord - surface.tip_chord) / half
    )


def lpc_drag_components(vehicle=None, boom_diameter=LPC_BOOM_DIAMETER):
    """
    Return the drag-build-up components and input values of the LPC vehicle.

    See docs theory/aerodynamics 'Drag build-up'. Components: wing, horizontal_tail, vertical_tail
    (LiftingSurfaceDrag with the vehicle's t/c, (x/c)_m, laminar fraction and maximum-thickness
    sweep), fuselage (BodyDrag) and booms (8 parts, FF 1.1, L_c 2.4384 m, wetted area pi d L_c with
    the assumed diameter d, 1 ft by default; the sources give no boom size). The rotor hubs are the
    lumped drag area 0.111484 m**2.

    Returns
    -------
    components : tuple
        For the ``components`` option of :class:`DragBuildupComp`.
    values : dict
        Input name -> value (SI) for the geometry, lumped drag area and reference area.
    """
    from lpc_mdo.vehicle import reference_vehicle

    v = vehicle or reference_vehicle()
    comps, values = [], {}
    for name, surf, mirrored in (
        ("wing", v.wing, True),
        ("horizontal_tail", v.horizontal_tail, True),
        ("vertical_tail", v.vertical_tail, False),
    ):
        comps.append(
            LiftingSurfaceDrag(
                name,
                surf.thickness_to_chord,
                surf.max_thickness_location,
                sweep=max_thickness_sweep(surf, mirrored),
                laminar_fraction=surf.laminar_fraction,
            )
        )
        values[f"{name}_area"] = surf.area
        values[f"{name}_mean_aerodynamic_chord"] = surf.mean_aerodynamic_chord
    comps.append(BodyDrag("fuselage"))
    values["fuselage_length"] = v.fuselage.length
    values["fuselage_max_height"] = v.fuselage.max_height
    values["fuselage_max_width"] = v.fuselage.max_width
    comps.append(
        FixedFormFactorDrag("booms", v.booms.form_factor, count=len(v.booms.attach_points))
    )
    values["booms_length"] = v.booms.length
    values["booms_wetted_area"] = math.pi * boom_diameter * v.booms.length
    values["lumped_drag_area"] = LPC_ROTOR_DRAG_AREA
    values["reference_area"] = v.wing.area
    return tuple(comps), values
