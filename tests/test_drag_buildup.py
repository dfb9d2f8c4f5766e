import math

import numpy as np
import openmdao.api as om
import pytest
from drag_cases import CRUISE, fully_turbulent, make_problem
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.aero.drag_buildup import (
    LPC_LEAKAGE_PROTUBERANCE,
    BluffDrag,
    BodyDrag,
    FixedFormFactorDrag,
    LiftingSurfaceDrag,
    raymer_ga_tyre,
)
from lpc_mdo.groups.vehicle_drag import lpc_drag_components
from lpc_mdo.vehicle import reference_vehicle


def test_form_factors_against_reference_table():
    # docs theory/aerodynamics 'Drag build-up' table (Raymer form, no sweep):
    # wing LS(1)-0413 1.2236, LS(1)-0417 1.3385, tails (t/c 0.15, (x/c)_m 0.3) 1.3506;
    # fuselage f = 9.144/1.688 = 5.417, FF = 1.3910. Tolerance: the 4 printed decimals.
    comps = (
        LiftingSurfaceDrag("ls413", 0.13, 0.4),
        LiftingSurfaceDrag("ls417", 0.17, 0.4),
        LiftingSurfaceDrag("tail", 0.15, 0.3),
        BodyDrag("fuselage"),
    )
    values = {"fuselage_length": 9.144, "fuselage_max_height": 1.688, "fuselage_max_width": 1.557}
    prob = make_problem(comps, values)
    assert_near_equal(prob.get_val("form_factors"), [1.2236, 1.3385, 1.3506, 1.3910], 5e-5)
    assert_near_equal(9.144 / 1.688, 5.417, 1e-4)


def test_lpc_buildup_against_hand_calculation():
    comps, values = lpc_drag_components()
    # MACs: the cranked NASA wing 1.33328 m (trapezoid-rule integration of the vehicle file's
    # sections, tests/test_cranked_wing_vehicle.py::_hand_planform); the tails of
    # docs theory/aerodynamics 'Drag build-up' table (h-tail 0.9469, v-tail 1.6343 m).
    assert_near_equal(
        [
            values["wing_mean_aerodynamic_chord"],
            values["horizontal_tail_mean_aerodynamic_chord"],
            values["vertical_tail_mean_aerodynamic_chord"],
        ],
        [1.33328, 0.9469, 1.6343],
        1e-4,
    )
    prob = make_problem()
    # Independent evaluation of docs theory/aerodynamics 'Drag build-up' with the math module:
    # Raymer wetted areas 2 S (1 + 0.2 t/c), Torenbeek fuselage pi D L (1 - 2/f)^(2/3) (1 + 1/f^2)
    # with D = sqrt(H W) (also for the 4 booms of 2 x 2.4384 m, d = 0.3048 m, Q 1.5), the
    # docs theory/aerodynamics 'Drag build-up' skin friction with the LPC laminar fractions
    # (wing 0.7, others 0.1), Q = 1.1; the bluff parts count C_D A.
    v, rho, mu, a = (CRUISE[k] for k in ("speed", "density", "dynamic_viscosity", "speed_of_sound"))
    mach = v / a

    def cf(length, lam):
        re = rho * v * length / mu
        return lam * 1.328 / math.sqrt(re) + (1 - lam) * 0.455 / (
            math.log10(re) ** 2.58 * (1 + 0.144 * mach**2) ** 0.65
        )

    d_eq = math.sqrt(1.688 * 1.557)
    f_eq = 9.144 / d_eq
    swet_fus = math.pi * d_eq * 9.144 * (1 - 2 / f_eq) ** (2 / 3) * (1 + 1 / f_eq**2)
    f_b = 4.8768 / 0.3048
    swet_boom = 4 * math.pi * 0.3048 * 4.8768 * (1 - 2 / f_b) ** (2 / 3) * (1 + 1 / f_b**2)
    # 16 blades, mean chord 0.3 m (0.45 -> 0.15 m) over 0.8 R = 1.2192 m, t/c 0.12; spinner
    # cone r 0.274, l 0.548.
    swet_blades = 16 * 2 * 1.024 * 0.3 * 1.2192
    swet_spinner = math.pi * 0.274 * math.hypot(0.274, 0.548)
    swet = [
        2 * 19.6 * 1.026,
        2 * 3.7 * 1.03,
        2 * 2.54 * 1.03,
        swet_fus,
        swet_boom,
        swet_blades,
        swet_spinner,
    ]
    friction = [0, 1, 2, 3, 4, 5, 8]
    assert_near_equal(prob.get_val("wetted_areas")[friction], swet, 1e-10)
    ff = prob.get_val("form_factors")[friction]
    assert_near_equal(ff[4], 1 + 60 / f_b**3 + f_b / 400, 1e-12)
    lengths = [1.33328, 0.946904, 1.63433, 9.144, 4.8768, 1.2192, 0.548]
    lams = [0.7, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1]
    qs = [1.1, 1.1, 1.1, 1.1, 1.5, 1.0, 1.0]
    areas = [
        cf(L, p) * f * qi * s for L, p, f, qi, s in zip(lengths, lams, ff, qs, swet, strict=True)
    ]
    assert_near_equal(prob.get_val("drag_areas")[0][friction], areas, 1e-4)  # MAC rounding
    # Bluff parts: 8 hubs 0.63 x 0.3048 x 0.1524; 8 pylons 0.05 x 0.1524 x mean |dz| of the CAD
    # hubs above the boom attach points; 2 + 1 wheels 0.25 D w (Raymer Table 11.1 tyres);
    # 3 struts 0.30 x 0.5 x 0.0762. Tyres at the design gross mass.
    dz = np.mean(np.abs([0.07773, 0.61722, 0.07346, 0.61539] * 2))
    w_dg = reference_vehicle().masses.design_gross_mass
    (dm, wm), (dn, wn) = raymer_ga_tyre(0.45 * w_dg), raymer_ga_tyre(0.1 * w_dg)
    bluff = [
        8 * 0.63 * 0.3048 * 0.1524,
        8 * 0.05 * 0.1524 * dz,
        2 * 0.25 * dm * wm,
        0.25 * dn * wn,
        3 * 0.30 * 0.5 * 0.0762,
    ]
    assert_near_equal(prob.get_val("drag_areas")[0][[6, 7, 9, 10, 11]], bluff, 1e-4)
    q = 0.5 * rho * v**2
    total = (sum(areas) + sum(bluff)) * (1 + LPC_LEAKAGE_PROTUBERANCE)
    assert_near_equal(prob.get_val("CD0")[0], total / 19.6, 1e-4)
    breakdown = prob.get_val("drag_breakdown")[0]
    assert_near_equal(breakdown.sum(), prob.get_val("CD0")[0], 1e-12)
    assert_near_equal(breakdown[-1], LPC_LEAKAGE_PROTUBERANCE * total / 1.05 / 19.6, 1e-4)
    assert_near_equal(prob.get_val("parasite_drag")[0], q * total, 1e-4)
    # Force along the relative wind (not the horizontal of quirk Q5).
    force = prob.get_val("parasite_drag_force")[0]
    alpha = CRUISE["angle_of_attack"]
    assert_near_equal(force, -q * total * np.array([math.cos(alpha), 0.0, math.sin(alpha)]), 1e-4)
    # Magnitude check: turbulent flat plate (Prandtl-Schlichting) C_f at Re = 1e7 is 0.00300.
    assert_near_equal(0.455 / 7.0**2.58, 0.00300, 2e-3)


