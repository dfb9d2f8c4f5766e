"""The design review of a final design: each buildability limit at its worst point."""

import pytest

from lpc_mdo.post.design_review import ReviewItem, design_review, design_review_table


def test_review_item_margin_and_status():
    # A lower limit is met from above, an upper one from below; the status allows the
    # optimizers' 1e-3 of the limit's scale (at least 1).
    assert ReviewItem("a", 0.12, 0.1, ">=", "x").margin == pytest.approx(0.02)
    assert ReviewItem("b", 0.75, 0.7, "<=", "x").margin == pytest.approx(-0.05)
    assert ReviewItem("c", 0.6995, 0.7, ">=", "x").ok
    assert not ReviewItem("d", 0.698, 0.7, ">=", "x").ok


def check_trimmed_initial_design(case_file):
    """
    Check the design review of the trimmed initial design (``lpc-mdo analyze``'s case file).

    Called by the analyze test of tests/test_cli.py, which writes that case file, so that the
    model is trimmed once for both.
    """
    items = {item.check: item for item in design_review(case_file)}
    # The initial design's motors are sized to the mission (run_scripts/close_initial_design.py):
    # the worst lift motor sits on its torque margin with a rotor out, within the voltage limit,
    # and the control reserve holds. (The paper's TC2 lift motors ran beyond their peak torque
    # there: tests/test_motor_sizing_to_margins.py.)
    torque = items["lift motors: torque margin T_max/T - 1"]
    assert torque.ok and torque.value == pytest.approx(0.1, abs=2e-3)
    assert torque.where.startswith("oei_")
    assert items["lift motors: voltage margin 1 - |U|/V_lim"].ok
    assert items["control reserve / required acceleration"].ok
    # The layout is the NASA CAD's (docs theory/geometry 'Rotor clearances'): the rear in-row
    # disks 0.068 m apart, the front-inner disk 0.202 m from the fuselage, the rear-inner one
    # 1.30 m ahead of the tail and 2.88 m from the pusher disk.
    assert items["clearance: lift disk to lift disk"].value == pytest.approx(0.0678, abs=5e-4)
    assert items["clearance: lift disk to fuselage"].value == pytest.approx(0.202, abs=5e-4)
    assert items["clearance: lift disk to horizontal tail"].value == pytest.approx(1.30, abs=5e-3)
    assert items["clearance: lift disk to pusher disk"].value == pytest.approx(2.878, abs=5e-3)
    # Systems, battery and gear at NASA's stations, outside the cabin; the gauges at the
    # 0.508 mm minimum the initial design was closed with.
    assert items["systems, battery and gear inside the cabin (count)"].value == 0.0
    assert items["wing-box gauge"].value == pytest.approx(0.508e-3, rel=1e-9)
    assert items["wing-box gauge"].ok
    # The reference wing is within its stall limits: at the 3621 kg initial design the largest
    # ratio is 0.50 in cruise against 0.625, 0.55 at +3g against 0.9 (at the 3911 kg one it was
    # 0.58 in transition point 2, docs theory/aerodynamics 'Section lift limit').
    assert items["wing section c_l/c_l,max (KS), 1-g conditions"].where == "cruise"
    assert 0.48 < items["wing section c_l/c_l,max (KS), 1-g conditions"].value < 0.53
    assert items["wing section c_l/c_l,max (KS), +3g/-1g"].ok
    # The table names each violation.
    status = {row[0]: row[-1] for row in design_review_table(case_file).rows}
    # The least-power hover trim keeps every pair within the 0.6 tip-Mach limit (0.59); with a
    # rotor out the tips reach helical Mach 0.72, beyond the NACA 0012's compressibility stall:
    # the tip-Mach and blade stall limits are violated there, for the optimizer.
    assert status["hover tip Mach (per pair)"] == "ok"
    assert status["lift rotors' helical tip Mach, OEI and transition"] == "VIOLATED"
    blade = items["blade alpha/alpha_stall (KS), lift rotors in hover and one-rotor-out hover"]
    assert not blade.ok and blade.where.startswith("oei_")
    assert status["clearance: lift disk to lift disk"] == "ok"
