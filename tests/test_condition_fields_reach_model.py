"""Vehicle-file fields reach the OpenMDAO model (and are not left at component defaults).

Each test changes one field of the reference vehicle (``dataclasses.replace``, which skips the
file validation) or of its TOML dict, builds the smallest LPCGroup that uses it, runs it, and
checks (a) that the model input holds the vehicle's value and (b) that an output that depends on
it moves as the physics says. Fields the model cannot honour are rejected with a VehicleSpecError
naming the field.
"""

import dataclasses
import re

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.components.aero.polar import LinearQuadraticPolar
from lpc_mdo.components.dynamics.eom import GRAVITY
from lpc_mdo.groups.lpc import LPCGroup
from lpc_mdo.vehicle import (
    AIRFOILS,
    VehicleSpecError,
    read_vehicle_file,
    reference_vehicle,
    vehicle_from_dict,
)

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration

REF = reference_vehicle()


def run(vehicle, conditions, **options):
    """Set up and run an LPCGroup of ``vehicle`` with only ``conditions``."""
    prob = om.Problem(LPCGroup(vehicle=vehicle, conditions=conditions, **options), reports=False)
    prob.setup()
    prob.run_model()
    return prob


def with_condition(vehicle, name, **changes):
    conditions = tuple(
        dataclasses.replace(c, **changes) if c.name == name else c for c in vehicle.conditions
    )
    return dataclasses.replace(vehicle, conditions=conditions)


def with_lift_airfoil(vehicle, airfoil, pairs=(0, 1, 2, 3), thickness_to_chord=None):
    """Return the vehicle with another lift-rotor airfoil (and its t/c, as the loader sets it)."""
    if thickness_to_chord is None:
        thickness_to_chord = AIRFOILS[airfoil].thickness_to_chord
    rotors = tuple(
        dataclasses.replace(r, airfoil=airfoil, thickness_to_chord=thickness_to_chord)
        if r.pair in pairs
        else r
        for r in vehicle.lift_rotors
    )
    return dataclasses.replace(vehicle, lift_rotors=rotors)


# ------------------------------------------------------------------ 1. material density


def test_material_density_reaches_the_structural_beam():
    # Source: [material] density (2700 kg/m^3 aluminium) -> plus_3g.material_density -> the
    # beam's BeamMassComp.density; before the fix it stayed at the component default 2700.
    light = dataclasses.replace(REF, material=dataclasses.replace(REF.material, density=1350.0))
    base, half = run(REF, ["plus_3g"]), run(light, ["plus_3g"])
    assert_near_equal(half.get_val("plus_3g.material_density", units="kg/m**3"), 1350.0, 1e-15)
    assert_near_equal(half.get_val("plus_3g.beam.mass.density", units="kg/m**3"), 1350.0, 1e-15)
    # The box geometry does not depend on the density, so the beam mass halves exactly.
    m_base = base.get_val("plus_3g.beam.beam_mass", units="kg")[0]
    m_half = half.get_val("plus_3g.beam.beam_mass", units="kg")[0]
    assert_near_equal(m_half, 0.5 * m_base, 1e-12)
    # Own-weight load: the nodal z forces are the aero forces (unchanged: same pitch, speed and
    # mesh) plus m n g cos(theta) (z down; LoadTransferComp). Lower density -> a smaller
    # downward own-weight load, by exactly the mass difference at 3 g.
    theta = base.get_val("plus_3g.pitch", units="rad")[0]
    fz_base = base.get_val("plus_3g.beam.node_forces", units="N")[:, 2].sum()
    fz_half = half.get_val("plus_3g.beam.node_forces", units="N")[:, 2].sum()
    expected = (m_base - m_half) * 3.0 * GRAVITY * np.cos(theta)
    assert expected > 0.0
    assert_near_equal(fz_base - fz_half, expected, 1e-9)


# ------------------------------------------------------------------ 2. noise observer


def _observer(distance=None, elevation=None):
    (obs,) = REF.noise_observer
    obs = dataclasses.replace(
        obs,
        distance=obs.distance if distance is None else distance,
        elevation=obs.elevation if elevation is None else elevation,
    )
    return dataclasses.replace(REF, noise_observer=(obs,))


def test_observer_distance_reaches_the_noise_model():
    # Source: [noise_observer] distance (100 m) -> hover.observer_distance (was the component
    # default 100 m whatever the file said). Farther observer -> lower total A-weighted SPL.
    near, far = run(_observer(distance=100.0), ["hover"]), run(_observer(distance=200.0), ["hover"])
    assert_near_equal(far.get_val("hover.observer_distance", units="m"), 200.0, 1e-15)
    assert_near_equal(far.get_val("hover.noise.observer_distance", units="m"), 200.0, 1e-15)
    assert far.get_val("hover.total_spl_a")[0] < near.get_val("hover.total_spl_a")[0] - 6.0
    # Geometry closed form: the observer sits 200 m from the hub centroid.
    centroid = far.get_val("hover.lift_hub_position", units="m").mean(axis=0)
    observer = far.get_val("hover.noise.observer_position", units="m")
    assert_near_equal(np.linalg.norm(observer - centroid), 200.0, 1e-12)


