"""Systems group as named items: Raymer's general-aviation weight equations.

Raymer, D. P., "Aircraft Design: A Conceptual Approach", 6th ed., AIAA, 2018, Sec. 15.3.3
"General Aviation Weights", eqs. 15.54 (flight controls), 15.56 (electrical), 15.57 (avionics),
15.58 (air conditioning and anti-icing) and 15.59 (furnishings). In lb and ft:

- W_fc   = 0.053 L^1.536 B_w^0.371 (N_z W_dg 1e-4)^0.80
- W_av   = 2.117 W_uav^0.933
- W_el   = 12.57 (W_fuel_system + W_av)^0.51,   W_fuel_system = 0 (battery-electric)
- W_ecs  = 0.265 W_dg^0.52 N_p^0.68 W_av^0.17 M^0.08
- W_furn = 0.0582 W_dg - 65

L fuselage length, B_w wing span, N_z ultimate load factor (1.5 x limit), W_dg design gross
weight, W_uav uninstalled avionics weight, N_p persons on board, M cruise Mach number.
Hydraulics (eq. 15.55) are left out: the LPC's controls are electric (rotor speeds).
docs theory/weights 'Systems' gives the SI form and the inputs of the reference vehicle.
"""

import openmdao.api as om

from lpc_mdo.core.checks import RangeCheck, check_range

_FT = 0.3048
_LB = 0.45359237

_positive = RangeCheck(lower=0.0, lower_open=True)

#: Names of the outputs ``{name}_mass``, in this order.
SYSTEM_ITEMS = ("flight_controls", "avionics", "electrical", "environmental_control", "furnishings")


class SystemsMassComp(om.ExplicitComponent):
    """
    Flight controls, avionics, electrical, environmental control and furnishings masses (Raymer).

    Raymer Sec. 15.3.3, eqs. 15.54-15.59 (module docstring), evaluated in lb/ft and returned in
    kg. Flight controls move with the fuselage length and the span; everything scales with the
    design gross mass. Analytic partials (power laws; furnishings linear).

    Inputs
    ------
    fuselage_length : float, (1,), m
    wing_span : float, (1,), m
    design_gross_mass : float, (1,), kg
        All > 0.

    Outputs
    -------
    flight_controls_mass, avionics_mass, electrical_mass, environmental_control_mass,
    furnishings_mass : float, (1,), kg

    Options
    -------
    ultimate_load_factor : float
        N_z (> 0); 1.5 x the +3g limit = 4.5 by default.
    num_persons : int
        N_p, persons on board (>= 1).
    uninstalled_avionics_mass : float
        W_uav in kg (> 0).
    cruise_mach : float
        M (> 0).
    """

    def initialize(self):
        opts = self.options
        opts.declare(
            "ultimate_load_factor",
            default=4.5,
            types=(int, float),
            check_valid=_positive,
            desc="N_z = 1.5 x limit load factor",
        )
        opts.declare("num_persons", default=6, types=int, lower=1, desc="N_p")
        opts.declare(
            "uninstalled_avionics_mass",
            default=18.14,
            types=(int, float),
            check_valid=_positive,
            desc="W_uav, kg (assumption: 40 lb)",
        )
        opts.declare(
            "cruise_mach", default=0.168, types=(int, float), check_valid=_positive, desc="M"
        )

    def setup(self):
        self.add_input("fuselage_length", 9.144, units="m", desc="fuselage length")
        self.add_input("wing_span", 15.4, units="m", desc="wing span")
        self.add_input("design_gross_mass", 3700.0, units="kg", desc="design gross mass")
        for name in SYSTEM_ITEMS:
            self.add_output(f"{name}_mass", 50.0, units="kg", desc=f"{name} mass (Raymer)")
            if name not in ("avionics", "electrical"):  # these depend on W_uav only
                self.declare_partials(f"{name}_mass", "design_gross_mass")
        self.declare_partials("flight_controls_mass", ["fuselage_length", "wing_span"])

        o = self.options
        w_av = 2.117 * (o["uninstalled_avionics_mass"] / _LB) ** 0.933
        self._avionics = w_av
        self._electrical = 12.57 * w_av**0.51
        self._ecs = 0.265 * o["num_persons"] ** 0.68 * w_av**0.17 * o["cruise_mach"] ** 0.08

    def _lb(self, inputs):
        for name, units in (
            ("fuselage_length", "m"),
            ("wing_span", "m"),
            ("design_gross_mass", "kg"),
        ):
            check_range(name, inputs[name], lower=0.0, lower_open=True, units=units,
                        error=om.AnalysisError, where=self.msginfo)  # fmt: skip
        length = inputs["fuselage_length"] / _FT
        span = inputs["wing_span"] / _FT
        weight = inputs["design_gross_mass"] / _LB
        nz = self.options["ultimate_load_factor"]
        return {
            "flight_controls": 0.053 * length**1.536 * span**0.371 * (nz * weight * 1e-4) ** 0.80,
            "avionics": self._avionics + 0.0 * weight,
            "electrical": self._electrical + 0.0 * weight,
            "environmental_control": self._ecs * weight**0.52,
            "furnishings": 0.0582 * weight - 65.0,
        }

    def compute(self, inputs, outputs):
        for name, value in self._lb(inputs).items():
            outputs[f"{name}_mass"] = _LB * value

    def compute_partials(self, inputs, partials):
        w = self._lb(inputs)
        fc = _LB * w["flight_controls"]
        partials["flight_controls_mass", "fuselage_length"] = 1.536 * fc / inputs["fuselage_length"]
        partials["flight_controls_mass", "wing_span"] = 0.371 * fc / inputs["wing_span"]
        mass = inputs["design_gross_mass"]
        partials["flight_controls_mass", "design_gross_mass"] = 0.80 * fc / mass
        ecs = _LB * w["environmental_control"]
        partials["environmental_control_mass", "design_gross_mass"] = 0.52 * ecs / mass
        partials["furnishings_mass", "design_gross_mass"] = 0.0582 + 0.0 * mass


__all__ = ["SYSTEM_ITEMS", "SystemsMassComp"]
