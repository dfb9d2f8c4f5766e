import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.weights.power_electronics import (
    CABLE_MASS_PER_AMPERE_METRE,
    PowerElectronicsMassComp,
)


def _problem(current, motor_cg, station, **options):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "pe", PowerElectronicsMassComp(num_motors=len(current), **options), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("peak_current", current)
    prob.set_val("motor_cg", motor_cg)
    prob.set_val("inverter_station", station)
    prob.run_model()
    return prob


def test_cable_mass_per_ampere_metre_from_the_wire_table():
    # FAA AC 43.13-1B CHG 1 Table 11-9, AWG 0000: 210,900 circular mils = 106.87 mm^2 (1 cmil =
    # 5.067e-4 mm^2), 395 A at 200 deg C; copper 8890 kg/m^3: 8890 * 106.87e-6/395 =
    # 2.4053e-3 kg/(A m) (4 digits of the hand product: 1e-4).
    assert_near_equal(CABLE_MASS_PER_AMPERE_METRE, 2.4053e-3, 1e-4)


def test_inverter_and_cable_by_hand():
    # One motor at (-3, 4, -1) m, inverters at the origin, 400 A peak, 400 V, 19 kW/kg:
    # inverter (3/2)(400)(400)/19000 = 12.631579 kg; route 3 + 4 + 1 = 8 m; cable
    # 3 * 8 * 2.405e-3 * 400/sqrt(2) = 16.32566 kg; cable centroid (3 (-1.5, 0, 0) +
    # 4 (-3, 2, 0) + 1 (-3, 4, -0.5))/8 = (-2.4375, 1.5, -0.0625) m. Each smoothed leg is
    # longer by w^2/(2 |leg|) (w = 0.01): 8e-5 m in all, 1e-5 of the route: 2e-5 relative.
    prob = _problem(
        np.array([400.0]),
        np.array([[-3.0, 4.0, -1.0]]),
        np.zeros(3),
        voltage_limit=400.0,
        inverter_specific_power=19.0e3,
        cable_mass_per_ampere_metre=2.405e-3,
    )
    assert_near_equal(prob.get_val("inverter_mass"), [12.631579], 1e-6)
    assert_near_equal(prob.get_val("power_electronics_mass"), [12.631579], 1e-6)
    assert_near_equal(prob.get_val("power_cable_length"), [8.0], 2e-5)
    assert_near_equal(prob.get_val("power_cable_mass"), [16.32566], 2e-5)
    assert_near_equal(prob.get_val("power_cable_cg")[0], [-2.4375, 1.5, -0.0625], 2e-5)


def test_masses_scale_with_the_current_rating():
    # Both masses are linear in the current: twice the current, twice the mass (1e-14).
    cg = np.array([[-3.0, 4.0, -1.0], [-9.0, 0.0, -1.2]])
    one = _problem(np.array([200.0, 300.0]), cg, np.array([-0.25, 0.0, 0.06]))
    two = _problem(np.array([400.0, 600.0]), cg, np.array([-0.25, 0.0, 0.06]))
    for name in ("inverter_mass", "power_cable_mass", "power_electronics_mass"):
        assert_near_equal(two.get_val(name), 2.0 * one.get_val(name), 1e-14)


def test_partials():
    # Analytic partials against complex step: 1e-10. A motor on the plane of symmetry (the
    # pusher, y = 0) exercises the smoothed leg at zero.
    prob = _problem(
        np.array([250.0, 420.0, 380.0]),
        np.array([[-3.0, 4.0, -1.0], [-9.0, 0.0, -1.2], [-1.1, -2.0, -0.9]]),
        np.array([-0.25, 0.0, 0.06]),
    )
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_nonpositive_current_raises():
    with pytest.raises(om.AnalysisError, match=r"peak_current"):
        _problem(np.array([0.0]), np.zeros((1, 3)), np.ones(3))
