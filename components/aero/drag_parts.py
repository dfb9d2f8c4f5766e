"""Part descriptions of the parasite-drag build-up (docs theory/aerodynamics 'Drag build-up').

Each part says how its wetted area S_wet, form factor FF and characteristic length L follow from
its geometry inputs (friction parts: lifting surfaces, bodies, parts of given form factor), or
gives its drag area D/q directly (:class:`BluffDrag`: wheels, struts, rotor hubs). The component
:class:`~lpc_mdo.components.aero.drag_buildup.DragBuildupComp` adds the skin friction.
"""

import math
from dataclasses import dataclass

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_integer, check_number, check_range

#: Default interference factor Q (CADDEE default, reference/models_aero_rotor_acoustics.md §5);
#: the LPC parts use Raymer's values (Aircraft Design, 6th ed., sec. 12.5.5).
DEFAULT_INTERFERENCE = 1.1


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
    friction = True

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
    count : int
        Number of identical bodies (default 1); the wetted area is that of all of them.
    """

    name: str
    laminar_fraction: float = 0.1
    interference_factor: float = DEFAULT_INTERFERENCE
    count: int = 1
    friction = True

    def __post_init__(self):
        owner = f"BodyDrag '{self.name}'"
        _check_fraction(owner, "laminar_fraction", self.laminar_fraction)
        _check_fraction(owner, "interference_factor", self.interference_factor, 0.0, 10.0, True)
        check_integer("count", self.count, lower=1, where=owner)

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
        n = self.count
        swet = n * np.pi * d * length * g1 * g2
        dg = (2.0 / 3.0) * (1.0 - 2.0 / fe) ** (-1.0 / 3.0) * 2.0 / fe**2 * g2 - g1 * 2.0 / fe**3
        # d swet = pi g1 g2 (L dd + d dL) + pi d L dg dfe; fe = L/d
        dswet_dl = n * (np.pi * g1 * g2 * d + np.pi * d * length * dg / d)
        dswet_dd = n * (np.pi * g1 * g2 * length - np.pi * d * length * dg * length / d**2)
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
    friction = True

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


@dataclass(frozen=True)
class BluffDrag:
    """Identical bluff parts of given drag coefficient on their frontal area (no inputs).

    D/q = count C_D A_front (Raymer, Aircraft Design, 6th ed., sec. 12.5.6, Table 12.6 for
    landing-gear parts; Hoerner, Fluid-Dynamic Drag, 1965, ch. 3 for short cylinders); no
    skin-friction or Reynolds-number dependence, no interference factor (the coefficients are
    installed values).

    Attributes
    ----------
    name : str
    drag_coefficient : float
        C_D on the frontal area, in (0, 2].
    frontal_area : float
        Frontal area of one part, m**2, > 0.
    count : int
        Number of parts (>= 1).
    """

    name: str
    drag_coefficient: float
    frontal_area: float
    count: int = 1
    friction = False
    laminar_fraction = 0.0
    interference_factor = 1.0
    inputs = ()
    depends = {}

    def __post_init__(self):
        owner = f"BluffDrag '{self.name}'"
        _check_fraction(owner, "drag_coefficient", self.drag_coefficient, 0.0, 2.0, True)
        check_number("frontal_area", self.frontal_area, lower=0.0, lower_open=True, where=owner)
        check_integer("count", self.count, lower=1, where=owner)

    @property
    def drag_area(self):
        """D/q of all parts, m**2."""
        return self.count * self.drag_coefficient * self.frontal_area

    def evaluate(self, values):
        """Drag area in place of the wetted area (FF = 1, unit length): no derivatives."""
        one = np.ones(1)
        return self.drag_area * one, one, one, {}


@dataclass(frozen=True)
class SizedBluffDrag:
    """Identical bluff parts whose frontal area is an input ``{name}_frontal_area`` (one part).

    D/q = count C_D A_front, as :class:`BluffDrag`, for parts sized elsewhere in the model (the
    landing-gear tyres, from the design gross mass: ``components.aero.tyre_size``).

    Attributes
    ----------
    name : str
    drag_coefficient : float
        C_D on the frontal area, in (0, 2].
    count : int
        Number of parts (>= 1).
    """

    name: str
    drag_coefficient: float
    count: int = 1
    friction = False
    laminar_fraction = 0.0
    interference_factor = 1.0

    def __post_init__(self):
        owner = f"SizedBluffDrag '{self.name}'"
        _check_fraction(owner, "drag_coefficient", self.drag_coefficient, 0.0, 2.0, True)
        check_integer("count", self.count, lower=1, where=owner)

    @property
    def inputs(self):
        """(suffix, units, default, desc) of the component's inputs."""
        return (("frontal_area", "m**2", 0.1, "frontal area of one part"),)

    #: The frontal area changes the drag area (in the wetted-area slot of a bluff part).
    depends = {"frontal_area": ("wetted",)}

    def evaluate(self, values):
        """Drag area in place of the wetted area (FF = 1, unit length) and its derivative."""
        area = values["frontal_area"]
        _check_positive(self.name, (("frontal_area", area),))
        one = np.ones_like(area)
        k = self.count * self.drag_coefficient
        return k * area, one, one, {"frontal_area": (k * one, 0.0 * one, 0.0 * one)}


#: The part description classes the build-up accepts.
PART_TYPES = (LiftingSurfaceDrag, BodyDrag, FixedFormFactorDrag, BluffDrag, SizedBluffDrag)
