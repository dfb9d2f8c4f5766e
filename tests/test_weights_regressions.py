import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.weights.regressions import (
    BoomRegressionComp,
    EmpennageRegressionComp,
    FuselageRegressionComp,
    WingRegressionComp,
    m4_coefficients,
)

# Nose of the body frame in the M4 (CAD, metres) frame: (2.464, 0, 5.113) ft x 0.3048.
NOSE = np.array([2.464, 0.0, 5.113]) * 0.3048
MAIN = ("wing_area", "wing_aspect_ratio", "fuselage_length", "battery_mass", "cruise_speed")

# docs theory/weights 'M4 regressions', validation points computed from the
# coefficients: (S_w, AR, L, m_b, V) -> fuselage mass, total boom mass, wing (regression) mass,
# fuselage cg_X, cg_Z (M4 frame). Printed with 4 decimals.
VALIDATION = [
    ((19.5, 12.0, 9.0, 800.0, 67.0), 311.0062, 117.0665, 280.7108, 3.8330, 1.6769),
    ((19.6, 12.12, 9.144, 800.0, 61.25), 316.7976, 118.0712, 284.3352, 3.8964, 1.6855),
    ((19.6, 12.12, 9.144, 953.93, 61.25), 321.5783, 118.0910, 281.0371, 3.8524, 1.6854),
    ((19.6, 12.12, 9.144, 800.0, 57.19), 316.5185, 118.0966, 283.3605, 3.8911, 1.6855),
]


def run(comp, **values):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("comp", comp, promotes=["*"])
    prob.setup(force_alloc_complex=True)
    for name, value in values.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob


@pytest.mark.parametrize("point", VALIDATION)
def test_validation_points(point):
    x, fuselage, booms, wing, cg_x, cg_z = point
    inputs = dict(zip(MAIN, x, strict=True))
    fus = run(FuselageRegressionComp(cg_x_factor=1.0), **inputs)
    # Masses: the page prints 4 decimals, i.e. a relative precision better than 2e-7 at these
    # magnitudes, so 1e-6 relative is the acceptance tolerance.
    assert_near_equal(fus.get_val("fuselage_mass"), fuselage, 1e-6)
    assert_near_equal(run(BoomRegressionComp(), **inputs).get_val("boom_mass"), booms, 1e-6)
    assert_near_equal(run(WingRegressionComp(), **inputs).get_val("wing_mass"), wing, 1e-6)
    # cg back in the M4 frame (k_x = 1 here): x_M4 = x_nose - x_body, z_M4 = z_nose - z_body;
    # the page's 4 decimals allow 5e-5 m (+ round-off).
    cg = fus.get_val("fuselage_cg")
    assert abs(NOSE[0] - cg[0] - cg_x) < 6e-5
    assert abs(NOSE[2] - cg[2] - cg_z) < 6e-5
    assert cg[1] == 0.0


def test_empennage_validation_points():
    # Reference docs theory/weights 'M4 regressions': (S_h, S_v) = (3.5, 2.5) -> 54.4502 kg;
    # (3.7, 2.54) -> 56.5389 kg (4 decimals).
    for areas, mass in (((3.5, 2.5), 54.4502), ((3.7, 2.54), 56.5389)):
        prob = run(EmpennageRegressionComp(), htail_area=areas[0], vtail_area=areas[1])
        assert_near_equal(prob.get_val("empennage_mass"), mass, 1e-6)


def test_fuselage_frame_and_factors():
    # docs theory/weights 'M4 regressions' (as coded): body cg = (x_n - 0.88 cg_X, 0, z_n - cg_Z);
    # cg_X, cg_Z at the paper cruise speed from the docs theory/weights 'M4 regressions' row 4
    # inputs (by hand from the docs theory/weights 'M4 regressions' coefficients:
    # cg_X = 3.8911491674, cg_Z = 1.6855289202, 1e-9 m).
    x = dict(zip(MAIN, (19.6, 12.12, 9.144, 800.0, 57.19), strict=True))
    prob = run(FuselageRegressionComp(), **x)
    assert_near_equal(
        prob.get_val("fuselage_cg"),
        [NOSE[0] - 0.88 * 3.8911491674, 0.0, NOSE[2] - 1.6855289202],
        1e-9,
    )
    # Own inertia: Ixx, Iyy, Izz, Ixz of docs theory/weights 'M4 regressions' at these inputs
    # (plain arithmetic, 1e-9 relative); rotating x aft/z up to x forward/z down keeps I_xz.
    c = m4_coefficients()["fuselage"]
    xt = np.array([19.6, 12.12, 9.144, 800.0, 57.19, 1.0])
    ixx, iyy, izz, ixz = (
        float(np.dot(c[k], xt)) for k in ("inertia_xx", "inertia_yy", "inertia_zz", "inertia_xz")
    )
    assert_near_equal(
        prob.get_val("fuselage_inertia"), [[ixx, 0, ixz], [0, iyy, 0], [ixz, 0, izz]], 1e-9
    )
    # mass_factor scales mass and own inertia (public run scripts: 1.3).
    scaled = run(FuselageRegressionComp(mass_factor=1.3), **x)
    assert_near_equal(scaled.get_val("fuselage_mass"), 1.3 * prob.get_val("fuselage_mass"), 1e-12)
    assert_near_equal(
        scaled.get_val("fuselage_inertia"), 1.3 * prob.get_val("fuselage_inertia"), 1e-12
    )


