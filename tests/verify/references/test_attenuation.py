"""The float64 attenuation references: the window's shape, the inverse square it modulates, and
what the seed's quadratic falloff is next to physics."""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.verify.references.attenuation import (
    inverse_square,
    inverse_square_windowed,
    quadratic,
    range_window,
)


def test_window_is_one_at_the_light_and_zero_from_the_range_on() -> None:
    r = np.array([0.5, 3.0, 40.0])
    assert np.all(range_window(dist=0.0, range=r) == 1.0)
    assert np.all(range_window(dist=r, range=r) == 0.0)
    assert np.all(range_window(dist=2.0 * r, range=r) == 0.0)
    assert range_window(dist=0.0, range=0.0) == 0.0  # a light that reaches nothing


def test_window_meets_zero_with_zero_slope() -> None:
    # No visible rim where the light's influence ends: d/dq (1 − q⁴)² = −8q³(1 − q⁴) → 0 at q = 1.
    h = 1e-6
    slope = (range_window(dist=1.0, range=1.0) - range_window(dist=1.0 - h, range=1.0)) / h
    assert abs(slope) < 1e-4


def test_window_is_monotone_and_between_zero_and_one() -> None:
    q = np.linspace(0.0, 1.5, 10001)
    w = range_window(dist=q, range=1.0)
    assert np.all((w >= 0.0) & (w <= 1.0)) and np.all(np.diff(w) <= 0.0)


def test_windowed_form_tends_to_the_inverse_square_well_inside_the_range() -> None:
    # The window is 1 − 2q⁴ + q⁸: at a tenth of the range it costs 2e-4 of the light.
    d = np.linspace(0.1, 1.0, 50)
    ratio = inverse_square_windowed(dist=d, range=10.0) / inverse_square(dist=d)
    np.testing.assert_allclose(ratio, (1.0 - (d / 10.0) ** 4) ** 2, rtol=1e-12)
    assert ratio.min() == pytest.approx(1.0 - 2e-4, abs=1e-7)


def test_inverse_square_halves_twice_per_doubling() -> None:
    assert inverse_square(dist=4.0) / inverse_square(dist=2.0) == pytest.approx(0.25)
    assert np.isinf(inverse_square(dist=0.0))


def test_quadratic_is_one_at_the_light_and_a_hundred_times_the_inverse_square_far_away() -> None:
    assert quadratic(dist=0.0) == 1.0
    d = 1e6
    assert quadratic(dist=d) * d * d == pytest.approx(100.0, rel=1e-4)
    # Nowhere near physical at scene scale: at 10 units it keeps a third of the light, 1/d²
    # keeps a hundredth.
    assert quadratic(dist=10.0) == pytest.approx(1.0 / 3.0)
