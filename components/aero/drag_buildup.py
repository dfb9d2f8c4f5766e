"""Parasite-drag build-up: skin friction, form factors, interference and wetted areas."""

import math

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.drag_parts import (
    DEFAULT_INTERFERENCE,
    PART_TYPES,
    BluffDrag,
    BodyDrag,
    FixedFormFactorDrag,
    LiftingSurfaceDrag,
    SizedBluffDrag,
)
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

__all__ = [
    "DEFAULT_INTERFERENCE",
    "BluffDrag",
    "BodyDrag",
    "DragBuildupComp",
    "FixedFormFactorDrag",
    "LiftingSurfaceDrag",
    "LPC_LEAKAGE_PROTUBERANCE",
    "SizedBluffDrag",
    "max_thickness_sweep",
    "raymer_ga_tyre",
]
#: Boom diameter, m: 1 ft (MCEVS/NASA OpenVSP LPC boom; not in the CAD table, an assumption).
LPC_BOOM_DIAMETER = 0.3048
#: Interference factor of the booms: Raymer, Aircraft Design, 6th ed., sec. 12.5.5, "nacelle or
#: store mounted directly on the fuselage or wing", Q = 1.5.
LPC_BOOM_INTERFERENCE = 1.5
#: Blade thickness ratio for the blade wetted area 2 (1 + 0.2 t/c) c l (NACA 0012 rotor sections).
LPC_BLADE_THICKNESS = 0.12
#: Stopped lift-rotor hub: short cylinder, axis vertical, diameter = boom diameter and height
#: half of it (assumptions: the sources give no hub size), C_D 0.63 on d h: Hoerner,
#: Fluid-Dynamic Drag, 1965, ch. 3, finite circular cylinders in cross flow, l/d = 1 (the
#: smallest tabulated ratio; 2-D subcritical value 1.2).
LPC_HUB_DIAMETER, LPC_HUB_HEIGHT, LPC_HUB_CD = 0.3048, 0.1524, 0.63
#: Lift-rotor pylon (motor mount between boom and hub): streamline strut, C_D 0.05 on frontal area
#: (Raymer, 6th ed., Table 12.6, streamline strut 1/6 < t/c < 1/3); thickness 0.1524 m assumed,
#: height = the absolute difference of z_hub and z_boom from the CAD hub and boom attach points.
LPC_PYLON_THICKNESS, LPC_PYLON_CD = 0.1524, 0.05
#: Landing gear, fixed tricycle (assumed as on the NASA LPC OpenVSP model; GUAM lists a gear mass
#: of 8.48 slug): tyres from Raymer, 6th ed., Table 11.1 (general aviation: D = 1.51 W^0.349,
#: width = 0.7150 W^0.312, inches, W the load per wheel in lb; mains 90 % of the gross weight),
#: C_D 0.25 on D x width ("regular wheel and tire", Raymer Table 12.6); three round struts
#: (C_D 0.30, Raymer Table 12.6) 0.5 m long, 0.0762 m diameter (assumed).
LPC_MAIN_GEAR_FRACTION = 0.9
LPC_WHEEL_CD, LPC_STRUT_CD, LPC_STRUT_LENGTH, LPC_STRUT_DIAMETER = 0.25, 0.30, 0.5, 0.0762
#: Leakage and protuberance allowance, fraction of the summed parasite drag areas (Raymer, 6th
#: ed., sec. 12.5, leakage and protuberance drag estimated as a percentage of the parasite drag:
#: 2-5 % for transports; the upper end is taken for the many joints of the LPC).
LPC_LEAKAGE_PROTUBERANCE = 0.05


def raymer_ga_tyre(load_kg):
    """Tyre (diameter, width) in m of a general-aviation wheel carrying ``load_kg``.

    Raymer, Aircraft Design, 6th ed., Table 11.1: D = 1.51 W^0.349, width = 0.7150 W^0.312,
    inches, W in lb.
    """
    w_lb = load_kg / 0.45359237
    return 1.51 * w_lb**0.349 * 0.0254, 0.7150 * w_lb**0.312 * 0.0254


_SPEC_TYPES = PART_TYPES


