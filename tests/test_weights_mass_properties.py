import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.weights.mass_properties import (
    MassItem,
    MassPropertiesComp,
    transport_inertia,
)


def run(items, **values):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("mp", MassPropertiesComp(items=items), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    for name, value in values.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob


def test_two_point_masses():
    # Closed form: m1 = 1 kg at the origin, m2 = 3 kg at x = 4 m -> m = 4 kg, cg = (3, 0, 0) m,
    # I_yy = I_zz = 1 * 3^2 + 3 * 1^2 = 12 kg m^2, I_xx = 0, no products (exact).
    prob = run(
        [MassItem("point", count=2)],
        point_mass=[1.0, 3.0],
        point_cg=[[0.0, 0.0, 0.0], [4.0, 0.0, 0.0]],
    )
    assert_near_equal(prob.get_val("total_mass"), 4.0, 1e-15)
    assert_near_equal(prob.get_val("cg"), [3.0, 0.0, 0.0], 1e-15)
    assert_near_equal(prob.get_val("inertia"), np.diag([0.0, 12.0, 12.0]), 1e-14)


def test_symmetric_layout_is_translation_invariant():
    # Closed form: 4 equal masses m at (+-a, +-b, 0) around c: I_xx = 4 m b^2, I_yy = 4 m a^2,
    # I_zz = 4 m (a^2 + b^2), no products, cg = c (exact; 1e-12 for round-off in the shift).
    m, a, b = 2.5, 3.0, 1.5
    c = np.array([-2.0, 0.7, 0.3])
    offsets = np.array([[a, b, 0.0], [a, -b, 0.0], [-a, b, 0.0], [-a, -b, 0.0]])
    prob = run([MassItem("rotor", count=4)], rotor_mass=np.full(4, m), rotor_cg=c + offsets)
    assert_near_equal(prob.get_val("cg"), c, 1e-12)
    assert_near_equal(
        prob.get_val("inertia"), np.diag([4 * m * b**2, 4 * m * a**2, 4 * m * (a**2 + b**2)]), 1e-12
    )


def test_parallel_axis_shift_of_body_with_own_inertia():
    # Closed form: a uniform box (m = 2 kg, sides 1 x 2 x 3 m, own I = m/12 diag(13, 10, 5))
    # at (1, 0, 1) and a 2 kg point mass at (-1, 0, -1): cg = 0, each body adds
    # 2 [[1, 0, -1], [0, 2, 0], [-1, 0, 1]], so I = [[4 + 13/6, 0, -4], [0, 8 + 10/6, 0],
    # [-4, 0, 4 + 5/6]] kg m^2 (exact).
    box = np.diag([13.0, 10.0, 5.0]) * 2.0 / 12.0
    prob = run(
        [MassItem("box", own_inertia=True), MassItem("point")],
        box_mass=2.0,
        box_cg=[1.0, 0.0, 1.0],
        box_inertia=box,
        point_mass=2.0,
        point_cg=[-1.0, 0.0, -1.0],
    )
    assert_near_equal(prob.get_val("total_mass"), 4.0, 1e-15)
    assert_near_equal(prob.get_val("cg"), np.zeros(3), 1e-15)
    expected = np.array([[4 + 13 / 6, 0.0, -4.0], [0.0, 8 + 10 / 6, 0.0], [-4.0, 0.0, 4 + 5 / 6]])
    assert_near_equal(prob.get_val("inertia"), expected, 1e-14)


def test_transport_term_and_derivative():
    # P(r) = (r.r) 1 - r r^T by hand for r = (1, 2, 3); derivative against complex step.
    r = np.array([1.0, 2.0, 3.0])
    p, dp = transport_inertia(r)
    assert_near_equal(p, [[13.0, -2.0, -3.0], [-2.0, 10.0, -6.0], [-3.0, -6.0, 5.0]], 1e-15)
    for ell in range(3):
        step = np.zeros(3, complex)
        step[ell] = 1e-30j
        assert_near_equal(transport_inertia(r + step)[0].imag / 1e-30, dp[..., ell], 1e-14)


def mixed_problem():
    items = [
        MassItem("wing", own_inertia=True),
        MassItem("motor", count=3),
        MassItem("battery"),
        MassItem("booms", count=2, own_inertia=True),
    ]
    rng = np.random.default_rng(7)
    own = rng.normal(size=(2, 3, 3))
    return run(
        items,
        wing_mass=300.0,
        wing_cg=[-3.0, 0.1, -1.0],
        wing_inertia=[[3000.0, 1.0, -20.0], [1.0, 50.0, 2.0], [-20.0, 2.0, 3050.0]],
        motor_mass=[10.0, 12.0, 36.0],
        motor_cg=rng.normal(size=(3, 3)),
        battery_mass=800.0,
        battery_cg=[-2.1, 0.0, 0.56],
        booms_mass=[30.0, 31.0],
        booms_cg=rng.normal(size=(2, 3)),
        booms_inertia=own + own.transpose(0, 2, 1),
    )


def test_mixed_items_against_direct_sum():
    # Independent evaluation: inertia about the origin, sum m (|p|^2 1 - p p^T) + own, then the
    # parallel-axis shift to the cg, I_cg = I_0 - m (|c|^2 1 - c c^T) (1e-12 relative).
    prob = mixed_problem()
    masses, points, own = [], [], np.zeros((3, 3))
    for name, count in (("wing", 1), ("motor", 3), ("battery", 1), ("booms", 2)):
        masses.extend(prob.get_val(f"{name}_mass"))
        points.extend(prob.get_val(f"{name}_cg").reshape(count, 3))
    for name, count in (("wing", 1), ("booms", 2)):
        own += prob.get_val(f"{name}_inertia").reshape(count, 3, 3).sum(axis=0)
    masses, points = np.array(masses), np.array(points)
    total = masses.sum()
    cg = masses @ points / total
    about_origin = own + sum(
        m * (p @ p * np.eye(3) - np.outer(p, p)) for m, p in zip(masses, points, strict=True)
    )
    expected = about_origin - total * (cg @ cg * np.eye(3) - np.outer(cg, cg))
    assert_near_equal(prob.get_val("total_mass"), total, 1e-14)
    assert_near_equal(prob.get_val("cg"), cg, 1e-12)
    assert_near_equal(prob.get_val("inertia"), expected, 1e-12)


def test_partials():
    prob = mixed_problem()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-10)


