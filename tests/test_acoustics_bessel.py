"""Bessel functions of consecutive orders by Miller's algorithm: acoustics.common."""

import numpy as np
import pytest
from scipy.special import jv

from lpc_mdo.components.acoustics.common import bessel_j, bessel_j_range


@pytest.mark.parametrize("low, count", [(-12, 25), (0, 5), (8, 11), (30, 23), (40, 23)])
@pytest.mark.parametrize("largest", [15.0, 120.0])
def test_recurrence_matches_order_by_order_evaluation(low, count, largest):
    # Arguments from near the rotor axis (1e-8) through the loading noise's range (a few tens)
    # and beyond, orders around the harmonics m B of the rotors (both signs), against scipy's jv.
    x = np.concatenate([np.geomspace(1e-8, 1.0, 40), np.linspace(1.0, largest, 120)])
    table = bessel_j_range(low, count, x)
    direct = jv(low + np.arange(count), x[:, None])
    assert table.shape == (x.size, count)
    scale = np.max(np.abs(direct), axis=1, keepdims=True)
    significant = np.abs(direct) > 1e-200 * scale
    error = (
        np.abs(table - direct)[significant] / np.maximum(np.abs(direct), 1e-12 * scale)[significant]
    )
    assert error.max() < 1e-9


def test_orders_per_row_and_the_axis_fall_back():
    # A different lowest order per row (the harmonics of several rotors) and an argument on the
    # axis, where the table is J_n(0): 1 for n = 0, else 0.
    low = np.array([[-2], [4]])
    x = np.array([[0.0, 3.0, 7.5], [0.5, 0.0, 20.0]])
    table = bessel_j_range(low, 5, x)
    expected = jv(low[..., None] + np.arange(5), x[..., None])
    np.testing.assert_allclose(table, expected, rtol=1e-12, atol=1e-300)


def test_complex_step_gives_the_derivative():
    x = np.linspace(0.5, 30.0, 50)
    h = 1e-30
    table = bessel_j_range(3, 9, x + 1j * h)
    orders = 3 + np.arange(9)
    derivative = 0.5 * (bessel_j(orders - 1, x[:, None]) - bessel_j(orders + 1, x[:, None]))
    np.testing.assert_allclose(table.imag / h, derivative, rtol=1e-9, atol=1e-13)
