"""lpc_mdo.core.checks: one message form for every range, type, choice and shape check."""

import pickle

import numpy as np
import openmdao.api as om
import pytest

from lpc_mdo.core.checks import (
    RangeCheck,
    check_choice,
    check_finite,
    check_integer,
    check_number,
    check_range,
    check_shape,
    cut_text,
    range_text,
    units_suffix,
)


def _message(func, *args, **kwargs):
    with pytest.raises(Exception) as err:
        func(*args, **kwargs)
    return err.type, str(err.value)


@pytest.mark.parametrize(
    "kwargs, text",
    [
        (dict(lower=0, lower_open=True), "> 0"),
        (dict(lower=2), ">= 2"),
        (dict(upper=1, upper_open=True), "< 1"),
        (dict(upper=1), "<= 1"),
        (dict(lower=0, upper=1, upper_open=True), "in [0, 1)"),
        (dict(lower=0, upper=1, lower_open=True), "in (0, 1]"),
        (dict(lower=1e-7, upper=0.5), "in [1e-07, 0.5]"),
        ({}, ""),
    ],
)
def test_range_text(kwargs, text):
    assert range_text(**kwargs) == text


def test_units_suffix():
    assert units_suffix("m**2") == " (m**2)"
    assert units_suffix(None) == units_suffix("") == ""


def test_scalar_message_forms():
    assert _message(check_range, "num_radial", 1, lower=2) == (
        ValueError,
        "'num_radial' = 1 is out of range: must be >= 2",
    )
    assert _message(check_range, "wing.area", -3.0, lower=0, lower_open=True, units="m**2") == (
        ValueError,
        "'wing.area' = -3.0 is out of range: must be > 0 (m**2)",
    )
    assert _message(check_range, "x", np.float64(2.0), upper=1)[1] == (
        "'x' = 2.0 is out of range: must be <= 1"
    )


@pytest.mark.parametrize(
    "func, args, kwargs, expected",
    [
        # The messages lpc_mdo.vehicle gives for the same faults (_number, _integer, _string).
        (
            check_number,
            ("wing.area", -3),
            dict(lower=0.0, lower_open=True, units="m**2"),
            "'wing.area' = -3 is out of range: must be > 0 (m**2)",
        ),
        (
            check_number,
            ("wing.area", float("nan")),
            dict(lower=0.0, lower_open=True),
            "'wing.area' = nan is out of range: must be a finite number",
        ),
        (check_number, ("wing.area", "3"), {}, "'wing.area' must be a number, got str '3'"),
        (check_integer, ("num_blades", 2.5), {}, "'num_blades' must be an integer, got float 2.5"),
        (
            check_integer,
            ("num_radial", 1),
            dict(lower=2),
            "'num_radial' = 1 is out of range: must be >= 2",
        ),
        (
            check_choice,
            ("num_blades", 3, (2, 4, 5)),
            {},
            "'num_blades' = 3 is not allowed: must be one of 2, 4, 5",
        ),
        (
            check_choice,
            ("airfoil", "x", ("a", "b")),
            {},
            "'airfoil' = 'x' is not allowed: must be one of 'a', 'b'",
        ),
    ],
)
def test_messages_match_the_vehicle_file_form(func, args, kwargs, expected):
    from lpc_mdo.vehicle import VehicleSpecError

    assert _message(func, *args, error=VehicleSpecError, **kwargs) == (VehicleSpecError, expected)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_nan_and_inf_never_pass(bad):
    assert _message(check_range, "speed", bad)[1] == (
        f"'speed' = {bad!r} is out of range: must be a finite number"
    )
    assert "finite" in _message(check_range, "speed", bad, lower=0.0)[1]
    assert "finite" in _message(check_finite, "speed", [1.0, bad])[1]


def test_array_names_first_offending_entry_and_index():
    chord = np.array([[0.1, 0.2, 0.3], [0.1, -0.2, -0.4]])
    assert _message(check_range, "chord", chord, lower=0, lower_open=True, units="m")[1] == (
        "'chord[1, 1]' = -0.2 is out of range: must be > 0 (m)"
    )
    assert _message(check_range, "rpm", [100.0, np.nan, -1.0], lower=0)[1] == (
        "'rpm[1]' = nan is out of range: must be a finite number"
    )


