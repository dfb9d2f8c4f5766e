"""The 4- and 12-lift-rotor example vehicles trim every condition at their initial designs."""

from importlib import resources

import pytest

from lpc_mdo.analysis import analyze_vehicle
from lpc_mdo.vehicle import load_vehicle

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration


@pytest.mark.parametrize(
    ("n", "conditions"),
    [(4, 11), pytest.param(12, 17, marks=pytest.mark.slow)],  # 12 rotors: 45 s, the slow tier
)
def test_example_layout_trims_every_condition(n, conditions):
    vehicle = load_vehicle(resources.files("lpc_mdo") / "data" / f"lpc_{n}_lift_rotors.toml")
    analysis = analyze_vehicle(vehicle, processes=2)  # the CI machine has two cores
    assert len(vehicle.conditions) == conditions  # 12 rotors: 6 generated one-rotor-out cases
    assert analysis.failed == {}, analysis.failed
    prob = analysis.prob
    assert prob.get_val("lift_hub_position").shape == (n, 3)
    assert prob.get_val("rotor_radius").shape == (n // 2 + 1,)