# The fuselage is taller than wide, so d(FF)/d(width) is zero at this point.
@pytest.mark.filterwarnings("ignore::openmdao.utils.om_warnings.DerivativesWarning")
def test_hover_drag_factor_and_partials():
    hover = dict(CRUISE, speed=0.0, angle_of_attack=0.0)
    climb = dict(CRUISE, speed=60.8756, angle_of_attack=0.05, sideslip_angle=0.03)
    hover["sideslip_angle"] = 0.0
    cruise = dict(CRUISE, sideslip_angle=-0.02)
    prob = make_problem(conditions=(hover, cruise, climb))
    assert prob.get_val("parasite_drag")[0] == 0.0
    assert np.all(np.isfinite(prob.get_val("CD0")))
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)
    scaled = make_problem(conditions=(hover, cruise, climb), drag_factor=1.5)
    assert_near_equal(scaled.get_val("parasite_drag"), 1.5 * prob.get_val("parasite_drag"), 1e-14)


def test_bad_specs_and_inputs():
    with pytest.raises(
        ValueError, match="'thickness_to_chord' = 0.7 is out of range: must be in \\(0, 0.5\\]"
    ):
        LiftingSurfaceDrag("wing", 0.7, 0.4)
    with pytest.raises(ValueError, match="'count' = 0 is out of range: must be >= 1"):
        FixedFormFactorDrag("booms", 1.1, count=0)
    prob = make_problem(
        (BodyDrag("pod"),), {"pod_length": 5.0, "pod_max_height": 1.0, "pod_max_width": 0.8}
    )
    assert prob.get_val("form_factors")[0] > 1.0
    prob.set_val("pod_length", 1.5)
    with pytest.raises(
        om.AnalysisError,
        match=r"pod_length/sqrt\(pod_max_height\*pod_max_width\)"
        r" = 1.67705; .* fineness ratio > 2",
    ):
        prob.run_model()
    prob.set_val("pod_length", -1.0)
    with pytest.raises(
        om.AnalysisError,
        match=r"'pod_length\[0\]' = -1.0 is out of range: "
        r"must be > 0",
    ):
        prob.run_model()


