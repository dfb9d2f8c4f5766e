"""The structural sizing study (paper Tables 4-5), one-way coupled."""

import numpy as np
import pytest

from lpc_mdo.studies import structural_sizing_problem
from lpc_mdo.vehicle import reference_vehicle

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration


def solve(aggregated):
    prob = structural_sizing_problem(aggregated=aggregated, optimizer="SLSQP")
    prob.driver.options["maxiter"] = 300
    prob.driver.options["tol"] = 1e-8
    prob.driver.options["disp"] = False
    result = prob.run_driver()
    return prob, result


@pytest.fixture(scope="module")
def both():
    return solve(False), solve(True)


def test_problem_sizes_match_table4(both):
    (full, _), (ks, _) = both
    # Paper Table 4: 34 design variables; 114 constraints (here 112: the clamped root node's
    # displacement is identically zero and is left out), or 8 aggregated.
    for prob in (full, ks):
        assert sum(m["size"] for m in prob.model.get_design_vars().values()) == 34
    assert sum(m["size"] for m in full.model.get_constraints().values()) == 112
    assert sum(m["size"] for m in ks.model.get_constraints().values()) == 8


def test_both_variants_converge_to_the_same_wing(both):
    (full, r_full), (ks, r_ks) = both
    assert r_full.success and r_ks.success
    m_full = full.get_val("wing_mass", units="kg")[0]
    m_ks = ks.get_val("wing_mass", units="kg")[0]
    # The KS aggregate is conservative by at most ln(n)/rho, so the aggregated wing is slightly
    # heavier (paper: the variants agree to 0.1 %; here within 3 %).
    assert m_full <= m_ks < 1.03 * m_full
    # Active set on the cranked NASA wing of the itemised reference (SLSQP): the +3g top-skin
    # buckling constraint in every bay (paper Table 5: active), the tip deflection at the
    # vehicle file's limit, the outer spar webs at the 0.508 mm minimum gauge with the root webs
    # at the stress limit; the -1g bottom-skin buckling (the tip deflection sizes the bottom
    # skin inboard) below its limit. Paper
    # Table 5 (taper-0.2 trapezoid, 2.12 m root chord) has the -1g buckling active. How far it
    # reaches inboard goes with the weight: the outer three bays at 3265 kg, the outermost at
    # 3556 kg and at the 3621 kg of the initial design sized to its mission, none at the paper's
    # 3723.99 kg (peak 0.98) nor at 3911 kg.
    values = full.driver.get_constraint_values(driver_scaling=False)
    assert np.allclose(values["plus_3g.top_skin_buckling_ratio"], 1.0, atol=1e-4)
    stress = values["plus_3g.stress_ratio"].max()
    assert 0.98 < stress <= 1.0 + 1e-4
    # The two root webs carry the stress at the 3621 kg initial design (the second 0.525 mm;
    # at 3556 kg only the root one did), the outer ones sit at the minimum gauge.
    webs = [full.get_val(f"{s}_spar_thickness", units="m")[2:] for s in ("front", "rear")]
    assert np.all(np.concatenate(webs) <= reference_vehicle().material.min_gauge * (1 + 1e-6))
    limit = reference_vehicle().constraints.max_displacement
    assert np.isclose(values["plus_3g.displacements"][-1], -limit, rtol=1e-4)
    # At the 3621 kg initial design of the wider blades (trims at least power) the outermost
    # -1g bay is active, as at 3556 kg, the others below 0.9 (at 3911 kg none was: peak 0.82).
    bottom = values["minus_1g.bottom_skin_buckling_ratio"]
    assert bottom[-1] == pytest.approx(1.0, abs=1e-4) and bottom[:-1].max() < 0.9
