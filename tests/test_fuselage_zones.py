"""The fuselage length acts as a tail arm: a stretch of the tail cone moves the neutral point aft.

docs theory/geometry 'Fuselage zones' and theory/dynamics 'Neutral point and static margin'.
"""

import numpy as np
import pytest

from lpc_mdo.problems import build_analysis_problem

LENGTHS = (6.4008, 7.5, 9.144, 10.66)  # m: the lower bound and the paper's Table 8 lengths


@pytest.fixture(scope="module")
def cruise_at_lengths(tmp_path_factory):
    """Cruise at the reference design for each fuselage length: x_np, x_cg, MAC, tail share."""
    prob = build_analysis_problem(
        None, conditions=["cruise"], work_dir=str(tmp_path_factory.mktemp("zones"))
    )
    c = "cruise"
    rows = []
    for length in LENGTHS:
        prob.set_val("fuselage_length", length, units="m")
        prob.run_model()
        delta = prob.model._get_subsystem(f"{c}.stability_derivatives").options["delta"]
        wing_panels = prob.get_val(f"{c}.wing_sectional_cl").shape[-1]
        forces = []
        for vlm in ("vlm", "vlm_perturbed"):
            f = prob.get_val(f"{c}.{vlm}.panel_forces", units="N")[0]
            f = f + prob.get_val(f"{c}.{vlm}.viscous_panel_forces", units="N")[0]
            forces.append(f[wing_panels:, 2].sum())
        correction = (
            prob.get_val(f"{c}.perturbed_tail_force_correction", units="N")[0, 2]
            - prob.get_val(f"{c}.tail_force_correction", units="N")[0, 2]
        )
        tail_slope = (forces[1] - forces[0] + correction) / delta
        rows.append(
            {
                "x_np": prob.get_val(f"{c}.neutral_point", units="m")[0],
                "x_cg": prob.get_val(f"{c}.static_margin.cg_x", units="m")[0],
                "mac": prob.get_val(f"{c}.static_margin.mean_aerodynamic_chord", units="m")[0],
                "share": tail_slope / prob.get_val(f"{c}.normal_force_slope", units="N/rad")[0],
            }
        )
    prob.cleanup()
    return rows


def test_neutral_point_moves_aft_by_the_tail_share_per_metre_of_stretch(cruise_at_lengths):
    # A tail-cone stretch moves the horizontal tail aft by the change of length, and the neutral
    # point x_np = sum_i x_i dF_i/dalpha / sum_i dF_i/dalpha (Raymer, Aircraft Design, 6th ed.,
    # sec. 16.3) by the tail's share of the lift slope per metre; the fuselage's Munk couple
    # and the tail's downwash change little with it. So x_np moves aft monotonically, between
    # consecutive lengths by the mean tail share (0.07-0.09 here) within 0.01 m per metre.
    rows = cruise_at_lengths
    for a, b, la, lb in zip(rows, rows[1:], LENGTHS, LENGTHS[1:], strict=False):
        aft_per_metre = (a["x_np"] - b["x_np"]) / (lb - la)
        share = 0.5 * (a["share"] + b["share"])
        assert 0.05 < share < 0.12
        assert aft_per_metre > 0.0
        assert abs(aft_per_metre - share) < 0.01, (la, lb, aft_per_metre, share)


def test_static_margin_rises_with_the_tail_arm_at_a_fixed_cg(cruise_at_lengths):
    # At the cg of the reference length, the margin (x_cg - x_np)/MAC rises strictly with the
    # fuselage length, as a tail arm's does (paper Sec. V.B). The vehicle's own margin also
    # pays for the cg moving aft with the stretch (the fuselage structure, the empennage and
    # the pusher on the tail end: docs theory/dynamics 'Neutral point and static margin').
    rows = cruise_at_lengths
    reference = rows[LENGTHS.index(9.144)]
    margins = [(reference["x_cg"] - r["x_np"]) / r["mac"] for r in rows]
    assert np.all(np.diff(margins) > 0.0), margins
    cg = [r["x_cg"] for r in rows]
    assert np.all(np.diff(cg) < 0.0), cg  # the cg moves aft too
