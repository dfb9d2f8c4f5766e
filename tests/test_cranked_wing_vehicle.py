"""The cranked NASA LPC wing (planform = "sections") wired through VehicleGroup."""

import dataclasses
import math

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_check_totals,
    assert_near_equal,
)

from lpc_mdo.components.geometry.cranked_planform import SectionLayout
from lpc_mdo.components.structures.section_wing_box_geometry import SectionWingBoxGeometryComp
from lpc_mdo.components.structures.wing_box_geometry import WingBoxGeometryComp
from lpc_mdo.groups.vehicle import VehicleGroup
from lpc_mdo.groups.vlm import VLMGroup, VLMSurface
from lpc_mdo.vehicle import read_vehicle_file, reference_vehicle, vehicle_from_dict

VEHICLE = reference_vehicle()
PANELS = 26


def _vehicle_problem(vehicle=VEHICLE, other_mass=1000.0):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "vehicle",
        VehicleGroup(vehicle=vehicle, other_mass=other_mass, other_cg=(0.0, 0.0, 0.0)),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.run_model()
    return prob


def _hand_planform(wing, points=20001):
    """
    Integrate the vehicle file's sections numerically (trapezoid rule, 20001 points a section).

    Independent of SectionLayout: the sections are scaled to the wing's area and aspect ratio by
    the documented rule (projected half span h = sqrt(AR S)/2 split in the sections' projected
    span proportions; chords in the file's proportions, their scale such that twice the
    integral of c ds over the half wing, ds in each section's plane, is S). The leading edge
    follows each section's swept line at its chord fraction (body frame, x forward).
    """
    proj = np.array([s.span * math.cos(s.dihedral) for s in wing.sections])
    h = 0.5 * math.sqrt(wing.aspect_ratio * wing.area)
    scale_y = h / proj.sum()
    t = np.linspace(0.0, 1.0, points)
    # per section: arc length s in its plane and chord in file units
    strips = [
        (sec, sec.span * scale_y * t, sec.root_chord + t * (sec.tip_chord - sec.root_chord))
        for sec in wing.sections
    ]
    scale_c = wing.area / sum(2.0 * np.trapezoid(c, s) for _, s, c in strips)
    root = wing.sections[0].root_chord * scale_c
    # leading edge: the swept line at chord fraction x_f moves aft by ds tan(sweep)
    integrand_c2 = integrand_cx = 0.0
    line = -wing.sections[0].sweep_location * root  # line x at the root (root LE at 0)
    for sec, s, c_rel in strips:
        c = c_rel * scale_c
        line_x = line - s * math.tan(sec.sweep)
        xle = line_x + sec.sweep_location * c
        integrand_c2 += np.trapezoid(c**2, s)
        integrand_cx += np.trapezoid(c * xle, s)
        line = line_x[-1]
    mac = 2.0 / wing.area * integrand_c2
    mac_x = 2.0 / wing.area * integrand_cx
    return {"span": 2 * h, "root_chord": root, "mac": mac, "mac_le_x": mac_x}


