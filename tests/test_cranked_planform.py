import math

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.geometry.cranked_planform import CrankedPlanformComp, SectionLayout
from lpc_mdo.components.geometry.section_mesh import SectionMeshComp, kinked_stations
from lpc_mdo.vehicle import VehicleSpecError, read_vehicle_file, vehicle_from_dict

FT = 0.3048
# NASA LPC wing of OpenVSP as MCEVS NASA_LPC_Wing lists it (github.com/alfiyandyhr/MCEVS,
# MCEVS/Applications/OpenVSP/Components/Wing.py), feet, degrees: the span order is root to tip
# (the listed order gives S = 210.278 ft^2, the reversed order 130.8 ft^2).
SPANS = np.array([14.745022, 6.626930, 2.083091, 1.809956])
CHORDS = np.array([5.4432819, 4.1308305, 3.304664, 2.840884, 1.043961])
SWEEP = np.radians([0.0, 0.0, 3.636364, 8.0])
DIHEDRAL = math.radians(-2.0)
VSP_AREA, VSP_AR = 210.27814 * FT**2, 12.12761

LAYOUT = SectionLayout(
    span_fraction=SPANS / SPANS.sum(),
    chord_ratio=CHORDS / CHORDS[0],
    sweep=SWEEP,
    sweep_location=[0.7] * 4,
    dihedral=[DIHEDRAL] * 4,
    twist=np.radians([0.0, -0.5, -0.5, -0.5, -0.5]),
)


