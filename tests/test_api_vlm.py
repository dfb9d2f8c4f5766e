"""lpc_mdo.api.vlm against published and closed-form numbers, and its argument checks."""

import math

import numpy as np
import openmdao.api as om
import pytest
from scipy.optimize import brentq

import lpc_mdo.api as lpc
from lpc_mdo.api.vlm import _check_surface, surface_mesh
from lpc_mdo.components.geometry.planform import PlanformMeshComp


def _rectangle(span, chord, ns, nc, spacing="uniform", **extra):
    return {
        "span": span,
        "root_chord": chord,
        "tip_chord": chord,
        "num_spanwise": ns,
        "num_chordwise": nc,
        "spacing": spacing,
        **extra,
    }


@pytest.mark.parametrize(
    "ns, nc, cl, cdi", [(10, 2, 0.44264, 0.005877), (20, 6, 0.43333, 0.005926)]
)
def test_public_code_reference_numbers(ns, nc, cl, cdi):
    # The numbers of tests/test_vlm_verification.py (docs theory/aerodynamics 'Validation',
    # VortexAD_temp ex1_oas.py): b = 10 m, c = 1 m, linear spacing, alpha = 5 deg, V = 60 m/s,
    # rho = 1.225. Tolerance: the 5 printed digits.
    out = lpc.vlm(_rectangle(10.0, 1.0, ns, nc), alpha_deg=5.0, velocity=60.0)
    assert out["CL"] == pytest.approx(cl, rel=2e-5)
    assert out["CDi"] == pytest.approx(cdi, rel=2e-4)
    assert out["reference_area"] == pytest.approx(10.0, rel=1e-15)


def test_bertin_smith_swept_wing():
    # Bertin & Smith, Aerodynamics for Engineers, VLM example (as tests/test_vlm_verification.py):
    # AR 5, untapered, 45 deg sweep, 4 horseshoes per semispan: CL_alpha = 3.433 /rad; 1 %.
    wing = _rectangle(5.0, 1.0, 8, 1, sweep_le_deg=45.0)
    out = lpc.vlm(wing, alpha_deg=1.0, velocity=50.0)
    assert out["CL"] / math.radians(1.0) == pytest.approx(3.433, rel=0.01)


def test_tapered_wing_matches_lifting_line():
    # Prandtl lifting line, elliptic loading: CL_alpha = 2 pi AR/(AR + 2) and CDi = CL^2/(pi e AR)
    # with e = 1. A taper-0.4 wing is the near-elliptic trapezoid (Glauert's delta < 0.01 at
    # high AR), AR 20. Measured: slope 2.0 % below the formula (the lifting surface lifts less
    # than the lifting line), e = 0.998 (Trefftz) and 0.994 (near field). Acceptance: slope
    # within 3 %, e in [0.98, 1.0], near-field and Trefftz drag within 1 %.
    span, aspect_ratio, taper = 10.0, 20.0, 0.4
    area = span**2 / aspect_ratio
    root = 2.0 * area / (span * (1.0 + taper))
    wing = {
        "span": span,
        "root_chord": root,
        "tip_chord": taper * root,
        "num_spanwise": 60,
        "num_chordwise": 4,
    }
    out = lpc.vlm(wing, alpha_deg=[2.0, 4.0], velocity=50.0)
    assert out["reference_area"] == pytest.approx(area, rel=1e-12)
    slope = (out["CL"][1] - out["CL"][0]) / math.radians(2.0)
    assert slope == pytest.approx(2 * math.pi * aspect_ratio / (aspect_ratio + 2), rel=0.03)
    e = out["CL"] ** 2 / (math.pi * aspect_ratio * out["CDi_trefftz"])
    assert np.all((0.98 <= e) & (e <= 1.0))
    np.testing.assert_allclose(out["CDi"], out["CDi_trefftz"], rtol=0.01)
    # the sectional cl integrates to the lift: sum c_l q c dy = L (planar, unswept LE here is
    # swept slightly by the taper: 1e-3 as in tests/test_vlm_verification.py)
    data = out["surfaces"]["surface_0"]
    dy = np.diff(data["mesh"][0, :, 1])
    q = 0.5 * 1.225 * 50.0**2
    lift = np.sum(data["cl"] * q * data["chord"] * dy, axis=1)
    np.testing.assert_allclose(lift, out["lift"], rtol=1e-3)
    np.testing.assert_allclose(data["lift"], out["lift"], rtol=1e-12)