def test_vehicle_planform_against_a_hand_integration_of_the_sections():
    # Independent numbers: trapezoid-rule integration of the file's sections (_hand_planform),
    # tolerance 1e-6 (the rule's error at 20001 points is ~1e-9 of the integrals).
    prob = _vehicle_problem()
    hand = _hand_planform(VEHICLE.wing)
    x0 = VEHICLE.wing.root_leading_edge[0]
    assert_near_equal(prob.get_val("wing_span", units="m")[0], hand["span"], 1e-12)
    assert_near_equal(prob.get_val("wing_root_chord", units="m")[0], hand["root_chord"], 1e-6)
    assert_near_equal(prob.get_val("wing_mac", units="m")[0], hand["mac"], 1e-6)
    assert_near_equal(
        prob.get_val("wing_mac_leading_edge", units="m")[0], x0 + hand["mac_le_x"], 1e-6
    )
    # The numbers of docs theory/geometry 'Cranked wing planform' (3 decimals).
    assert round(prob.get_val("wing_root_chord")[0], 3) == 1.662
    assert round(prob.get_val("wing_mac")[0], 3) == 1.333
    assert round(prob.get_val("wing_mac_leading_edge")[0], 3) == -2.193
    # The Wing properties the drag build-up and polars read agree with the model's planform.
    assert_near_equal(VEHICLE.wing.mean_aerodynamic_chord, prob.get_val("wing_mac")[0], 1e-12)
    # The VLM mesh and the wing box both start at the root chord of that planform and the
    # mesh has its nodes on the kinks: its leading edges at the section ends are the planform's.
    mesh = prob.get_val("wing_mesh", units="m")
    le = prob.get_val("wing_section_leading_edges", units="m")
    right = mesh[0, PANELS // 2 :]
    for k in range(le.shape[0]):
        assert np.min(np.linalg.norm(right - le[k], axis=1)) < 1e-12
    assert_near_equal(prob.get_val("wing_box.chord", units="m")[0], hand["root_chord"], 1e-6)


def _our_lift(mesh, alpha, speed=60.0, density=1.0):
    prob = om.Problem(reports=False)
    ivc = prob.model.add_subsystem("inputs", om.IndepVarComp(), promotes=["*"])
    ivc.add_output("wing_mesh", mesh, units="m")
    prob.model.add_subsystem(
        "vlm", VLMGroup(surfaces=(VLMSurface("wing", 1, PANELS),), num_nodes=1), promotes=["*"]
    )
    prob.setup()
    prob.set_val("speed", [speed], units="m/s")
    prob.set_val("density", [density], units="kg/m**3")
    prob.set_val("angle_of_attack", [alpha], units="deg")
    prob.set_val("sideslip_angle", [0.0], units="deg")
    prob.set_val("reference_area", 1.0, units="m**2")
    prob.set_val("wing_zero_lift_angle", np.zeros((1, PANELS)), units="rad")
    prob.run_model()
    return float(prob.get_val("lift", units="N")[0])


def _openaerostruct_lift(mesh, alpha, speed=60.0, density=1.0):
    from openaerostruct.aerodynamics.aero_groups import AeroPoint
    from openaerostruct.geometry.geometry_group import Geometry

    # OpenAeroStruct's frame: x aft, y right, z up (a rotation of ours by 180 deg about y).
    oas_mesh = mesh * np.array([-1.0, 1.0, -1.0])
    surface = {
        "name": "wing",
        "symmetry": False,
        "S_ref_type": "projected",
        "mesh": oas_mesh,
        "CL0": 0.0,
        "CD0": 0.0,
        "k_lam": 0.05,
        "t_over_c_cp": np.array([0.13]),
        "c_max_t": 0.4,
        "with_viscous": False,
        "with_wave": False,
    }
    prob = om.Problem(reports=False)
    ivc = prob.model.add_subsystem("prob_vars", om.IndepVarComp(), promotes=["*"])
    ivc.add_output("v", val=speed, units="m/s")
    ivc.add_output("alpha", val=alpha, units="deg")
    ivc.add_output("Mach_number", val=0.0)
    ivc.add_output("re", val=1.0e6, units="1/m")
    ivc.add_output("rho", val=density, units="kg/m**3")
    ivc.add_output("cg", val=np.zeros(3), units="m")
    prob.model.add_subsystem("wing", Geometry(surface=surface))
    prob.model.add_subsystem(
        "aero",
        AeroPoint(surfaces=[surface]),
        promotes_inputs=["v", "alpha", "Mach_number", "re", "rho", "cg"],
    )
    prob.model.connect("wing.mesh", "aero.wing.def_mesh")
    prob.model.connect("wing.mesh", "aero.aero_states.wing_def_mesh")
    prob.model.connect("wing.t_over_c", "aero.wing_perf.t_over_c")
    prob.setup()
    prob.run_model()
    cl = float(prob.get_val("aero.wing_perf.CL")[0])
    s_ref = float(prob.get_val("aero.wing.S_ref", units="m**2")[0])
    return cl * 0.5 * density * speed**2 * s_ref


@pytest.mark.parametrize("alpha", [2.0, 5.0])
def test_cranked_wing_vlm_against_openaerostruct(alpha):
    # Independent VLM: OpenAeroStruct 2.12.0 (Jasa et al., "Open-source coupled aerostructural
    # optimization using Python", SMO 57, 2018; github.com/mdolab/OpenAeroStruct), on the same
    # lattice (the cranked reference wing's mesh, 26 x 1 panels with nodes on the kinks,
    # incidence and twist in the node positions), flat-plate sections, Mach 0. Tolerance 0.5 %
    # on the lift (= CL at a common reference area; issue 16). OpenAeroStruct sheds its wake
    # along the body x axis, ours along the relative wind: a difference of second order in alpha.
    pytest.importorskip(
        "openaerostruct",
        reason="OpenAeroStruct (test-only, pip install -e '.[dev]') is not installed",
    )
    mesh = _vehicle_problem().get_val("wing_mesh", units="m")
    ours, theirs = _our_lift(mesh, alpha), _openaerostruct_lift(mesh, alpha)
    assert ours > 0.0
    assert abs(ours / theirs - 1.0) < 0.005


def _with_section_chord(factor, section=2):
    data = read_vehicle_file()
    sections = data["wing"]["sections"]
    sections[section]["tip_chord"] *= factor
    sections[section + 1]["root_chord"] *= factor
    return vehicle_from_dict(data)


def test_a_section_chord_moves_the_wing_box_and_the_wing_mass():
    # A 30 % larger chord at the outer kink (eta = 0.928, end of section 3 of 4) deepens the
    # outer bays (ribs at eta = 0.75, 0.875, 1: bays 7 and 8 reach into section 3); at fixed
    # area the root chord shrinks, so bays 1-6 (inside sections 1-2) scale down together. The
    # VLM mesh, the MAC and the box all follow (one planform).
    base = _vehicle_problem()
    bigger = _vehicle_problem(_with_section_chord(1.3))
    ratio = bigger.get_val("box_height") / base.get_val("box_height")
    assert ratio[-1] > 1.04 and ratio[-2] > 1.02
    assert np.all(ratio[:6] < 1.0)
    assert_near_equal(ratio[:6], np.full(6, ratio[0]), 1e-12)
    assert bigger.get_val("wing_root_chord")[0] < base.get_val("wing_root_chord")[0]
    assert bigger.get_val("wing_mac")[0] != pytest.approx(base.get_val("wing_mac")[0])
    m0, m1 = base.get_val("wing_mass")[0], bigger.get_val("wing_mass")[0]
    assert abs(m1 / m0 - 1.0) > 1e-3
    # Each bay's height is the airfoil thickness at the beam axis (WING_BOX_SECTIONS['ls413'],
    # 0.1243 c) times the mean chord of its two ribs, the chords of the changed planform.
    chord = bigger.get_val("wing_box.chord")
    assert_near_equal(bigger.get_val("box_height"), 0.1243 * 0.5 * (chord[:-1] + chord[1:]), 1e-12)


def _box_problem(layout, nodes=9):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "box", SectionWingBoxGeometryComp(layout=layout, num_nodes=nodes), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    return prob


def test_section_wing_box_partials():
    prob = _box_problem(SectionLayout.from_wing(VEHICLE.wing))
    prob.set_val(
        "section_leading_edges",
        np.array(
            [
                [-2.0, 0, -1],
                [-2.1, 4, -0.9],
                [-2.2, 6, -0.85],
                [-2.4, 6.6, -0.83],
                [-2.9, 7.7, -0.8],
            ]
        ),
    )
    prob.set_val("section_chords", [1.66, 1.26, 1.0, 0.87, 0.32])
    prob.set_val("wing_incidence", 0.04)
    prob.run_model()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_section_wing_box_of_one_section_is_the_trapezoid_box():
    # Independent closed form: one trapezoidal section without dihedral (taper 0.4, LE sweep
    # 5 deg) gives the box of WingBoxGeometryComp (c(eta) = c_r (1 - (1 - taper) eta), x_LE =
    # x_0 - y tan sweep); tolerance 1e-12.
    wing = dataclasses.replace(
        VEHICLE.horizontal_tail, taper_ratio=0.4, sweep=math.radians(5.0), dihedral=0.0
    )
    area, ar, incidence = 19.6, 12.12, math.radians(2.0)
    x0 = np.array([-1.9, 0.0, -1.07])
    layout = SectionLayout.from_wing(wing)
    geometry = layout.geometry(area, ar, x0)
    prob = _box_problem(layout)
    prob.set_val("section_leading_edges", geometry["section_leading_edges"])
    prob.set_val("section_chords", geometry["section_chords"])
    prob.set_val("wing_incidence", incidence)
    prob.run_model()
    ref = om.Problem(reports=False)
    ref.model.add_subsystem(
        "box", WingBoxGeometryComp(num_nodes=9, wing=reference_vehicle().wing), promotes=["*"]
    )
    ref.setup()
    for name, value in (
        ("wing_area", area),
        ("wing_aspect_ratio", ar),
        ("wing_taper_ratio", 0.4),
        ("wing_sweep", math.radians(5.0)),
        ("wing_dihedral", 0.0),
        ("wing_incidence", incidence),
        ("wing_root_leading_edge", x0),
    ):
        ref.set_val(name, value)
    ref.run_model()
    for name in ("nodes", "chord", "box_width", "box_height", "top_skin_radius"):
        assert_near_equal(prob.get_val(name), ref.get_val(name), 1e-12)


def test_totals_of_the_cranked_wing_planform_and_mass():
    prob = _vehicle_problem()
    data = prob.check_totals(
        of=["wing_mac", "wing_mac_leading_edge", "wing_mesh", "wing_mass", "box_height"],
        wrt=["wing_area", "wing_aspect_ratio", "top_skin_thickness"],
        method="cs",
        out_stream=None,
    )
    assert_check_totals(data, atol=1e-8, rtol=1e-7)
