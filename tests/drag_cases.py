"""Shared drag test cases: the cruise condition and a drag build-up problem."""

import dataclasses
import math

import openmdao.api as om

from lpc_mdo.components.aero.drag_buildup import LPC_LEAKAGE_PROTUBERANCE, DragBuildupComp
from lpc_mdo.groups.vehicle_drag import lpc_drag_components

# Cruise (reference vehicle file): M 0.17 at 999.74 m, CADDEE atmosphere (docs theory/atmosphere):
# rho = 1.11177 kg/m^3, mu = 1.70443e-5 Pa s, a = 336.410 m/s, V = 57.1897 m/s.
CRUISE = {
    "speed": 57.1897,
    "density": 1.11177,
    "dynamic_viscosity": 1.70443e-5,
    "speed_of_sound": 336.410,
    "angle_of_attack": math.radians(2.0),
}


def fully_turbulent(components):
    """Return the parts with every laminar fraction 0 (as a fully turbulent CFD)."""
    return tuple(
        dataclasses.replace(c, laminar_fraction=0.0)
        if "laminar_fraction" in {f.name for f in dataclasses.fields(c)}
        else c
        for c in components
    )


def make_problem(components=None, values=None, conditions=(CRUISE,), **options):
    if components is None:
        components, values = lpc_drag_components()
        options.setdefault("allowance_fraction", LPC_LEAKAGE_PROTUBERANCE)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "drag",
        DragBuildupComp(components=components, num_nodes=len(conditions), **options),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    for name, value in (values or {}).items():
        prob.set_val(name, value)
    for name in conditions[0]:
        prob.set_val(name, [c[name] for c in conditions])
    prob.run_model()
    return prob