def test_bluff_part_adds_its_drag_area():
    # A BluffDrag part adds count C_D A_front to D/q, independent of Re and M: two wheels of
    # 0.675 m x 0.236 m frontal area at C_D 0.25 (Raymer, Aircraft Design 6th ed., Table 12.6,
    # regular wheel and tire) give 2 * 0.25 * 0.1593 = 0.079650 m^2 (exact arithmetic, 1e-12).
    wheel = BluffDrag("main_wheels", 0.25, 0.675 * 0.236, count=2)
    wing = LiftingSurfaceDrag("wing", 0.13, 0.4)
    values = {"wing_area": 19.6, "wing_mean_aerodynamic_chord": 1.46, "reference_area": 19.6}
    prob = make_problem((wing, wheel), values, conditions=(CRUISE, {**CRUISE, "speed": 30.0}))
    areas = prob.get_val("drag_areas")
    assert_near_equal(areas[:, 1], [0.079650, 0.079650], 1e-12)
    only_wing = make_problem((wing,), values, conditions=(CRUISE, {**CRUISE, "speed": 30.0}))
    assert_near_equal(prob.get_val("CD0") - only_wing.get_val("CD0"), [0.079650 / 19.6] * 2, 1e-10)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-8)


def test_bluff_part_rejects_bad_coefficient():
    with pytest.raises(ValueError, match="drag_coefficient"):
        BluffDrag("gear", -0.1, 0.1)


def test_raymer_tyre_sizing():
    # Raymer, Aircraft Design 6th ed., Table 11.1 (general aviation): D = 1.51 W^0.349 in,
    # width = 0.7150 W^0.312 in. W = 1000 lb: D = 1.51 * 11.14 = 16.83 in, w = 0.715 * 8.65
    # = 6.18 in (hand arithmetic, 0.2 %).
    d, w = raymer_ga_tyre(1000 * 0.45359237)
    assert_near_equal([d / 0.0254, w / 0.0254], [16.83, 6.185], 2e-3)


def test_stopped_rotor_hub_against_hoerner():
    # Hoerner, Fluid-Dynamic Drag (1965) ch. 3: finite cylinder in cross flow, l/d = 1, C_D 0.63
    # on l d. Hub 0.3048 x 0.1524 m: D/q = 0.63 * 0.04645 = 0.029265 m^2 per hub.
    comps, values = lpc_drag_components()
    hubs = next(c for c in comps if c.name == "lift_rotor_hubs")
    assert_near_equal(hubs.drag_area / hubs.count, 0.029265, 1e-4)


def test_lpc_zero_lift_drag_against_nasa():
    # Published NASA LPC data (issue 16): a physics-based drag build-up of the complete vehicle
    # gives CD0 ~ 0.040; the CFD-based model of Simmons, Buning and Murphy ("Full-Envelope
    # Aero-Propulsive Model Identification for Lift+Cruise Aircraft Using Computational
    # Experiments", AIAA 2021-3170; GUAM repository nasa/Generic-Urban-Air-Mobility-GUAM,
    # vehicles/Lift+Cruise/AeroProp/Polynomial/.../LC_G_ab_CFM__Cp3FI_cv.m, glider model,
    # 90 kt, no deflections) gives CD 0.0484 at alpha 0 (CL 0.229), a parabolic fit
    # CD0 0.0417, max L/D 12.6 -- coarse grid, fully turbulent, booms and gear removed.
    # Complete vehicle against the complete build-up: within 15 %.
    prob = make_problem()
    assert_near_equal(prob.get_val("CD0")[0], 0.040, 0.15)
    # Like for like with the CFD (no booms, no gear): measured 0.029, 31 % under the CFD fit
    # 0.0417; the difference is written down in docs theory/aerodynamics 'Drag build-up'
    # (fully turbulent CFD vs 70 % laminar wing, lift-dependent profile drag missing here).
    comps, values = lpc_drag_components(gear=False, booms=False)
    clean = make_problem(comps, values)
    cd0 = clean.get_val("CD0")[0]
    assert 0.5 * 0.0417 < cd0 < 0.0417
    # Fully turbulent as the CFD (every laminar fraction 0), like for like: within 15 % of the
    # CFD fit (measured 0.0357, -14.5 %; the parabolic fit of the trimmed polar, -13 %, is the
    # slow test in test_lift_to_drag.py).
    cd0_turbulent = make_problem(
        fully_turbulent(comps), values, allowance_fraction=LPC_LEAKAGE_PROTUBERANCE
    ).get_val("CD0")[0]
    assert cd0 < cd0_turbulent
    assert_near_equal(cd0_turbulent, 0.0417, 0.15)