def test_boom_parallel_axis():
    # Independent evaluation of docs theory/weights 'M4 regressions' with the
    # docs theory/weights 'Public-code compatibility' correction, written out per group:
    # m_g = m/4; cg = mean of the group cgs with y = 0; I = sum_g [diag(Ixx, Iyy, Izz)_g +
    # m_g ((r.r) 1 - r r^T)], r = cg_g - cg (body frame: x, z flipped about the nose).
    data = m4_coefficients()["booms"]
    xt = np.array([19.6, 12.12, 9.144, 800.0, 57.19, 1.0])
    mass = float(np.dot(data["mass"], xt))
    points, own = [], []
    for g in ("in_port", "out_port", "in_star", "out_star"):
        d = data[g]
        points.append(
            [
                NOSE[0] - np.dot(d["cg_x"], xt),
                np.dot(d["cg_y"], xt),
                NOSE[2] - np.dot(d["cg_z"], xt),
            ]
        )
        own.append(np.diag([np.dot(d[k], xt) for k in ("inertia_xx", "inertia_yy", "inertia_zz")]))
    points = np.array(points)
    cg = points.mean(axis=0) * [1.0, 0.0, 1.0]
    expected = sum(own)
    for p in points:
        r = p - cg
        expected = expected + mass / 4 * (np.dot(r, r) * np.eye(3) - np.outer(r, r))
    prob = run(BoomRegressionComp(), **dict(zip(MAIN, xt[:5], strict=True)))
    assert_near_equal(prob.get_val("boom_cg"), cg, 1e-12)
    assert_near_equal(prob.get_val("boom_inertia"), expected, 1e-12)
    # Sanity against a hand estimate: Ixx is dominated by the spanwise offsets,
    # 2 (m/4)(2.548^2 + 5.715^2) = 2313 kg m^2 (group cg_Y by hand at these inputs), 1 %.
    assert_near_equal(prob.get_val("boom_inertia")[0, 0], 2313.0, 1e-2)


def test_empennage_parallel_axis():
    # Two sub-parts with mass fractions 0.65 / 0.35 (docs theory/weights 'M4 regressions');
    # independent evaluation as above.
    data = m4_coefficients()["empennage"]
    xt = np.array([3.7, 2.54, 1.0])
    mass = float(np.dot(data["mass"], xt))
    parts = []
    for tail, w in (("htail", 0.65), ("vtail", 0.35)):
        d = data[tail]
        p = np.array([NOSE[0] - np.dot(d["cg_x"], xt), 0.0, NOSE[2] - np.dot(d["cg_z"], xt)])
        own = np.diag([np.dot(d[k], xt) for k in ("inertia_xx", "inertia_yy", "inertia_zz")])
        if tail == "htail":  # I_yz changes sign under x, z -> -x, -z
            own[1, 2] = own[2, 1] = -np.dot(d["inertia_yz"], xt)
        else:
            own[0, 2] = own[2, 0] = np.dot(d["inertia_xz"], xt)
        parts.append((w, p, own))
    cg = sum(w * p for w, p, _ in parts)
    expected = sum(
        own + w * mass * (np.dot(p - cg, p - cg) * np.eye(3) - np.outer(p - cg, p - cg))
        for w, p, own in parts
    )
    prob = run(EmpennageRegressionComp(), htail_area=3.7, vtail_area=2.54)
    assert_near_equal(prob.get_val("empennage_cg"), cg, 1e-12)
    assert_near_equal(prob.get_val("empennage_inertia"), expected, 1e-12)