def test_observer_elevation_reaches_the_noise_model():
    # Source: [noise_observer] elevation_deg (45 deg below the rotor plane) -> hover.
    # observer_elevation (was the component default 45 deg). Closed form of ObserverPositionComp:
    # the observer is d sin(e) below the hub centroid (z down).
    elevation = np.radians(30.0)
    prob = run(_observer(elevation=elevation), ["hover"])
    assert_near_equal(prob.get_val("hover.observer_elevation", units="rad"), elevation, 1e-15)
    centroid = prob.get_val("hover.lift_hub_position", units="m").mean(axis=0)
    observer = prob.get_val("hover.noise.observer_position", units="m")
    d = REF.noise_observer[0].distance
    assert_near_equal(observer[2] - centroid[2], d * np.sin(elevation), 1e-12)
    # A shallower observer (30 deg instead of 45 deg) is farther from the rotor axes.
    base = run(REF, ["hover"])
    assert np.all(
        prob.get_val("hover.noise.inplane_distance") > base.get_val("hover.noise.inplane_distance")
    )


# ------------------------------------------------------------------ 3. battery initial SoC


def test_initial_soc_reaches_the_battery():
    # Source: [battery] initial_soc (1.0) -> battery.initial_soc; BatteryComp: SoC_final =
    # initial_soc - E_used / E_total (was 1 - E_used / E_total). Same mission energy, so a 0.9
    # start ends exactly 0.1 lower.
    low = dataclasses.replace(REF, battery=dataclasses.replace(REF.battery, initial_soc=0.9))
    base, prob = run(REF, ["hover"]), run(low, ["hover"])
    assert_near_equal(prob.get_val("battery.initial_soc"), 0.9, 1e-15)
    assert_near_equal(prob.get_val("energy_used"), base.get_val("energy_used"), 1e-15)
    assert_near_equal(
        base.get_val("state_of_charge")[0] - prob.get_val("state_of_charge")[0], 0.1, 1e-12
    )


# ------------------------------------------------------------------ 4. hover / OEI pitch


@pytest.mark.parametrize(
    "index, key, kind",
    [(0, "conditions[0]", "hover"), (9, "conditions[9] (generated oei_1)", "oei")],
)
def test_nonzero_hover_pitch_is_rejected_by_the_file_validation(index, key, kind):
    # The hover model holds the body level (body-fixed thrust axes, u_dot not a hover trim
    # constraint), so conditions[i].pitch_deg must be 0 in hover and OEI (the file's one 'oei'
    # table generates oei_1..4; the message names the table and the first generated case).
    data = read_vehicle_file()
    data["conditions"][index]["pitch_deg"] = 3.0
    with pytest.raises(
        VehicleSpecError,
        match=re.escape(f"'{key}.pitch_deg' = 3 deg is not allowed: must be 0 in '{kind}'"),
    ):
        vehicle_from_dict(data)


def test_nonzero_hover_pitch_is_rejected_by_the_model():
    # dataclasses.replace skips the file validation; the hover group checks again.
    vehicle = with_condition(REF, "hover", pitch=np.radians(3.0))
    prob = om.Problem(LPCGroup(vehicle=vehicle, conditions=["hover"]), reports=False)
    with pytest.raises(VehicleSpecError, match=r"'conditions\[0\]\.pitch_deg' = 3 deg"):
        prob.setup()


def test_hover_pitch_reaches_the_model():
    # The (zero) pitch of the file is the hover group's pitch.
    prob = run(REF, ["hover"])
    assert prob.get_val("hover.pitch", units="rad")[0] == REF.condition("hover").pitch == 0.0


# ------------------------------------------------------------------ 5. rotor airfoils


def _group_polars(vehicle, conditions, **options):
    prob = om.Problem(LPCGroup(vehicle=vehicle, conditions=conditions, **options), reports=False)
    prob.setup()
    return prob


def test_pusher_uses_its_own_airfoil_and_lift_rotors_theirs():
    # Source: pusher.airfoil and lift_rotors[i].airfoil -> the BEM/Pitt-Peters polar options.
    # Before the fix every rotor took the polar of lift_rotors[0].airfoil.
    vehicle = dataclasses.replace(REF, pusher=dataclasses.replace(REF.pusher, airfoil="naca0015"))
    prob = _group_polars(vehicle, ["transition_1"])
    assert prob.model.transition_1.pusher.options["polar"] is get_polar("naca0015")
    assert prob.model.transition_1.lift_rotors.options["polar"] is get_polar("naca0012")
    # And the other way round: lift rotors of another section leave the pusher's alone.
    prob = _group_polars(with_lift_airfoil(REF, "naca0015"), ["transition_1"])
    assert prob.model.transition_1.pusher.options["polar"] is get_polar("naca0012")
    assert prob.model.transition_1.lift_rotors.options["polar"] is get_polar("naca0015")
    # An explicit rotor_polar still serves every rotor.
    polar = LinearQuadraticPolar()
    prob = _group_polars(vehicle, ["transition_1"], rotor_polar=polar, wing_zero_lift_angle=-0.07)
    assert prob.model.transition_1.pusher.options["polar"] is polar
    assert prob.model.transition_1.lift_rotors.options["polar"] is polar


