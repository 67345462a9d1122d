"""The bare slab against exact and published plate frequencies.

* Rectangular plates simply supported on two opposite edges and free on the others: the
  exact Levy solution (Leissa, *Vibration of Plates*, NASA SP-160, 1969, section 4.3),
  computed here from its characteristic equation, independently of the library; and
  Leissa's printed values for the square plate, nu = 0.3: lambda = omega a^2 sqrt(rho h / D)
  = 9.631, 16.135, 36.726, 38.945, 46.738, 70.740.
* Skewed (rhombic) plates simply supported on all four edges, nu = 0.3: lambda = 20.87
  (15 degrees) and 24.96 (30 degrees), the values tabulated by Liew and Lam (1990,
  J. Sound Vib. 139(2), 241-252) and, before them, Conway and Farnham (1965); this case
  tests the oblique coordinates on their own (``sides="simply supported"``).
* Skewed plates simply supported on their skew edges and free on the others (the deck's own
  case): the independent plate finite-element model of ``deck_fe.py``.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from deck_fe import PlateFE, grid
from scipy.optimize import brentq

from vbi_lib.decks import Deck

E, NU, RHO, H = 30e9, 0.3, 2400.0, 0.2
D = E * H**3 / (12 * (1 - NU**2))

LEISSA_SQUARE = [9.631, 16.135, 36.726, 38.945, 46.738, 70.740]


def levy_determinant(k: float, alpha: float, half: float, nu: float, symmetric: bool) -> float:
    """Free-edge conditions at y = half of sin(alpha x) Y(y), ``k^4 = rho h omega^2 / D``.

    Y'''' - 2 alpha^2 Y'' + (alpha^4 - k^4) Y = 0; free edge: Y'' - nu alpha^2 Y = 0 (moment)
    and Y''' - (2 - nu) alpha^2 Y' = 0 (Kirchhoff shear).  Rows scaled by cosh(p half).
    """
    p = math.sqrt(alpha**2 + k**2)
    beta = (2 - nu) * alpha**2
    ch, sh = 1.0, math.tanh(p * half)  # cosh and sinh over cosh
    if k < alpha:
        q = math.sqrt(alpha**2 - k**2)
        cq, sq = (
            math.cosh(q * half) / math.cosh(p * half),
            math.sinh(q * half) / math.cosh(p * half),
        )
        if symmetric:  # A cosh(py) + B cosh(qy)
            m = [(p**2 - nu * alpha**2) * ch, (q**2 - nu * alpha**2) * cq]
            v = [(p**3 - beta * p) * sh, (q**3 - beta * q) * sq]
        else:  # A sinh(py) + B sinh(qy)
            m = [(p**2 - nu * alpha**2) * sh, (q**2 - nu * alpha**2) * sq]
            v = [(p**3 - beta * p) * ch, (q**3 - beta * q) * cq]
    else:
        q = math.sqrt(k**2 - alpha**2)
        cq, sq = math.cos(q * half), math.sin(q * half)
        if symmetric:  # A cosh(py) + B cos(qy)
            m = [(p**2 - nu * alpha**2) * ch, (-(q**2) - nu * alpha**2) * cq]
            v = [(p**3 - beta * p) * sh, (q**3 + beta * q) * sq]
        else:  # A sinh(py) + B sin(qy)
            m = [(p**2 - nu * alpha**2) * sh, (-(q**2) - nu * alpha**2) * sq]
            v = [(p**3 - beta * p) * ch, (-(q**3) - beta * q) * cq]
    return m[0] * v[1] - m[1] * v[0]


def levy_lambdas(a: float, b: float, nu: float, count: int) -> list[float]:
    """The first ``count`` lambda = omega a^2 sqrt(rho h / D) of the SS-F-SS-F plate, a x b."""
    found = []
    for m in range(1, 6):
        alpha = m * math.pi / a
        for symmetric in (True, False):
            ks = np.linspace(1e-6, 40.0 / a, 40001)
            ks = ks[abs(ks - alpha) > 1e-9]
            values = [levy_determinant(k, alpha, 0.5 * b, nu, symmetric) for k in ks]
            for k0, k1, f0, f1 in zip(ks[:-1], ks[1:], values[:-1], values[1:], strict=True):
                if f0 * f1 < 0 and not (k0 < alpha < k1):
                    k = brentq(levy_determinant, k0, k1, args=(alpha, 0.5 * b, nu, symmetric),
                               xtol=1e-14)  # fmt: skip
                    found.append((k * a) ** 2)
    return sorted(found)[:count]


def plate_lambdas(plate: Deck, count: int, a: float) -> np.ndarray:
    omega = 2 * math.pi * plate.frequencies_hz(count)
    return omega * a**2 * math.sqrt(RHO * H / D)


def test_the_levy_solution_here_gives_leissa_s_printed_values() -> None:
    """The test's own reference, against the book (printed to 5 digits)."""
    assert levy_lambdas(1.0, 1.0, 0.3, 6) == pytest.approx(LEISSA_SQUARE, rel=6e-5)


