r"""Strain versus displacement amplification of a simply supported beam (study equations 19-31).

A simply supported beam carries a vehicle force :math:`A_v P` at midspan and, while it
vibrates, the inertia of its own mass.  In mode :math:`n` that inertia is the distributed load
:math:`(m_b A_n / L) \sin(n \pi x / L)` (23)-(24) with :math:`m_b` the beam's mass and
:math:`A_n` the modal acceleration amplitude.  Adding the two static solutions and dividing by
the point-load solutions :math:`P L^3 / 48 EI` (19) and :math:`P L / 4` (21) gives, with
the inertia ratio :math:`\eta_n = m_b A_n / P` (the book's symbol; the study wrote the
ratio without naming it),

.. math::
    DAF_d = A_v + \sum_n \frac{48\, \eta_n \sin(n\pi/2)}{n^4 \pi^4}, \qquad
    DAF_s = A_v + \sum_n \frac{4\, \eta_n \sin(n\pi/2)}{n^2 \pi^2}

(25)-(27) for the first mode, (29)-(30) in general (:eq:`study-25` to :eq:`study-27`,
:eq:`study-29`, :eq:`study-30` in the book).  The extra terms stand in the ratio
:math:`12 / (n^2 \pi^2)` (28), (31): 1.216 for the first mode, so a displacement gauge reads
more amplification than a strain gauge whenever the first mode vibrates.

Limits: the algebra is for a simply supported beam with the vehicle force at midspan; the
beam's inertia is treated as an equivalent static load (each mode's shape, its peak
acceleration).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from .. import _validation as check

if TYPE_CHECKING:
    from matplotlib.axes import Axes

#: Displacement coefficient of the first-mode inertia term, ``48 / pi^4`` (26).
DISPLACEMENT_INERTIA_COEFFICIENT = 48.0 / math.pi**4
#: Strain (stress, moment) coefficient of the first-mode inertia term, ``4 / pi^2`` (27).
STRAIN_INERTIA_COEFFICIENT = 4.0 / math.pi**2


def inertia_ratio(beam_mass: float, acceleration: float | np.ndarray, force: float) -> np.ndarray:
    """``eta = m_b A / P``: peak inertia force of the beam over the vehicle weight (25)-(27).

    Parameters
    ----------
    beam_mass
        Total mass of the (simply supported) beam ``m_b`` [kg].
    acceleration
        Modal acceleration amplitude ``A`` (midspan for mode 1) [m/s^2]; an array for several
        modes.
    force
        Vehicle weight ``P`` [N].

    Examples
    --------
    >>> float(inertia_ratio(50_000.0, 0.5, 250_000.0))
    0.1
    """
    beam_mass = check.positive("beam_mass", beam_mass)
    force = check.positive("force", force)
    acceleration = np.asarray(acceleration, dtype=float)
    if not np.all(np.isfinite(acceleration)):
        raise ValueError(f"acceleration={acceleration!r} must be finite")
    return beam_mass * acceleration / force


def _mode_numbers(modes: int | Sequence[int]) -> np.ndarray:
    numbers = np.atleast_1d(np.asarray(modes))
    if numbers.ndim != 1 or numbers.size == 0 or not np.issubdtype(numbers.dtype, np.integer):
        raise ValueError(f"modes={modes!r} must be a mode number or a list of them (1, 2, ...)")
    if np.any(numbers < 1):
        raise ValueError(f"modes={modes!r} must hold mode numbers >= 1")
    return numbers.astype(int)


def _sin_half_pi(n: np.ndarray) -> np.ndarray:
    """``sin(n pi / 2)`` exactly for integers: 0 for even n, +1/-1 alternating for odd n."""
    return np.where(n % 2 == 0, 0.0, np.where(n % 4 == 1, 1.0, -1.0))


def _inertia_terms(
    ratio: float | np.ndarray, modes: int | Sequence[int], power: int, coefficient: float
) -> np.ndarray:
    numbers = _mode_numbers(modes)
    ratio = np.asarray(ratio, dtype=float)
    if not np.all(np.isfinite(ratio)):
        raise ValueError(f"inertia_ratio={ratio!r} must be finite")
    weights = coefficient * _sin_half_pi(numbers) / (numbers.astype(float) ** power)
    if np.ndim(modes) == 0:
        return ratio * weights[0]
    if ratio.ndim == 0 or ratio.shape[-1] != numbers.size:
        raise ValueError(
            f"inertia_ratio has shape {ratio.shape}; with modes={list(numbers)} its last axis "
            f"must hold one ratio per mode ({numbers.size})"
        )
    return ratio @ weights


def displacement_daf(
    vehicle_amplification: float | np.ndarray,
    inertia_ratio: float | np.ndarray,
    modes: int | Sequence[int] = 1,
) -> np.ndarray:
    """Midspan displacement amplification with the beam's own inertia (26), (29).

    ``DAF_d = A_v + sum_n 48 eta_n sin(n pi / 2) / (n^4 pi^4)``.

    Parameters
    ----------
    vehicle_amplification
        ``A_v``: the vehicle's contact force over its weight [-].
    inertia_ratio
        ``eta_n = m_b A_n / P`` [-]; with ``modes`` a list, the last axis holds one ratio
        per mode.
    modes
        Mode number (default 1) or list of mode numbers; even modes add nothing at midspan.

    Examples
    --------
    >>> round(float(displacement_daf(1.1, 0.5)), 4)   # 1.1 + 0.5 * 48 / pi^4
    1.3464
    """
    terms = _inertia_terms(inertia_ratio, modes, 4, DISPLACEMENT_INERTIA_COEFFICIENT)
    return np.asarray(vehicle_amplification, dtype=float) + terms


def strain_daf(
    vehicle_amplification: float | np.ndarray,
    inertia_ratio: float | np.ndarray,
    modes: int | Sequence[int] = 1,
) -> np.ndarray:
    """Midspan strain (stress, moment) amplification with the beam's own inertia (27), (30).

    ``DAF_s = A_v + sum_n 4 eta_n sin(n pi / 2) / (n^2 pi^2)``; arguments as for
    :func:`displacement_daf`.

    Examples
    --------
    >>> round(float(strain_daf(1.1, 0.5)), 4)   # 1.1 + 0.5 * 4 / pi^2
    1.3026
    """
    terms = _inertia_terms(inertia_ratio, modes, 2, STRAIN_INERTIA_COEFFICIENT)
    return np.asarray(vehicle_amplification, dtype=float) + terms


def extra_amplification_ratio(mode: int = 1) -> float:
    """Displacement over strain extra amplification of mode ``n``: ``12 / (n^2 pi^2)`` (28), (31).

    Above 1 only for the first mode: the higher odd modes add more to strain than to
    displacement.

    Examples
    --------
    >>> round(extra_amplification_ratio(1), 3), round(extra_amplification_ratio(3), 4)
    (1.216, 0.1351)
    """
    n = int(_mode_numbers(mode)[0])
    if np.ndim(mode) != 0:
        raise ValueError(f"mode={mode!r} must be a single mode number")
    return 12.0 / (n**2 * math.pi**2)


def plot_extra_amplification(max_ratio: float = 1.0, ax: Axes | None = None) -> Axes:
    """Figure 2.11.1: amplification added by the first mode's inertia against ``eta``.

    ``ax``: a matplotlib axes, or None for a new figure (7 x 3.2 in).  Returns the axes.
    """
    import matplotlib.pyplot as plt

    max_ratio = check.positive("max_ratio", max_ratio)
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 3.2))
    eta = np.linspace(0.0, max_ratio, 201)
    ax.plot(eta, displacement_daf(0.0, eta), label=r"displacement, $48 \eta / \pi^4$")
    ax.plot(eta, strain_daf(0.0, eta), label=r"strain, stress, moment, $4 \eta / \pi^2$")
    ax.set_xlabel(r"bridge inertia over vehicle weight $\eta = m_b A_{max} / P$ [-]")
    ax.set_ylabel("extra amplification [-]")
    ax.legend(loc="upper left")
    ax.grid(alpha=0.3)
    return ax


__all__ = [
    "DISPLACEMENT_INERTIA_COEFFICIENT",
    "STRAIN_INERTIA_COEFFICIENT",
    "displacement_daf",
    "extra_amplification_ratio",
    "inertia_ratio",
    "plot_extra_amplification",
    "strain_daf",
]
