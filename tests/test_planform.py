import dataclasses
import math

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.geometry.planform import PlanformMeshComp, planform_values, span_stations
from lpc_mdo.vehicle import reference_vehicle


def make_problem(num_span_panels=6, num_chord_panels=2, spacing="cosine", values=None):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "planform",
        PlanformMeshComp(
            num_span_panels=num_span_panels, num_chord_panels=num_chord_panels, spacing=spacing
        ),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    for name, value in (values or {}).items():
        prob.set_val(name, value)
    prob.run_model()
    return prob


def test_lpc_wing_mesh_against_vehicle_geometry():
    # PlanformMeshComp builds one trapezoid: the reference wing's area, aspect ratio, sweep,
    # dihedral and incidence with the taper-0.2 trapezoid of the vehicle file's "trapezoid"
    # planform (the cranked reference wing is meshed by SectionMeshComp, tests of its own).
    wing = dataclasses.replace(
        reference_vehicle().wing, planform="trapezoid", sections=None, taper_ratio=0.2
    )
    prob = make_problem(26, 1, values=planform_values(wing))
    mesh = prob.get_val("mesh")
    assert mesh.shape == (2, 27, 3)
    # Span and chords from docs theory/aerodynamics 'Drag build-up' table
    # (b = 15.4127 m, c_root = 2.1195 m, lambda = 0.2) and the vehicle file
    # (LE sweep 7.81 deg, dihedral -2 deg, incidence 2.04 deg, root LE (-1.95925, 0, -1.07290) m);
    # tolerance 1e-4 (table rounding).
    assert_near_equal(mesh[0, -1, 1] - mesh[0, 0, 1], 15.4127, 1e-4)
    le_root, le_tip = mesh[0, 13], mesh[0, 26]
    assert_near_equal(le_root, [-1.95925, 0.0, -1.07290], 1e-12)
    half = 15.4127 / 2
    assert_near_equal(
        le_tip,
        [
            -1.95925 - half * math.tan(math.radians(7.81)),
            half,
            -1.07290 - half * math.tan(math.radians(-2.0)),
        ],
        1e-4,
    )
    # Root chord length and incidence: TE lies c_root (cos i, 0, -sin i) behind/below the LE.
    chord = mesh[1, 13] - mesh[0, 13]
    inc = math.radians(2.04)
    assert_near_equal(chord, [-2.1195 * math.cos(inc), 0.0, 2.1195 * math.sin(inc)], 1e-4)
    tip_chord = np.linalg.norm(mesh[1, 26] - mesh[0, 26])
    assert_near_equal(tip_chord, 0.2 * 2.1195, 1e-4)
    # Mirror symmetry about y = 0 (x and z equal, y opposite).
    assert_near_equal(mesh[:, ::-1, 0], mesh[:, :, 0], 1e-14)
    assert_near_equal(mesh[:, ::-1, 1], -mesh[:, :, 1], 1e-14)


def test_spacing_and_twist():
    # Cosine stations eta_j = -cos(pi j/N) (docs theory/aerodynamics 'Reference-vehicle defaults'
    # "half-cosine"), uniform -1 + 2j/N.
    assert_near_equal(
        span_stations(4, "cosine"), [-1, -math.sqrt(0.5), 0, math.sqrt(0.5), 1], 1e-15
    )
    assert_near_equal(span_stations(4, "uniform"), [-1, -0.5, 0, 0.5, 1], 1e-15)
    values = {
        "span": 4.0,
        "root_chord": 1.0,
        "tip_chord": 1.0,
        "twist": np.radians([0.0, -2.0, -4.0]),
    }
    mesh = make_problem(4, 1, "uniform", values).get_val("mesh")
    # Tip section twisted -4 deg about its leading edge: TE rises by c sin(4 deg) (z down).
    assert_near_equal(mesh[1, 0, 2] - mesh[0, 0, 2], -math.sin(math.radians(4.0)), 1e-12)
    assert_near_equal(mesh[1, 3, 2] - mesh[0, 3, 2], -math.sin(math.radians(2.0)), 1e-12)
    assert_near_equal(mesh[1, 2, 2], 0.0, 1e-15)


def test_partials():
    values = {
        "span": 9.0,
        "root_chord": 1.5,
        "tip_chord": 0.6,
        "sweep": 0.3,
        "dihedral": -0.1,
        "incidence": 0.04,
        "twist": [0.0, -0.01, -0.03, -0.05],
        "root_leading_edge": [-2.0, 0.1, -0.5],
    }
    prob = make_problem(6, 2, "cosine", values)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_bad_inputs_and_options():
    with pytest.raises(ValueError, match="'num_span_panels' = 5 is out of range: must be even"):
        PlanformMeshComp(num_span_panels=5)
    prob = make_problem(4, 1)
    prob.set_val("span", -1.0)
    with pytest.raises(om.AnalysisError, match=r"span = -1.0; must be > 0 m"):
        prob.run_model()
    prob.set_val("span", 1.0)
    prob.set_val("sweep", 2.0)
    with pytest.raises(om.AnalysisError, match=r"sweep = 2.0; must be in \(-pi/2, pi/2\) rad"):
        prob.run_model()