@pytest.mark.parametrize("aspect", [1.0, 0.5, 2.0])
def test_bare_slab_matches_the_levy_solution(aspect: float) -> None:
    a = 12.0
    b = aspect * a
    exact = levy_lambdas(a, b, NU, 6)
    plate = Deck.plate(a, b, H, E, NU, RHO)
    assert plate_lambdas(plate, 6, a) == pytest.approx(exact, rel=5e-3)
    # and far closer than the 0.5 %: the basis holds the exact shapes along
    assert plate_lambdas(plate, 6, a) == pytest.approx(exact, rel=2e-5)


def _rhombic(theta: float, resolution: tuple[int, int] | None) -> Deck:
    a = 10.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Deck.plate(a, a * math.cos(math.radians(theta)), H, E, NU, RHO, skew=theta,
                          skew_hand="left", sides="simply supported",
                          resolution=resolution)  # fmt: skip


@pytest.mark.parametrize(("theta", "published"), [(15.0, 20.87), (30.0, 24.96)])
def test_skewed_plate_simply_supported_all_round_matches_published(
    theta: float, published: float
) -> None:
    """Within 0.5 % at the default basis.  The published values are Ritz upper bounds
    themselves; the obtuse corners make every basis converge slowly, and a finer one here
    falls a little below them (24.92 at 36 x 36 functions, 30 degrees), never above."""
    plate = _rhombic(theta, None)
    first = plate_lambdas(plate, 1, 10.0)[0]
    assert first == pytest.approx(published, rel=5e-3)
    finer = plate_lambdas(_rhombic(theta, (16, 34)), 1, 10.0)[0]
    assert finer <= first * (1 + 1e-10)
    assert finer == pytest.approx(published, rel=5e-3)


def test_ritz_frequencies_fall_as_functions_are_added() -> None:
    """Nested bases give decreasing upper bounds (the Rayleigh-Ritz method)."""
    previous = None
    for resolution in [(6, 8), (10, 12), (14, 16), (18, 20)]:
        now = plate_lambdas(_rhombic(30.0, resolution), 4, 10.0)
        if previous is not None:
            assert (now <= previous * (1 + 1e-10)).all(), (resolution, now, previous)
        previous = now


@pytest.mark.parametrize("theta", [16.0, 30.0])
@pytest.mark.parametrize("hand", ["left", "right"])
def test_skewed_slab_free_on_its_sides_matches_an_independent_fe(theta: float, hand: str) -> None:
    """The deck's own boundary conditions, skewed: Ritz against the plate FE of deck_fe.py."""
    length, width = 12.0, 10.0
    plate = Deck.plate(length, width, H, E, NU, RHO, skew=theta, skew_hand=hand)
    t = plate.tangent
    fe = PlateFE(grid(length, [], 20), grid(width, [], 16), D, NU, RHO * H, t, [0.0, length])
    reference = fe.frequencies_hz(6)  # converged to 2e-4 (28 x 24 elements change < 2e-4)
    ritz = plate.frequencies_hz(6)
    assert ritz == pytest.approx(reference, rel=5e-3)
    assert ritz == pytest.approx(reference, rel=1e-3)
    # the two hands are mirror images: the same frequencies
    other = Deck.plate(length, width, H, E, NU, RHO, skew=theta,
                       skew_hand="right" if hand == "left" else "left")  # fmt: skip
    assert other.frequencies_hz(6) == pytest.approx(ritz, rel=1e-7)