def test_pusher_airfoil_moves_the_pusher_and_not_the_lift_rotors(tmp_path):
    # A pusher section with 3x the drag of the same lift curve (a user polar file) -> lower
    # cruise pusher efficiency at the same rpm; the hover lift rotors do not change.
    alpha = np.linspace(-20.0, 20.0, 81)
    values = get_polar("naca0012").evaluate(np.radians(alpha), 2e6, 0.3)
    for name, factor in (("plain", 1.0), ("draggy", 3.0)):
        np.savetxt(
            tmp_path / f"{name}.dat",
            np.column_stack([alpha, np.ravel(values.cl), factor * np.ravel(values.cd)]),
        )
    results = {}
    for name in ("plain", "draggy"):
        vehicle = dataclasses.replace(
            REF, pusher=dataclasses.replace(REF.pusher, airfoil=str(tmp_path / f"{name}.dat"))
        )
        results[name] = run(vehicle, ["hover", "cruise"])
    plain, draggy = results["plain"], results["draggy"]
    assert (
        draggy.get_val("cruise.pusher_efficiency")[0, 0]
        < plain.get_val("cruise.pusher_efficiency")[0, 0] - 0.01
    )
    assert_near_equal(
        draggy.get_val("hover.lift_thrust"), plain.get_val("hover.lift_thrust"), 1e-14
    )


def test_lift_rotors_with_different_airfoils_are_rejected():
    # One polar serves all eight lift rotors (one rotor-model call per condition): a pair with
    # another section is a VehicleSpecError naming the first rotor that differs.
    vehicle = with_lift_airfoil(REF, "naca0015", pairs=(1,))
    prob = om.Problem(LPCGroup(vehicle=vehicle, conditions=["hover"]), reports=False)
    with pytest.raises(
        VehicleSpecError,
        match=r"'lift_rotors\[1\]\.airfoil' = 'naca0015' differs from "
        r"'lift_rotors\[0\]\.airfoil' = 'naca0012'; allowed: one airfoil",
    ):
        prob.setup()


# ------------------------------------------------------------------ 6. blade thickness (noise)


def test_lift_rotor_thickness_to_chord_reaches_the_thickness_noise():
    # Source: lift_rotors[i].airfoil -> AIRFOILS[...].thickness_to_chord -> hover.
    # lift_thickness_to_chord (was the component default 0.12 for any section). The same polar
    # for both runs keeps the loads equal, so only t/c changes: the Barry-Magliozzi pressure is
    # linear in t/c, so every thickness harmonic rises by 20 log10(0.15/0.12) dB.
    polar = LinearQuadraticPolar()
    base = run(REF, ["hover"], rotor_polar=polar)
    thick = run(with_lift_airfoil(REF, "naca0015"), ["hover"], rotor_polar=polar)
    np.testing.assert_array_equal(base.get_val("hover.lift_thickness_to_chord"), 0.12)
    np.testing.assert_array_equal(thick.get_val("hover.lift_thickness_to_chord"), 0.15)
    np.testing.assert_array_equal(thick.get_val("hover.noise.thickness_to_chord"), 0.15)
    rise = thick.get_val("hover.noise.thickness_spl") - base.get_val("hover.noise.thickness_spl")
    np.testing.assert_allclose(rise, 20.0 * np.log10(0.15 / 0.12), rtol=1e-9)
    assert thick.get_val("hover.total_spl")[0] > base.get_val("hover.total_spl")[0]


def test_polar_file_rotor_thickness_key_reaches_the_thickness_noise(tmp_path):
    # A polar file has no thickness: the file's lift_rotors[i].thickness_to_chord gives it.
    path = tmp_path / "blade.dat"
    alpha = np.linspace(-10.0, 12.0, 23)
    np.savetxt(path, np.column_stack([alpha, 0.1 * alpha, 0.01 + 1e-4 * alpha**2]))
    data = read_vehicle_file()
    for rotor in data["lift_rotors"]:
        rotor.update(airfoil=str(path), thickness_to_chord=0.09)
    prob = om.Problem(
        LPCGroup(
            vehicle=vehicle_from_dict(data),
            conditions=["hover"],
            rotor_polar=LinearQuadraticPolar(),
            wing_zero_lift_angle=-0.07,
        ),
        reports=False,
    )
    prob.setup()
    prob.final_setup()
    np.testing.assert_array_equal(prob.get_val("hover.lift_thickness_to_chord"), 0.09)