def _check_components(name, value):
    if not isinstance(value, (tuple, list)) or len(value) == 0:
        raise ValueError(f"{name} = {value!r}; must be a non-empty tuple of drag components.")
    for spec in value:
        if not isinstance(spec, _SPEC_TYPES):
            raise ValueError(
                f"{name}: {spec!r} is not a LiftingSurfaceDrag, BodyDrag, FixedFormFactorDrag, "
                "BluffDrag or SizedBluffDrag."
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
    :func:`lpc_mdo.groups.vehicle_drag.lpc_drag_components` for the LPC vehicle.

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
            "allowance_fraction",
            default=0.0,
            types=float,
            lower=0.0,
            upper=1.0,
            desc="leakage and protuberance allowance, fraction of the summed drag areas",
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
        self.add_output(
            "drag_breakdown",
            np.zeros((nn, nc + 2)),
            units=None,
            desc="C_D0 per part, then the lumped drag area and the allowance",
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
        nb = nc + 2
        self.declare_partials(
            "drag_breakdown", nodewise, rows=np.arange(nn * nb), cols=np.repeat(ar, nb)
        )
        self.declare_partials(
            "drag_breakdown",
            "lumped_drag_area",
            rows=np.concatenate([ar * nb + nc, ar * nb + nc + 1]),
            cols=np.zeros(2 * nn, int),
        )
        self.declare_partials(
            "drag_breakdown", "reference_area", rows=np.arange(nn * nb), cols=np.zeros(nn * nb, int)
        )
        for out in ("CD0", "parasite_drag"):
            self.declare_partials(out, nodewise, diagonal=True)
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
                    "drag_breakdown",
                    name,
                    rows=np.concatenate([ar * nb + i, ar * nb + nc + 1]),
                    cols=np.zeros(2 * nn, int),
                )
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
        # BluffDrag parts carry their D/q as the "wetted area": C_f = 1, independent of Re, M.
        friction = np.array([s.friction for s in comps])[None, :]
        cf = np.where(friction, cf, 1.0)
        dcf_dre = np.where(friction, dcf_dre, 0.0)
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
        dcf_dm = np.where(friction, dcf_dm, 0.0)
        return cf, re_raw, dcf_dre, dcf_dm

    def compute(self, inputs, outputs):
        comps = self.options["components"]
        swet, ff, length, _ = self._evaluate(inputs)
        q_int = np.array([s.interference_factor for s in comps])
        cf, *_ = self._friction(inputs, length)
        area = cf * (ff * q_int * swet)[None, :]
        k0 = self.options["drag_factor"]
        f_a = self.options["allowance_fraction"]
        k = k0 * (1.0 + f_a)
        lumped = inputs["lumped_drag_area"]
        total = np.sum(area, axis=1) + lumped
        q = 0.5 * inputs["density"] * inputs["speed"] ** 2
        s_ref = inputs["reference_area"]
        outputs["drag_breakdown"] = (
            k0
            * np.concatenate(
                [area, np.broadcast_to(lumped, (len(q), 1)), f_a * total[:, None]], axis=1
            )
            / s_ref
        )
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
        k0 = self.options["drag_factor"]
        f_a = self.options["allowance_fraction"]
        k = k0 * (1.0 + f_a)
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
            d_breakdown = np.concatenate(
                [d_area, np.zeros_like(d_total)[:, None], f_a * d_total[:, None]], axis=1
            )
            partials["drag_breakdown", name] = (k0 * d_breakdown / s_ref).ravel()
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
        nn = len(q)
        partials["drag_breakdown", "lumped_drag_area"] = (
            np.concatenate([np.full(nn, k0), np.full(nn, k0 * f_a)]) / s_ref
        )
        breakdown = np.concatenate(
            [area, np.broadcast_to(inputs["lumped_drag_area"], (nn, 1)), f_a * total[:, None]],
            axis=1,
        )
        partials["drag_breakdown", "reference_area"] = (-k0 * breakdown / s_ref**2).ravel()

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
                partials["drag_breakdown", name] = np.concatenate(
                    [k0 * d_area / s_ref, k0 * f_a * d_area / s_ref]
                )
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
