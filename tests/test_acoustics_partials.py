"""Analytic partials of every acoustics component against complex step (assert_check_partials).

Each component is run with generic (non-symmetric) inputs, with the options of the hover case
and of edgewise flight where they change the code path. Tolerance 1e-8 absolute and relative:
the analytic partials are exact, complex step is exact to round-off.
"""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.acoustics.a_weighting import AWeightingComp
from lpc_mdo.components.acoustics.broadband import GillLeeBroadbandComp
from lpc_mdo.components.acoustics.loads import HoverLoadDistributionComp, LoadFourierComp
from lpc_mdo.components.acoustics.observer import ObserverGeometryComp, ObserverPositionComp
from lpc_mdo.components.acoustics.thickness import BarryMagliozziThicknessComp
from lpc_mdo.components.acoustics.tonal import LowsonLoadingNoiseComp, SearsGustLoadsComp
from lpc_mdo.components.acoustics.total import TotalNoiseComp

NR, NRAD = 3, 5
RNG = np.random.default_rng(42)


def _check(comp, values, atol=1e-8, rtol=1e-8):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("comp", comp, promotes=["*"])
    prob.setup(force_alloc_complex=True)
    for name, val in values.items():
        prob.set_val(name, val)
    prob.run_model()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=atol, rtol=rtol)
    return prob


def _rotor_values():
    return {"radius": [1.5, 1.3, 1.4], "rpm": [1200.0, 1350.0, 1100.0]}


# At zero flight velocity the speed partials are exactly zero (smooth minimum of |V|).
@pytest.mark.filterwarnings("ignore::openmdao.utils.om_warnings.DerivativesWarning")
@pytest.mark.parametrize("velocity", [(0.0, 0.0, 0.0), (40.0, 3.0, -5.0)])
@pytest.mark.parametrize("rotation", [None, (1, -1, 1)])
def test_observer_geometry(velocity, rotation):
    _check(
        ObserverGeometryComp(num_rotors=NR, rotation_direction=rotation),
        {
            "hub_position": RNG.uniform(-6.0, 6.0, (NR, 3)),
            "thrust_direction": [[0.1, -0.05, -1.0], [0.0, 0.2, -0.9], [1.0, 0.1, -0.3]],
            "observer_position": [-60.0, 25.0, 70.0],
            "flight_velocity": velocity,
            "speed_of_sound": 338.0,
        },
    )


def test_observer_position():
    _check(
        ObserverPositionComp(num_rotors=NR),
        {
            "hub_position": RNG.uniform(-6.0, 6.0, (NR, 3)),
            "observer_distance": 90.0,
            "observer_elevation": 0.6,
            "observer_azimuth": 2.5,
        },
    )


def test_load_fourier():
    _check(
        LoadFourierComp(num_rotors=2, num_radial=4, num_azimuth=7),
        {
            "thrust_per_span": RNG.uniform(100.0, 900.0, (2, 4, 7)),
            "drag_per_span": RNG.uniform(10.0, 90.0, (2, 4, 7)),
        },
    )


def test_hover_load_distribution():
    _check(
        HoverLoadDistributionComp(num_rotors=NR, num_radial=NRAD, num_blades=(2, 3, 2)),
        {
            **_rotor_values(),
            "thrust": [4000.0, 3000.0, 3500.0],
            "torque": [700.0, 500.0, 600.0],
            "density": 1.2,
        },
    )


def test_sears_gust_loads():
    _check(
        SearsGustLoadsComp(num_rotors=NR, num_radial=NRAD, num_azimuth=3, num_gust_harmonics=4),
        {
            **_rotor_values(),
            "inflow_angle": RNG.uniform(0.05, 0.3, (NR, NRAD, 3)),
            "chord": RNG.uniform(0.05, 0.3, (NR, NRAD)),
            "density": 1.1,
        },
    )