def test_flat_plate_moment_about_quarter_chord():
    # Thin-airfoil theory: a flat plate's centre of pressure is at the quarter chord, so a
    # rectangular flat-plate wing has CM = 0 about its quarter chord (x = -c/4 in the body frame,
    # x forward). One chord-wise panel: the bound vortex lies on c/4, CM = 0 to round-off. Eight
    # chord-wise panels (AR 10): within 1 % of CL (centre of pressure within 1 % c of c/4).
    chord = 1.2
    quarter = (-0.25 * chord, 0.0, 0.0)
    one = lpc.vlm(_rectangle(12.0, chord, 20, 1), 4.0, 50.0, reference_point=quarter)
    assert abs(one["CM"]) < 1e-12 * one["CL"]
    assert one["reference_chord"] == pytest.approx(chord, rel=1e-15)
    eight = lpc.vlm(_rectangle(12.0, chord, 20, 8), 4.0, 50.0, reference_point=quarter)
    assert abs(eight["CM"]) < 0.01 * eight["CL"]


def test_moment_transfer_rule():
    # M(p2) = M(p1) + (p1 - p2) x F exactly; CM is M_y/(q S c_ref), positive nose up: about
    # the leading edge (ahead of the lift) the moment is nose down.
    wing = {"span": 8.0, "root_chord": 1.4, "tip_chord": 0.6, "sweep_le_deg": 10.0}
    p1, p2 = np.array([0.3, 0.0, 0.2]), np.array([-0.5, 0.0, -0.1])
    a = lpc.vlm(wing, 5.0, 40.0, reference_point=p1)
    b = lpc.vlm(wing, 5.0, 40.0, reference_point=p2)
    np.testing.assert_allclose(b["moment"], a["moment"] + np.cross(p1 - p2, a["force"]), atol=1e-9)
    lead = lpc.vlm(wing, 5.0, 40.0)
    assert lead["CM"] < 0.0
    q_s_c = 0.5 * 1.225 * 40.0**2 * lead["reference_area"] * lead["reference_chord"]
    assert lead["CM"] == pytest.approx(lead["moment"][1] / q_s_c, rel=1e-14)


def test_mesh_equals_planform_component():
    # Without sections the mesh is the PlanformMeshComp mesh with linear twist (incidence =
    # root twist, extra twist (tip - root) abs(eta) at the half-span nodes).
    surface = _check_surface(
        0,
        {
            "span": 9.0,
            "root_chord": 1.5,
            "tip_chord": 0.7,
            "sweep_le_deg": 12.0,
            "dihedral_deg": 4.0,
            "twist_root_deg": 2.0,
            "twist_tip_deg": -3.0,
            "root_le": (-2.0, 0.3, -1.0),
            "num_spanwise": 12,
            "num_chordwise": 3,
        },
    )
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "planform", PlanformMeshComp(num_span_panels=12, num_chord_panels=3), promotes=["*"]
    )
    prob.setup()
    eta = np.abs(np.cos(np.pi * np.arange(13) / 12))[6:]
    for name, value in (
        ("span", 9.0),
        ("root_chord", 1.5),
        ("tip_chord", 0.7),
        ("sweep", math.radians(12.0)),
        ("dihedral", math.radians(4.0)),
        ("incidence", math.radians(2.0)),
        ("twist", math.radians(-5.0) * eta),
        ("root_leading_edge", [-2.0, 0.3, -1.0]),
    ):
        prob.set_val(name, value)
    prob.run_model()
    np.testing.assert_allclose(surface_mesh(surface), prob.get_val("mesh"), atol=1e-12)