@pytest.mark.parametrize(
    "comp_class",
    [FuselageRegressionComp, WingRegressionComp, BoomRegressionComp, EmpennageRegressionComp],
)
def test_partials(comp_class):
    prob = run(comp_class())
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-10)


def test_boom_cg_at_a_fixed_fuselage_length():
    # cg_fuselage_length = 9.144: at 10.66 m the booms' cg is the regression's at 9.144 m (the
    # wing keeps its station), while mass and inertia follow 10.66 m; 1e-12. Partials by
    # complex step, with d(cg)/dL = 0.
    fixed = run(BoomRegressionComp(cg_fuselage_length=9.144), fuselage_length=10.66)
    at_ref = run(BoomRegressionComp(), fuselage_length=9.144)
    long = run(BoomRegressionComp(), fuselage_length=10.66)
    assert_near_equal(fixed.get_val("boom_cg"), at_ref.get_val("boom_cg"), 1e-12)
    assert_near_equal(fixed.get_val("boom_mass"), long.get_val("boom_mass"), 1e-12)
    assert abs(fixed.get_val("boom_cg")[0] - long.get_val("boom_cg")[0]) > 0.3
    data = fixed.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-10)
    assert np.all(data["comp"][("boom_cg", "fuselage_length")]["J_fd"] == 0.0)


def test_partials_off_design():
    # Away from the initial design, with non-default factors (boom inertia is nonlinear).
    values = dict(
        wing_area=15.04,
        wing_aspect_ratio=15.76,
        fuselage_length=10.66,
        battery_mass=953.93,
        cruise_speed=61.25,
    )
    for comp in (BoomRegressionComp(mass_factor=1.3), FuselageRegressionComp(cg_x_factor=1.0)):
        prob = run(comp, **values)
        data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
        assert_check_partials(data, atol=1e-8, rtol=1e-10)
    prob = run(EmpennageRegressionComp(htail_mass_fraction=0.5), htail_area=2.59, vtail_area=2.0)
    assert_check_partials(
        prob.check_partials(method="cs", compact_print=True, out_stream=None), atol=1e-8, rtol=1e-10
    )


def test_bad_inputs_and_options():
    with pytest.raises(
        om.AnalysisError,
        match=r"'wing_area' = -1.0 is out of range: "
        r"must be > 0 \(m\*\*2\)",
    ):
        run(FuselageRegressionComp(), wing_area=-1.0)
    # Outside the fuselage-length data range [6.4008, 11.8872] m the regressions stop.
    for comp in (FuselageRegressionComp, WingRegressionComp, BoomRegressionComp):
        with pytest.raises(
            om.AnalysisError,
            match=r"'fuselage_length' = 1.0 is out of range: must be in \[6.4008, 11.8872\] \(m\)",
        ):
            run(comp(), fuselage_length=1.0)
    # The edge itself holds, also a few ulps outside it, where a design variable on its bound
    # arrives after the driver's scaling (a sweep point failed on 6.400799999999999); 1 mm
    # outside does not.
    run(FuselageRegressionComp(), fuselage_length=6.400799999999999)
    run(FuselageRegressionComp(), fuselage_length=11.887200000000002)
    with pytest.raises(om.AnalysisError, match=r"'fuselage_length' = 6.3998 is out of range"):
        run(FuselageRegressionComp(), fuselage_length=6.3998)
    # An aspect ratio of 500 extrapolates to a negative mass: 1.01 - 0.4068 x 500 + 42.6 x
    # 6.4008 + 0.0311 x 800 + 0.0687 x 57.19 - 116.7 = -17.7 kg.
    with pytest.raises(om.AnalysisError, match="fuselage_mass = .* must be > 0"):
        run(
            FuselageRegressionComp(), wing_area=1.0, wing_aspect_ratio=500.0, fuselage_length=6.4008
        )
    with pytest.raises(ValueError, match=r"'mass_factor' = -1.3 is out of range: must be > 0"):
        FuselageRegressionComp(mass_factor=-1.3)
    with pytest.raises(
        ValueError,
        match=r"'htail_mass_fraction' = 1.5 is out of "
        r"range: must be in \[0, 1\]",
    ):
        EmpennageRegressionComp(htail_mass_fraction=1.5)
    with pytest.raises(ValueError, match=r"'nose' must have shape \(3,\), got shape \(2,\)"):
        BoomRegressionComp(nose=(1, 2))