def _lowson_values(num_load, num_gust, inplane_speed):
    vals = {
        **_rotor_values(),
        "speed_of_sound": 338.0,
        "axial_distance": [-50.0, 30.0, 0.5],
        "inplane_distance": [60.0, 70.0, 80.0],
        "convected_distance": [78.0, 75.0, 82.0],
        "observer_azimuth_cos": [0.6, -0.3, 0.1],
        "observer_azimuth_sin": [0.8, 0.95, -0.99],
        "inplane_speed": inplane_speed,
    }
    for load, scale in (("thrust", 1000.0), ("drag", 100.0)):
        for kind in ("cos", "sin"):
            vals[f"{load}_{kind}_coeff"] = scale * RNG.uniform(-1.0, 1.0, (NR, NRAD, num_load + 1))
            if num_gust:
                vals[f"{load}_gust_{kind}"] = (
                    0.1 * scale * RNG.uniform(-1.0, 1.0, (NR, NRAD, num_gust))
                )
    return vals


@pytest.mark.parametrize(
    "path, num_load, num_gust, speed",
    [
        ("auto", 0, 10, [0.0, 0.0, 0.0]),  # hover: Sears path
        ("auto", 2, 3, [0.09, 0.12, 30.0]),  # inside and beyond the path switch
        ("sears", 2, 3, [0.0, 0.0, 0.0]),
        ("unsteady", 3, 0, [20.0, 30.0, 40.0]),
    ],
)
def test_lowson_loading(path, num_load, num_gust, speed):
    _check(
        LowsonLoadingNoiseComp(
            num_rotors=NR,
            num_blades=(2, 3, 5),
            num_radial=NRAD,
            num_harmonics=3,
            num_load_harmonics=num_load,
            num_gust_harmonics=max(num_gust, 1),
            loading_path=path,
        ),
        _lowson_values(num_load, num_gust if path != "unsteady" else 0, speed),
    )


@pytest.mark.parametrize("axial_speed", [[0.0, 0.0, 0.0], [5.0, -10.0, 20.0]])
def test_barry_magliozzi(axial_speed):
    _check(
        BarryMagliozziThicknessComp(num_rotors=NR, num_blades=(2, 3, 2), num_radial=NRAD),
        {
            **_rotor_values(),
            "chord": RNG.uniform(0.1, 0.3, (NR, NRAD)),
            "thickness_to_chord": RNG.uniform(0.08, 0.15, (NR, NRAD)),
            "axial_distance": [-30.0, 20.0, 0.0],
            "inplane_distance": [40.0, 60.0, 50.0],
            "axial_speed": axial_speed,
            "density": 1.15,
            "speed_of_sound": 338.0,
        },
    )


@pytest.mark.parametrize("edgewise", [False, True])
def test_gill_lee(edgewise):
    _check(
        GillLeeBroadbandComp(
            num_rotors=NR, num_blades=(2, 3, 2), num_radial=NRAD, edgewise_correction=edgewise
        ),
        {
            **_rotor_values(),
            "thrust": [4000.0, 3000.0, 3500.0],
            "chord": RNG.uniform(0.1, 0.3, (NR, NRAD)),
            "distance": [80.0, 60.0, 100.0],
            "axial_distance": [-30.0, 20.0, -70.0],
            "axial_speed": [5.0, -10.0, 0.0],
            "inplane_speed": [7.0, 12.0, 9.5],
            "density": 1.15,
            "speed_of_sound": 338.0,
        },
    )


def test_a_weighting_comp():
    _check(
        AWeightingComp(shape=(NR, 3), names=["loading_spl", "thickness_spl"]),
        {
            "frequency": RNG.uniform(20.0, 400.0, (NR, 3)),
            "loading_spl": RNG.uniform(40.0, 80.0, (NR, 3)),
            "thickness_spl": RNG.uniform(40.0, 80.0, (NR, 3)),
        },
    )
    _check(
        AWeightingComp(
            shape=(NR, 4),
            names=["broadband_spl"],
            frequencies=np.array([100.0, 1000.0, 2000.0, 8000.0]),
        ),
        {"broadband_spl": RNG.uniform(40.0, 80.0, (NR, 4))},
    )


@pytest.mark.parametrize("weighting", ["A", "none"])
def test_total(weighting):
    sfx = "_a" if weighting == "A" else ""
    _check(
        TotalNoiseComp(num_rotors=NR, num_harmonics=3, num_bands=6, weighting=weighting),
        {
            f"loading_spl{sfx}": RNG.uniform(40.0, 80.0, (NR, 3)),
            f"thickness_spl{sfx}": RNG.uniform(20.0, 60.0, (NR, 3)),
            f"broadband_spl{sfx}": RNG.uniform(30.0, 75.0, (NR, 6)),
        },
    )