def test_cranked_planform():
    # A break on the straight trapezoid reproduces the trapezoid; a real crank has the area and
    # mean aerodynamic chord of its two trapezoids: S = 2 sum (c_a + c_b)/2 dy,
    # MAC = (2/S) sum (c_a^2 + c_a c_b + c_b^2)/3 dy.
    base = {"span": 10.0, "root_chord": 1.6, "tip_chord": 0.6, "sweep_le_deg": 5.0}
    tip_offset = 5.0 * math.tan(math.radians(5.0))
    straight = dict(base, sections=[(0.4, 1.6 - 0.4 * 1.0, 0.4 * tip_offset)])
    a = lpc.vlm(base, 3.0, 50.0)
    b = lpc.vlm(straight, 3.0, 50.0)
    assert b["CL"] == pytest.approx(a["CL"], rel=1e-12)
    cranked = dict(base, sections=[(0.4, 1.2, 0.1)], name="wing")
    out = lpc.vlm(cranked, 3.0, 50.0)
    dy = np.array([2.0, 3.0])
    ca, cb = np.array([1.6, 1.2]), np.array([1.2, 0.6])
    area = 2.0 * np.sum(0.5 * (ca + cb) * dy)
    mac = 2.0 * np.sum((ca**2 + ca * cb + cb**2) / 3.0 * dy) / area
    assert out["reference_area"] == pytest.approx(area, rel=1e-14)
    assert out["reference_chord"] == pytest.approx(mac, rel=1e-14)
    wing = out["surfaces"]["wing"]
    mesh = wing["mesh"]
    f = np.abs(mesh[0, :, 1]) / 5.0  # leading edge at every node: piecewise linear
    x_le = -np.interp(f, [0.0, 0.4, 1.0], [0.0, 0.1, tip_offset])
    np.testing.assert_allclose(mesh[0, :, 0], x_le, atol=1e-14)
    chord = np.interp(f, [0.0, 0.4, 1.0], [1.6, 1.2, 0.6])
    np.testing.assert_allclose(mesh[0, :, 0] - mesh[-1, :, 0], chord, atol=1e-14)
    assert out["CL"] > 0.0 and wing["cl"].shape == (20,)


def test_cambered_airfoil_shifts_the_zero_lift_angle():
    # The airfoil enters through its sectional zero-lift angle alpha_0 (the root of the polar's
    # cl, found here independently from api.airfoil_polar): an untwisted wing then has CL = 0 at
    # alpha = alpha_0 (to round-off) and CL(0) = CL_flat(-alpha_0) up to the wake direction
    # (which follows the free stream: 1 %).
    wing = _rectangle(10.0, 1.0, 20, 2, airfoil="ls413", reynolds=3e6)
    alpha0 = brentq(lambda a: lpc.airfoil_polar("ls413", a, 3e6)["cl"], -10.0, 5.0, xtol=1e-12)
    out = lpc.vlm(wing, [0.0, alpha0], 60.0)
    assert out["surfaces"]["surface_0"]["zero_lift_angle_deg"] == pytest.approx(alpha0, abs=1e-8)
    assert abs(out["CL"][1]) < 1e-12
    flat = lpc.vlm(dict(wing, airfoil=None), -alpha0, 60.0)
    assert out["CL"][0] == pytest.approx(flat["CL"], rel=0.01)
    # default Reynolds number: rho V MAC / mu(sea level)
    default = lpc.vlm(dict(wing, reynolds=None), 0.0, 60.0)
    assert default["surfaces"]["surface_0"]["reynolds"] == pytest.approx(
        1.225 * 60.0 * 1.0 / 1.7894e-5, rel=1e-4
    )


