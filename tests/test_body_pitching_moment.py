"""Fuselage and boom Munk-Multhopp moment: apparent mass, wing flow field, couple, wiring."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.dynamics.body_pitching_moment import (
    BodyMomentSlopeComp,
    BodyPitchingMomentComp,
    body_moment_slope_options,
    boom_strips,
    lifting_line_upwash_gradient,
    multhopp_flow_gradient,
    munk_apparent_mass_factor,
    wing_lift_slope,
)
from lpc_mdo.vehicle import reference_vehicle

REFERENCE = reference_vehicle()


@pytest.mark.parametrize(
    "fineness, k1, k2",
    # Lamb, Hydrodynamics (6th ed., 1932) sec. 373 table of prolate spheroids (a/b, alpha = k1,
    # beta = k2), printed to 3 decimals: tolerance 0.002 on k2 - k1.
    [(1.99, 0.209, 0.702), (3.99, 0.082, 0.860), (6.01, 0.045, 0.918), (9.97, 0.021, 0.960)],
)
def test_munk_factor_matches_lambs_table(fineness, k1, k2):
    assert abs(munk_apparent_mass_factor(fineness) - (k2 - k1)) < 2e-3


def test_munk_factor_limits():
    # Sphere: k1 = k2 = 1/2 (no couple); infinitely slender body: k2 - k1 -> 1 (Munk, TR 184).
    assert munk_apparent_mass_factor(1.0 + 1e-9) < 1e-6
    assert munk_apparent_mass_factor(1e4) > 0.9999


def test_lifting_line_far_wake_downwash():
    # Elliptic lifting line: far behind the wing the downwash is uniform across the span,
    # eps = 2 C_L/(pi A) (Anderson, Fundamentals of Aerodynamics, sec. 5.3.1, twice the
    # downwash at the line). Tolerance 1 % (vortex discretization and core smoothing).
    area, aspect = 19.6, 12.12
    span = np.sqrt(area * aspect)
    cla = wing_lift_slope(aspect, 0.0)
    x = np.full(3, -5000.0)
    y = np.array([0.0, 2.5, 5.7])
    eps = lifting_line_upwash_gradient(x, y, span, area, cla, 0.0)
    assert_near_equal(eps, np.full(3, -2.0 * cla / (np.pi * aspect)), 0.01)


def test_upwash_ahead_of_the_wing_decays_and_is_zero_under_the_chord():
    # Ahead of a lifting wing the flow turns up (Multhopp, NACA TM 1036): 1 < dbeta/dalpha,
    # growing towards the leading edge; under the root chord the strip carries no moment.
    x = np.array([-0.2, -1.0, -1.8, -2.5, -3.5, -6.0])
    g = multhopp_flow_gradient(x, 0.0, 15.4, 19.6, 5.3, -1.96, 2.12)
    assert 1.0 < g[0] < g[1] < g[2]
    assert g[3] == 0.0 and g[4] == 0.0
    assert 0.0 < g[5] < 1.0


def _slope_problem(options, length=9.0, area=19.6, span=15.4, root_chord=1.66):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("slope", BodyMomentSlopeComp(**options), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    for name, value in (
        ("fuselage_length", length),
        ("wing_area", area),
        ("wing_span", span),
        ("wing_root_chord", root_chord),
    ):
        prob.set_val(name, value)
    prob.run_model()
    return prob


def _one_boom(x_front, x_rear, y, diameter, num_strips=200):
    edges = np.linspace(x_front, x_rear, num_strips + 1)
    k = float(munk_apparent_mass_factor((x_front - x_rear) / diameter))
    return {
        "boom_x": 0.5 * (edges[:-1] + edges[1:]),
        "boom_y": np.full(num_strips, y),
        "boom_strip_factor": np.full(num_strips, diameter**2 * (x_front - x_rear) / num_strips),
        "boom_flow_mask": np.ones(num_strips),
        "boom_apparent_mass_factor": k,
    }


def test_bodies_far_ahead_of_the_wing_carry_munks_couple():
    # With the wing 10 km behind, the flow at the bodies is the free stream (g = 1) and each
    # body carries Munk's couple M = q Vol (k2 - k1) sin(2 alpha) (Munk, NACA TR 184, 1924),
    # i.e. a slope of 2 Vol (k2 - k1) per radian: the spheroid fuselage Vol = pi/6 L w^2; a
    # boom line taken as a body of the cylinder's section, (pi/2) d^2 L. Tolerance 1e-3
    # (midpoint strips); the zero-lift sums (g - 1) vanish to 1e-6 of the slope.
    length, width = 9.0, 1.5
    options = {
        "fuselage_max_width": width,
        "wing_sweep": 0.0,
        "wing_root_leading_edge_x": -1.0e4,
        "num_strips": 400,
        **_one_boom(-1.0, -5.0, 2.5, 0.3),
    }
    prob = _slope_problem(options, length=length)
    k_f = munk_apparent_mass_factor(length / width)
    k_b = munk_apparent_mass_factor(4.0 / 0.3)
    expected = [2.0 * np.pi / 6.0 * length * width**2 * k_f, 0.5 * np.pi * 0.3**2 * 4.0 * k_b]
    assert_near_equal(prob.get_val("body_moment_slope", units="m**3"), expected, 1e-3)
    assert np.all(np.abs(prob.get_val("body_moment_zero_lift")) < 1e-6 * np.array(expected))


def test_slope_partials_and_a_longer_fuselage_destabilizes_more():
    options = body_moment_slope_options(REFERENCE)
    prob = _slope_problem(options)
    data = prob.check_partials(method="cs", out_stream=None, compact_print=True)
    assert_check_partials(data, atol=1e-9, rtol=1e-9)
    # Longer fuselage at the same width: more strips' area ahead of the wing, a larger
    # fineness (k2 - k1 closer to 1): the fuselage slope grows; the booms' does not change.
    longer = _slope_problem(options, length=1.165 * 9.0)
    assert longer.get_val("body_moment_slope")[0] > 1.1 * prob.get_val("body_moment_slope")[0]
    assert_near_equal(
        longer.get_val("body_moment_slope")[1], prob.get_val("body_moment_slope")[1], 1e-14
    )


def test_fuselage_sums_are_continuous_where_a_chord_edge_crosses_a_strip():
    # The root chord's trailing edge swept across several strip edges (strips 0.2286 m long):
    # a strip that counted whole or not at all by its centre made the sums jump by its w^2 dx
    # (~0.3 m**3, a 60 N m step of the cruise pitching moment at an aspect-ratio change of
    # 4e-5, which stalled SLSQP's line search); split at the edge, the change over each small
    # step stays within the step times the largest slope the partials give (2x margin).
    options = {**body_moment_slope_options(REFERENCE), "num_strips": 40}
    chords = np.linspace(1.55, 2.05, 251)
    values, slopes = [], []
    for c in chords:
        prob = _slope_problem(options, length=9.144, root_chord=c)
        values.append(prob.get_val("body_moment_slope")[0])
        totals = prob.compute_totals("body_moment_slope", "wing_root_chord")
        slopes.append(totals["body_moment_slope", "wing_root_chord"][0, 0])
    steps = np.abs(np.diff(values))
    assert np.all(steps <= 2.0 * np.max(np.abs(slopes)) * np.diff(chords))
    # Partials at a point where the trailing edge lies inside a strip (30 % of strip 16).
    edge = -9.144 * 16.3 / 40
    prob = _slope_problem(
        options, length=9.144, root_chord=options["wing_root_leading_edge_x"] - edge
    )
    data = prob.check_partials(method="cs", out_stream=None, compact_print=True)
    assert_check_partials(data, atol=1e-9, rtol=1e-9)


def test_split_strips_converge_to_the_fine_strip_sum():
    # Midpoint rule on the parts outside the chord: 40 strips within 0.5 % of 4000 (the
    # fuselage slope S_f; the error of a whole strip counted by its centre is ~w^2 dx/S_f,
    # a few per cent).
    options = body_moment_slope_options(REFERENCE)
    coarse = _slope_problem({**options, "num_strips": 40}, length=9.144)
    fine = _slope_problem({**options, "num_strips": 4000}, length=9.144)
    for out in ("body_moment_slope", "body_moment_zero_lift"):
        assert_near_equal(coarse.get_val(out)[0], fine.get_val(out)[0], 5e-3)


def test_couple_and_partials():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "body",
        BodyPitchingMomentComp(num_nodes=2, num_bodies=2, wing_zero_lift_angle=-0.1),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("angle_of_attack", [0.02, 0.05])
    prob.set_val("density", [1.2, 1.0])
    prob.set_val("speed", [50.0, 60.0])
    prob.set_val("body_moment_slope", [12.0, 2.0])
    prob.set_val("body_moment_zero_lift", [-8.0, -0.5])
    prob.run_model()
    # Closed form M_y = q sum_b (S_b alpha - Z_b alpha_0w), nothing about x and z.
    q = 0.5 * np.array([1.2 * 50.0**2, 1.0 * 60.0**2])
    expected = q * (14.0 * np.array([0.02, 0.05]) - (-8.5) * -0.1)
    assert_near_equal(prob.get_val("body_moment")[:, 1], expected, 1e-14)
    assert np.all(prob.get_val("body_moment")[:, [0, 2]] == 0.0)
    assert_check_partials(prob.check_partials(method="cs", out_stream=None, compact_print=True))


def test_reference_booms():
    # Two boom lines per side (|y| 2.515 and 5.715 m), each from its front to its rear hub
    # (vehicle file: 4.307 m outer, 4.307 m inner); the strips under the wing's local chord
    # carry nothing.
    booms = boom_strips(REFERENCE)
    assert sorted(set(np.round(np.abs(booms["boom_y"]), 4))) == [2.5146, 5.715]
    assert booms["boom_x"].size == 4 * 20
    covered = booms["boom_flow_mask"] == 0.0
    assert 0 < covered.sum() < 4 * 20
    assert np.all(booms["boom_x"][covered] < REFERENCE.wing.root_leading_edge[0])
    assert_near_equal(booms["boom_strip_factor"].sum(), 4 * 0.3048**2 * 4.30682, 1e-5)


@pytest.mark.integration
def test_cruise_budget_sums_to_the_static_margin_and_fuselage_destabilizes():
    from lpc_mdo.analysis import static_margin_budget
    from lpc_mdo.components.aero.polar import LinearQuadraticPolar
    from lpc_mdo.groups.lpc import LPCGroup

    prob = om.Problem(reports=False)
    prob.model = LPCGroup(
        conditions=["cruise"], rotor_polar=LinearQuadraticPolar(), wing_zero_lift_angle=-0.07
    )
    prob.setup()
    prob.run_model()
    budget = static_margin_budget(prob, "cruise")
    # The parts are a partition of the model's force and moment: they sum to its SM (the
    # same differences, so to round-off).
    assert_near_equal(budget["total"], prob.get_val("cruise.static_margin")[0], 1e-9)
    # The lattice moment plus the fuselage and camber couples and the tail correction is the
    # model's aero moment, and the tail's loads are eta_t = 0.9 times the lattice's ...
    assert_near_equal(
        prob.get_val("cruise.aero_moment"),
        prob.get_val("cruise.vlm_moment")
        + prob.get_val("cruise.body_moment")
        + prob.get_val("cruise.tail_moment_correction")
        + prob.get_val("cruise.wing_camber_moment"),
        1e-12,
    )
    tail = (
        prob.get_val("cruise.panel_forces")[0, 26:]
        + prob.get_val("cruise.vlm.viscous_panel_forces")[0, 26:]
    )
    assert_near_equal(
        prob.get_val("cruise.aero_force")[0] - prob.get_val("cruise.vlm_force")[0],
        -0.1 * tail.sum(axis=0),
        1e-9,
    )
    # ... and the fuselage and booms move the neutral point forward (Munk: a body alone is
    # unstable), the booms by less (about 1/6 of the fuselage's w^2 L, measured -0.013).
    assert budget["fuselage"] < budget["booms"] < 0.0


@pytest.mark.integration
def test_budget_defaults_to_the_vehicles_cruise_condition():
    # A vehicle file whose design cruise condition has another name (mission.cruise_condition):
    # the analysis functions find it without being told.
    from lpc_mdo.analysis import format_static_margin_budget, static_margin_budget
    from lpc_mdo.problems import build_analysis_problem
    from lpc_mdo.vehicle import read_vehicle_file, vehicle_from_dict

    data = read_vehicle_file()
    data["mission"]["cruise_condition"] = "design_cruise"
    for condition in data["conditions"]:
        if condition["name"] == "cruise":
            condition["name"] = "design_cruise"
    vehicle = vehicle_from_dict(data)
    prob = build_analysis_problem(vehicle, conditions=["design_cruise"], design_problem=False)
    prob.run_model()
    budget = static_margin_budget(prob)
    assert budget == static_margin_budget(prob, "design_cruise")
    assert_near_equal(budget["total"], prob.get_val("design_cruise.static_margin")[0], 1e-9)
    assert format_static_margin_budget(prob) == format_static_margin_budget(prob, "design_cruise")
    prob.cleanup()


def test_tail_efficiency_scales_the_tail_loads():
    from lpc_mdo.components.aero.tail_efficiency import TailEfficiencyComp

    rng = np.random.default_rng(3)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "eta",
        TailEfficiencyComp(
            num_nodes=2, num_panels=5, tail_panels=(3, 5), dynamic_pressure_ratio=0.9
        ),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    f, fv, r = rng.normal(size=(2, 5, 3)), rng.normal(size=(2, 5, 3)), rng.normal(size=(5, 3))
    prob.set_val("panel_forces", f)
    prob.set_val("viscous_panel_forces", fv)
    prob.set_val("force_points", r)
    prob.run_model()
    # Closed form: the tail's loads at eta_t q are eta_t times the lattice's (Raymer eq. 16.12).
    ft = (f + fv)[:, 3:]
    assert_near_equal(prob.get_val("tail_force_correction"), -0.1 * ft.sum(axis=1), 1e-12)
    m = np.cross(r[None, 3:], ft).sum(axis=1)
    assert_near_equal(prob.get_val("tail_moment_correction"), -0.1 * m, 1e-12)
    assert_check_partials(prob.check_partials(method="cs", out_stream=None, compact_print=True))


def test_wing_cm0_couple():
    from lpc_mdo.components.aero.wing_zero_lift_moment import (
        WingZeroLiftMomentComp,
        wing_zero_lift_moment_coefficient,
    )

    # An unswept wing of infinite aspect ratio is the section (Raymer eq. 16.13 limit), and
    # sweep lowers it by cos^2 (DATCOM 4.1.4.1): closed forms, 1e-6.
    assert_near_equal(wing_zero_lift_moment_coefficient(-0.1, 1e9, 0.0), -0.1, 1e-6)
    assert_near_equal(
        wing_zero_lift_moment_coefficient(-0.1, 10.0, 0.3),
        -0.1 * 10.0 * np.cos(0.3) ** 2 / (10.0 + 2.0 * np.cos(0.3)),
        1e-12,
    )
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "cm0", WingZeroLiftMomentComp(num_nodes=2, moment_coefficient=-0.09), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("density", [1.2, 1.0])
    prob.set_val("speed", [50.0, 60.0])
    prob.run_model()
    # M = q S c Cm0 (nose down for a cambered section).
    assert_near_equal(
        prob.get_val("wing_camber_moment")[:, 1],
        0.5 * np.array([1.2 * 2500.0, 3600.0]) * 19.6 * 1.46 * -0.09,
        1e-12,
    )
    assert_check_partials(prob.check_partials(method="cs", out_stream=None, compact_print=True))


def test_reference_wing_section_cm0_is_the_ls413s():
    # LS(1)-0413 (GA(W)-2) quarter-chord cm0: the GA(W) family measures about -0.1 (McGhee &
    # Beasley, NASA TN D-7428, GA(W)-1 at Re 4e6); sign and size only, tolerance 15 %.
    from lpc_mdo.components.aero.airfoil import get_polar
    from lpc_mdo.components.aero.wing_zero_lift_moment import airfoil_zero_lift_moment

    cm0 = airfoil_zero_lift_moment(get_polar("ls413"), -0.07, 4e6, 0.17)
    assert_near_equal(cm0, -0.1, 0.15)


def _quarter_mac_x(surface):
    # Body x of the quarter-MAC point of a trapezoid (Raymer, Aircraft Design, Fig. 7.3:
    # ybar = b/6 (1 + 2 taper)/(1 + taper)).
    lam = surface.taper_ratio
    ybar = surface.span / 6.0 * (1.0 + 2.0 * lam) / (1.0 + lam)
    return (
        surface.root_leading_edge[0]
        - ybar * np.tan(surface.sweep)
        - 0.25 * surface.mean_aerodynamic_chord
    )


@pytest.mark.integration
def test_reference_neutral_point_against_the_classic_formula():
    # Wing-body-tail neutral point by the classic build-up (Raymer, Aircraft Design, eq. 16.9;
    # Etkin & Reid, Dynamics of Flight, eq. 2.3,23): x_np = (x_w CLa_w + eta S_t/S CLa_t
    # (1 - de/da) x_t + (dM/da)_fus/(q S)) / (CLa_w + eta S_t/S CLa_t (1 - de/da)), with
    # DATCOM lift slopes, the far-wake de/da = 2 CLa_w/(pi A) and quarter-MAC aerodynamic
    # centres. The lattice resolves the wing-tail interference and the tail's spanwise
    # downwash that the formula lumps: tolerance 0.1 MAC (the two differ by 0.06 MAC).
    from lpc_mdo.components.aero.polar import LinearQuadraticPolar
    from lpc_mdo.groups.lpc import LPCGroup
    from lpc_mdo.vehicle import reference_vehicle

    v = reference_vehicle()
    w, t = v.wing, v.horizontal_tail
    cla_w = wing_lift_slope(w.aspect_ratio, w.sweep)
    cla_t = wing_lift_slope(t.aspect_ratio, t.sweep)
    tail = v.stability.tail_dynamic_pressure_ratio * t.area / w.area * cla_t
    tail *= 1.0 - 2.0 * cla_w / (np.pi * w.aspect_ratio)
    # Fuselage and booms: Multhopp sums of the file's geometry (BodyMomentSlopeComp's).
    fus = (
        _slope_problem(body_moment_slope_options(v), 9.144, w.area, w.span, w.root_chord)
        .get_val("body_moment_slope")
        .sum()
    )
    x_np = (_quarter_mac_x(w) * cla_w + tail * _quarter_mac_x(t) + fus / w.area) / (cla_w + tail)

    prob = om.Problem(reports=False)
    prob.model = LPCGroup(
        conditions=["cruise"], rotor_polar=LinearQuadraticPolar(), wing_zero_lift_angle=-0.07
    )
    prob.setup()
    prob.run_model()
    model = prob.get_val("cruise.neutral_point", units="m")[0]
    assert abs(model - x_np) < 0.1 * w.mean_aerodynamic_chord