def test_passing_values_are_returned():
    assert check_range("n", 3, lower=2) == 3
    arr = check_range("x", [0.0, 0.5], lower=0, upper=1)
    assert isinstance(arr, np.ndarray) and arr.tolist() == [0.0, 0.5]
    assert check_number("x", np.float64(0.5), lower=0) == 0.5
    assert check_integer("n", 4.0, lower=1) == 4
    assert check_choice("q", "gauss", ("gauss", "midpoint")) == "gauss"


def test_complex_step_values_are_checked_by_real_part():
    check_range("x", np.array([1.0 + 1e-40j]), lower=0.0)
    assert _message(check_range, "x", np.array([-1.0 + 1e-40j]), lower=0.0)[1] == (
        "'x[0]' = -1.0 is out of range: must be >= 0"
    )


def test_where_prefix_error_class_and_allowed_text():
    kind, text = _message(
        check_range, "thrust", -1.0, lower=0, units="N", error=om.AnalysisError, where="Comp: rotor"
    )
    assert kind is om.AnalysisError
    assert text == "Comp: rotor: 'thrust' = -1.0 is out of range: must be >= 0 (N)"
    assert _message(check_range, "n", 3, upper=2, allowed="even and <= 2")[1] == (
        "'n' = 3 is out of range: must be even and <= 2"
    )


def test_type_choice_and_shape_messages():
    assert _message(check_integer, "num_blades", 2.5)[1] == (
        "'num_blades' must be an integer, got float 2.5"
    )
    assert _message(check_integer, "num_blades", True)[1] == (
        "'num_blades' must be an integer, got bool True"
    )
    assert _message(check_integer, "num_radial", 1, lower=2)[1] == (
        "'num_radial' = 1 is out of range: must be >= 2"
    )
    assert _message(check_number, "rho", "fifty")[1] == ("'rho' must be a number, got str 'fifty'")
    assert _message(check_range, "rho", "fifty")[1] == (
        "'rho' must be a number or an array of numbers, got str 'fifty'"
    )
    assert _message(check_choice, "quadrature", "simpson", ("gauss", "midpoint"))[1] == (
        "'quadrature' = 'simpson' is not allowed: must be one of 'gauss', 'midpoint'"
    )
    assert _message(check_shape, "thrust_axis", np.zeros(3), (8, 3))[1] == (
        "'thrust_axis' must have shape (8, 3), got shape (3,)"
    )
    assert _message(check_shape, "nodes", np.zeros(3), (None, 3))[1] == (
        "'nodes' must have shape (n, 3), got shape (3,)"
    )
    assert check_shape("nodes", np.zeros((4, 3)), (None, 3)).shape == (4, 3)


def test_long_text_is_cut_with_its_length():
    assert cut_text("gauss") == "'gauss'"
    assert cut_text("a\nb") == "'a\\nb'"  # one line
    assert cut_text("x" * 5000, 200) == repr("x" * 200) + "... (5000 characters)"
    message = _message(check_choice, "quadrature", "s" * 10**6, ("gauss", "midpoint"))[1]
    assert message.endswith(
        "... (1000000 characters) is not allowed: must be one of 'gauss', 'midpoint'"
    )
    assert len(message) < 200


def test_range_check_as_openmdao_check_valid():
    class Comp(om.ExplicitComponent):
        def initialize(self):
            self.options.declare(
                "rho", default=50.0, check_valid=RangeCheck(lower=0, lower_open=True)
            )
            self.options.declare("num", default=2, check_valid=RangeCheck(lower=1, integer=True))
            self.options.declare(
                "ratio", default=None, allow_none=True, check_valid=RangeCheck(lower=0, upper=1)
            )

    comp = Comp()
    with pytest.raises(ValueError, match=r"^'rho' = -1 is out of range: must be > 0$"):
        comp.options["rho"] = -1
    with pytest.raises(ValueError, match=r"'num' must be an integer, got float 1.5"):
        comp.options["num"] = 1.5
    comp.options["ratio"] = None
    comp.options["ratio"] = 0.5
    pickle.loads(pickle.dumps(comp.options["rho"]))
    pickle.dumps(RangeCheck(lower=0))


def test_array_bounds_show_the_bound_of_the_offending_entry():
    radius = np.array([1.5, 2.0])
    station = np.array([[0.5, 1.4], [0.5, 2.1]])
    assert _message(
        check_range,
        "station_radius",
        station,
        lower=0.3,
        upper=radius[:, None],
        lower_open=True,
        upper_open=True,
        units="m",
    )[1] == ("'station_radius[1, 1]' = 2.1 is out of range: must be in (0.3, 2) (m)")
    check_range("station_radius", station[:1], upper=radius[:1, None], upper_open=True)