def test_two_surfaces_see_each_other():
    # The tail behind the wing carries less lift than alone (downwash), the wing nearly the same.
    wing = {"span": 10.0, "root_chord": 1.0, "name": "wing"}
    tail = {"span": 3.0, "root_chord": 0.6, "root_le": (-5.0, 0.0, 0.0), "name": "tail"}
    both = lpc.vlm([wing, tail], 4.0, 50.0)
    alone = lpc.vlm(tail, 4.0, 50.0)
    assert both["surfaces"]["tail"]["lift"] < 0.8 * alone["lift"]
    assert both["lift"] == pytest.approx(
        both["surfaces"]["wing"]["lift"] + both["surfaces"]["tail"]["lift"], rel=1e-12
    )
    assert both["reference_area"] == pytest.approx(10.0)


@pytest.mark.parametrize(
    "change, match",
    [
        ({"spam": 1}, r"surfaces\[0\]: unknown key\(s\) 'spam'; allowed keys: span"),
        ({"span": -1.0}, r"'span' = -1.0 is out of range: must be > 0 \(m\)"),
        ({"span": "10"}, r"'span' must be a number, got str '10'"),
        ({"tip_chord": -0.1}, r"'tip_chord' = -0.1 is out of range: must be >= 0 \(m\)"),
        ({"num_spanwise": 7}, r"'num_spanwise' = 7 is out of range: must be >= 2 and even"),
        ({"num_spanwise": 2.5}, r"'num_spanwise' must be an integer"),
        ({"num_chordwise": 0}, r"'num_chordwise' = 0 is out of range: must be in \[1, 50\]"),
        ({"spacing": "linear"}, r"'spacing' = 'linear' is not allowed: must be one of"),
        ({"sweep_le_deg": 90.0}, r"'sweep_le_deg' = 90.0 is out of range: must be in \(-90, 90\)"),
        ({"root_le": (0, 0)}, r"'root_le' must have shape \(3,\), got shape \(2,\)"),
        ({"twist_tip_deg": float("nan")}, r"'twist_tip_deg' = nan is out of range: must be a fin"),
        ({"sections": [(0.6, 1.0, 0.0), (0.5, 1.0, 0.0)]}, r"'sections\[1\]\[0\] \(span_frac"),
        ({"sections": [(0.5, 1.0)]}, r"'sections\[0\]' = \(0.5, 1.0\) is not allowed"),
        ({"airfoil": "naca9999"}, r"surface 'surface_0': 'airfoil': airfoil = 'naca9999'"),
        ({"name": "my wing"}, r"'name' = 'my wing' is not allowed: must be a Python identifier"),
        ({"num_spanwise": 200, "num_chordwise": 20}, r"= 4000 is out of range: must be <= 2000"),
    ],
)
def test_bad_surface_is_a_named_error(change, match):
    with pytest.raises(ValueError, match=match):
        lpc.vlm({"span": 10.0, "root_chord": 1.0, **change}, 2.0, 50.0)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"velocity": 0.0}, r"vlm: 'velocity' = 0.0 is out of range: must be > 0 \(m/s\)"),
        ({"alpha_deg": [1.0, 95.0]}, r"vlm: 'alpha_deg\[1\]' = 95.0 is out of range"),
        ({"density": -1.0}, r"'density' = -1.0 is out of range: must be > 0 \(kg/m\*\*3\)"),
        ({"reference_area": 0.0}, r"'reference_area' = 0.0 is out of range"),
        ({"reference_point": (0, 0)}, r"'reference_point' must have shape \(3,\)"),
        ({"surfaces": []}, r"vlm: 'surfaces' = \[\] is not allowed"),
        ({"surfaces": [{"span": 1.0}]}, r"missing required key\(s\) 'root_chord'"),
    ],
)
def test_bad_argument_is_a_named_error(kwargs, match):
    args = {"surfaces": {"span": 10.0, "root_chord": 1.0}, "alpha_deg": 2.0, "velocity": 50.0}
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        lpc.vlm(**args)
