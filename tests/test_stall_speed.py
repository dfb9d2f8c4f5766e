"""Stall-speed check of the post-processing: the 1-g stall speed from the wing sections."""

from types import SimpleNamespace

import numpy as np
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.core.constants import GRAVITY, SEA_LEVEL_DENSITY
from lpc_mdo.post.stall import stall_speed
from lpc_mdo.vehicle import reference_vehicle


class _Values:
    """Recorded values by name, as a case answers ``get_val`` (units as recorded: SI)."""

    def __init__(self, values):
        self.values = values

    def get_val(self, name, units=None):
        return np.atleast_1d(self.values[name])


def _source(condition, cl, reynolds, mach, lift_coefficient, density, speed, ratio, ks):
    return {
        f"{condition}.wing_stall_ratio": ratio,
        f"{condition}.wing_stall_ratio_ks": ks,
        f"{condition}.wing_sectional_cl": cl,
        f"{condition}.vlm.wing_strip_flow.strip_reynolds": reynolds,
        f"{condition}.vlm.wing_strip_flow.strip_mach": mach,
        f"{condition}.CL": lift_coefficient,
        f"{condition}.density": density,
        f"{condition}.speed": speed,
    }


def _vehicle(airfoil):
    base = reference_vehicle()
    return SimpleNamespace(
        wing=SimpleNamespace(airfoil=airfoil),
        constraints=base.constraints,
        conditions=base.conditions,
        mission=base.mission,
    )


def test_closed_form_with_a_constant_section_maximum():
    # A single-(Re, M) table has one c_l,max for every Reynolds number, so the iteration stops
    # at the closed form: C_L,max = kappa C_L / r, V_S = sqrt(2 W / (rho S C_L,max)) (1e-12).
    alpha = np.arange(-10.0, 20.5, 0.5)
    cl_table = np.clip(0.11 * (alpha + 2.0), -0.9, 1.6)  # cl_max 1.6 at 12.6 deg and beyond
    cd_table = 0.01 + 1e-4 * alpha**2
    airfoil = np.column_stack([alpha, cl_table, cd_table])
    cl_max = get_polar(airfoil).max_lift_coefficients(np.array([1e6]), np.array([0.0]))[1][0]
    assert_near_equal(cl_max, 1.6, 1e-12)
    cl = np.array([0.6, 0.8, 0.9, 0.9, 0.8, 0.6])
    ratio = np.concatenate([cl / 1.6, cl / -0.9])
    values = _source("cruise", cl, np.full(6, 3e6), np.full(6, 0.17), 0.85, 1.112, 57.19, ratio, 0)
    values |= {"wing_area": 19.6, "gross_mass": 3000.0}
    vehicle = _vehicle(airfoil)
    found = stall_speed(_Values(values), vehicle, "cruise")
    kappa = vehicle.constraints.wing_stall_lift_fraction
    cl_wing_max = kappa * 0.85 / (0.9 / 1.6)
    expected = np.sqrt(2.0 * 3000.0 * GRAVITY / (1.112 * 19.6 * cl_wing_max))
    assert_near_equal(found["CL_max"], cl_wing_max, 1e-12)
    assert_near_equal(found["stall_speed"], expected, 1e-12)
    assert_near_equal(
        found["stall_speed_eas"], expected * np.sqrt(1.112 / SEA_LEVEL_DENSITY), 1e-12
    )


def test_reynolds_number_at_the_stall_speed():
    # With the wing table c_l,max falls with Re, so at V_S < V the section maximum is lower and
    # the stall speed higher than at the condition's own Re. Fixed point checked by hand: at
    # the returned V_S, the strips' Re and M scaled by V_S/V give c_l,max with
    # sqrt(2 W / (rho S kappa C_L / max(c_l / c_l,max))) = V_S (1e-5, the iteration's 1e-6).
    polar = get_polar("ls413")
    cl = np.array([0.70, 0.85, 0.90, 0.90, 0.85, 0.70])
    re = np.array([1.3e6, 4.0e6, 5.8e6, 5.8e6, 4.0e6, 1.3e6])
    mach = np.full(6, 0.17)
    low, high, *_ = polar.max_lift_coefficients(re, mach)
    ratio = np.concatenate([cl / high, cl / low])
    values = _source("cruise", cl, re, mach, 0.88, 1.112, 57.19, ratio, 0)
    values |= {"wing_area": 19.6, "gross_mass": 3265.0}
    vehicle = _vehicle("ls413")
    found = stall_speed(_Values(values), vehicle, "cruise")
    v_s = found["stall_speed"]
    _, high_s, *_ = polar.max_lift_coefficients(re * v_s / 57.19, mach * v_s / 57.19)
    kappa = vehicle.constraints.wing_stall_lift_fraction
    hand = np.sqrt(2.0 * 3265.0 * GRAVITY / (1.112 * 19.6 * kappa * 0.88 / np.max(cl / high_s)))
    assert_near_equal(v_s, hand, 1e-5)
    at_condition = np.sqrt(2.0 * 3265.0 * GRAVITY / (1.112 * 19.6 * kappa * 0.88 / ratio.max()))
    assert v_s > at_condition


def test_push_over_has_no_positive_stall_speed():
    cl = np.full(4, -0.3)
    re, mach = np.full(4, 5e6), np.full(4, 0.28)
    low, high, *_ = get_polar("ls413").max_lift_coefficients(re, mach)
    ratio = np.concatenate([cl / high, cl / low])
    values = _source("minus_1g", cl, re, mach, -0.35, 1.058, 93.65, ratio, 0.2)
    values |= {"wing_area": 19.6, "gross_mass": 3265.0}
    found = stall_speed(_Values(values), _vehicle("ls413"), "minus_1g")
    assert np.isnan(found["stall_speed"])
    assert_near_equal(found["ratio"], 0.3 / -low[0], 1e-12)