def _planform(area, ar, root=(0.0, 0.0, 0.0), layout=LAYOUT):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("planform", CrankedPlanformComp(layout=layout), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("area", area)
    prob.set_val("aspect_ratio", ar)
    prob.set_val("root_leading_edge", np.array(root))
    prob.run_model()
    return prob


def test_reproduces_the_openvsp_wing():
    # At the VSP area and aspect ratio the scaled planform is the VSP wing: chords to the
    # listed 7 digits, projected half span 25.26 ft cos 2 deg = 25.2496 ft (CAD tip LE y =
    # 25.25 ft, LPC_final_custom_blades.stp), tolerance 1e-6.
    prob = _planform(VSP_AREA, VSP_AR)
    assert_near_equal(prob.get_val("section_chords", units="ft"), CHORDS, 1e-6)
    assert_near_equal(
        prob.get_val("span", units="ft")[0] / 2, SPANS.sum() * math.cos(DIHEDRAL), 1e-6
    )
    le = prob.get_val("section_leading_edges", units="ft")
    # CAD tip leading edge 12.356 - 8.892 = 3.464 ft aft of the root LE (x aft in CAD); the
    # sections give 0.7 c_root + sum s_k tan(sweep_k) - 0.7 c_tip; tolerance 0.01 ft (CAD
    # coordinates to 3 decimals).
    assert abs(-le[-1, 0] - 3.464) < 0.01


def test_area_span_mac_against_a_hand_integration():
    # Independent: integrate the piecewise-linear chord numerically (20000 points per section)
    # along the section spans s_k = h p_k / cos(G): S = 2 int c ds, MAC = (2/S) int c^2 ds,
    # MAC LE = (2/S) int c X_LE ds, y_MAC = (2/S) int c y ds. Tolerance 1e-7.
    area, ar = 19.6, 12.12
    prob = _planform(area, ar, root=(-1.9, 0.0, -1.07))
    h = 0.5 * math.sqrt(ar * area)
    c_root = prob.get_val("root_chord")[0]
    chords = c_root * CHORDS / CHORDS[0]
    le = prob.get_val("section_leading_edges")
    s_true = h * SPANS / SPANS.sum() / math.cos(DIHEDRAL)
    a = mac = mac_x = mac_y = 0.0
    for k in range(4):
        t = np.linspace(0.0, 1.0, 20001)
        c = chords[k] + (chords[k + 1] - chords[k]) * t
        x = le[k] + (le[k + 1] - le[k]) * t[:, None]
        a += 2 * s_true[k] * np.trapezoid(c, t)
        mac += 2 * s_true[k] * np.trapezoid(c**2, t)
        mac_x += 2 * s_true[k] * np.trapezoid(c * x[:, 0], t)
        mac_y += 2 * s_true[k] * np.trapezoid(c * x[:, 1], t)
    assert_near_equal(a, area, 1e-7)
    assert_near_equal(prob.get_val("span")[0], math.sqrt(ar * area), 1e-12)
    assert_near_equal(prob.get_val("mean_aerodynamic_chord")[0], mac / a, 1e-7)
    assert_near_equal(prob.get_val("mac_leading_edge")[0], mac_x / a, 1e-7)
    assert_near_equal(prob.get_val("mac_leading_edge")[1], mac_y / a, 1e-7)
    # The section leading edges: the 70 % chord line has no sweep over sections 1-2, so there
    # the LE moves aft by 0.7 (c_root - c_k) (x forward: LE x decreases).
    assert_near_equal(le[2, 0] - le[0, 0], -0.7 * (chords[0] - chords[2]), 1e-12)


def test_one_trapezoidal_section_is_the_textbook_trapezoid():
    # Raymer, Aircraft Design (6th ed., Fig. 7.5): c_root = 2S/((1+l) b),
    # MAC = (2/3) c_root (1 + l + l^2)/(1 + l), y_MAC = (b/6)(1 + 2l)/(1 + l); no dihedral.
    lam, sweep = 0.2, math.radians(7.81)
    layout = SectionLayout([1.0], [1.0, lam], [sweep], [0.0], [0.0], [0.0, 0.0])
    prob = _planform(19.6, 12.12, layout=layout)
    b = math.sqrt(19.6 * 12.12)
    c_root = 2 * 19.6 / ((1 + lam) * b)
    assert_near_equal(prob.get_val("root_chord")[0], c_root, 1e-13)
    assert_near_equal(
        prob.get_val("mean_aerodynamic_chord")[0],
        2 / 3 * c_root * (1 + lam + lam**2) / (1 + lam),
        1e-13,
    )
    y_mac = b / 6 * (1 + 2 * lam) / (1 + lam)
    assert_near_equal(
        prob.get_val("mac_leading_edge"), [-y_mac * math.tan(sweep), y_mac, 0.0], 1e-12
    )


def test_planform_partials():
    prob = _planform(19.6, 12.12, root=(-1.9, 0.1, -1.07))
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def _mesh_problem(panels=26, chord_panels=2):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("planform", CrankedPlanformComp(layout=LAYOUT), promotes=["*"])
    prob.model.add_subsystem(
        "mesh",
        SectionMeshComp(layout=LAYOUT, num_span_panels=panels, num_chord_panels=chord_panels),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("area", 19.6)
    prob.set_val("aspect_ratio", 12.12)
    prob.set_val("root_leading_edge", np.array([-1.95925, 0.0, -1.0729]))
    prob.set_val("incidence", math.radians(2.04))
    prob.run_model()
    return prob


def test_mesh_has_nodes_on_the_kinks_and_the_sections():
    prob = _mesh_problem()
    mesh = prob.get_val("mesh")
    le = prob.get_val("section_leading_edges")
    chords = prob.get_val("section_chords")
    y = mesh[0, 13:, 1]
    for k in range(5):
        j = int(np.argmin(abs(y - le[k, 1])))
        assert_near_equal(mesh[0, 13 + j], le[k], 1e-12)
        # chord length and pitch: incidence + twist (-0.5 deg outboard of the root)
        chord = mesh[-1, 13 + j] - mesh[0, 13 + j]
        assert_near_equal(np.linalg.norm(chord), chords[k], 1e-12)
        theta = math.radians(2.04 - (0.5 if k else 0.0))
        assert_near_equal(chord[2] / -chord[0], math.tan(theta), 1e-10)
    assert_near_equal(mesh[:, ::-1, 0], mesh[:, :, 0], 1e-14)
    assert_near_equal(mesh[:, ::-1, 1], -mesh[:, :, 1], 1e-14)
    # 13 panels per half: enough for 3 kinks; 4 panels (2 per half) are not.
    assert kinked_stations(LAYOUT, 26).size == 14
    with pytest.raises(ValueError, match="num_span_panels = 4"):
        kinked_stations(LAYOUT, 4)


def test_mesh_partials():
    prob = _mesh_problem(10, 2)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def _sections_dict():
    data = read_vehicle_file()
    wing = data["wing"]
    wing["planform"] = "sections"
    wing.pop("taper_ratio", None)
    wing["sections"] = [
        {
            "span": float(s * FT),
            "root_chord": float(CHORDS[k] * FT),
            "tip_chord": float(CHORDS[k + 1] * FT),
            "sweep_deg": float(np.degrees(SWEEP[k])),
            "sweep_location": 0.7,
            "twist_deg": -0.5,
            "dihedral_deg": -2.0,
        }
        for k, s in enumerate(SPANS)
    ]
    return data


def test_vehicle_file_sections_build_the_layout():
    vehicle = vehicle_from_dict(_sections_dict())
    layout = SectionLayout.from_wing(vehicle.wing)
    assert_near_equal(layout.chord_ratio, LAYOUT.chord_ratio, 1e-12)
    assert_near_equal(layout.span_fraction, LAYOUT.span_fraction, 1e-12)
    assert vehicle.wing.taper_ratio == pytest.approx(CHORDS[-1] / CHORDS[0])
    # Wing properties follow the sections (1.66 m root chord where the taper-0.2 trapezoid
    # of the same area has 2.12 m).
    prob = _planform(vehicle.wing.area, vehicle.wing.aspect_ratio, layout=layout)
    assert_near_equal(vehicle.wing.root_chord, prob.get_val("root_chord")[0], 1e-12)
    assert_near_equal(
        vehicle.wing.mean_aerodynamic_chord, prob.get_val("mean_aerodynamic_chord")[0], 1e-12
    )


@pytest.mark.parametrize(
    "edit, message",
    [
        (lambda w: w.pop("sections"), "missing key 'wing.sections'"),
        (lambda w: w.update(taper_ratio=0.2), "'wing.taper_ratio' = 0.2 is given"),
        (
            lambda w: w["sections"][2].update(root_chord=1.2),
            r"'wing.sections\[2\].root_chord' = 1.2 differs",
        ),
        (lambda w: w["sections"][1].update(span=-1.0), r"'wing.sections\[1\].span'"),
        (lambda w: w.update(planform="cranked"), "'wing.planform' = 'cranked' is not allowed"),
        (
            lambda w: w.update(planform="trapezoid", taper_ratio=0.2),
            "'wing.sections' is given with wing.planform = 'trapezoid'",
        ),
    ],
)
def test_bad_wing_sections(edit, message):
    data = _sections_dict()
    edit(data["wing"])
    with pytest.raises(VehicleSpecError, match=message):
        vehicle_from_dict(data)