def test_bad_inputs_and_options():
    with pytest.raises(
        om.AnalysisError,
        match=r"'motor_mass\[1\]' = -2.0 is out of range: "
        r"must be >= 0 \(kg\)",
    ):
        run([MassItem("motor", count=2)], motor_mass=[1.0, -2.0])
    with pytest.raises(
        om.AnalysisError,
        match=r"'total mass' = 0.0 is out of range: "
        r"must be > 0 \(kg\)",
    ):
        run([MassItem("motor", count=2)], motor_mass=[0.0, 0.0])
    with pytest.raises(om.AnalysisError, match=r"'battery_cg\[.*\]' = .* must be a finite number"):
        run([MassItem("battery")], battery_mass=1.0, battery_cg=[np.nan, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"duplicate MassItem names \['a'\]"):
        MassPropertiesComp(items=[MassItem("a"), MassItem("a")])
    with pytest.raises(
        ValueError,
        match=r"MassItem 'motor': 'count' = 0 is out of range: "
        r"must be >= 1",
    ):
        MassItem("motor", count=0)
    with pytest.raises(ValueError, match=r"MassItem.name = 'wing mass'; must be a Python"):
        MassItem("wing mass")


def test_item_table_rows_add_up_and_check_partials():
    # Rows of item_mass_properties: each kind's mass, mass-weighted cg and inertia about the
    # vehicle cg; they add up to the vehicle's mass and tensor (parallel-axis theorem), and a
    # kind of zero mass sits at the mean of its bodies.
    items = [
        MassItem("box", own_inertia=True),
        MassItem("motor", count=3),
        MassItem("spare", count=2),
    ]
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("mp", MassPropertiesComp(items=items, item_table=True), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    rng = np.random.default_rng(3)
    prob.set_val("box_mass", [12.0])
    prob.set_val("box_cg", [0.3, -0.1, 0.2])
    own = rng.normal(size=(3, 3))
    prob.set_val("box_inertia", own + own.T + 6 * np.eye(3))
    prob.set_val("motor_mass", [2.0, 3.0, 4.0])
    prob.set_val("motor_cg", rng.normal(size=(3, 3)))
    prob.set_val("spare_mass", [0.0, 0.0])
    prob.set_val("spare_cg", [[1.0, 2.0, 3.0], [3.0, 0.0, -1.0]])
    prob.run_model()
    table = prob.get_val("item_mass_properties")
    inertia = prob.get_val("inertia")
    assert_near_equal(table[:, 0].sum(), prob.get_val("total_mass")[0], 1e-14)
    for col, (a, b) in zip(
        range(4, 10), [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)], strict=True
    ):
        assert_near_equal(table[:, col].sum(), inertia[a, b], 1e-12)
    motor_cg = np.array([2.0, 3.0, 4.0]) @ prob.get_val("motor_cg") / 9.0
    assert_near_equal(table[1, 1:4], motor_cg, 1e-14)
    assert_near_equal(table[2, 1:4], [2.0, 1.0, 1.0], 1e-14)
    assert_near_equal(table[2, 4:], np.zeros(6), 1e-14)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    # The zero-mass kind's cg has no derivative in its masses (one-sided by definition):
    # checked with positive masses below.
    assert_check_partials(
        {"mp": {k: v for k, v in data["mp"].items() if not (k[0] == "item_mass_properties"
                                                            and k[1] == "spare_mass")}},
        atol=1e-9, rtol=1e-9,
    )  # fmt: skip
    prob.set_val("spare_mass", [0.5, 1.5])
    prob.run_model()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-9, rtol=1e-9)
