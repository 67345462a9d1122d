r"""Impact factor, dynamic amplification factor and how design codes set them (equations 16-18).

With :math:`Q_{sta}` a response (deflection, strain, moment) to the vehicle standing still
and :math:`Q_{dyn}` its largest value at speed (the book's :eq:`study-16` to
:eq:`study-18`):

.. math::
    IM = \frac{Q_{dyn} - Q_{sta}}{Q_{sta}}, \qquad DAF = \frac{Q_{dyn}}{Q_{sta}} = 1 + IM,
    \qquad Q_{LL} = Q_{sta} (1 + IM) = Q_{sta}\, DAF .

Design codes give the allowance ``IM`` without a vehicle-bridge model:

* AASHTO LRFD Bridge Design Specifications, Art. 3.6.2.1 (Table 3.6.2.1-1): dynamic load
  allowance 33 % for all limit states, 15 % for fatigue and fracture, 75 % for deck joints.
* AASHTO Standard Specifications for Highway Bridges, Art. 3.8.2.1 (17th ed., 2002):
  ``I = 50 / (L + 125) <= 0.30`` with the loaded length ``L`` in feet.
* Ontario Highway Bridge Design Code, 2nd ed. (1983), Cl. 2-7.2: the allowance depends on the
  first flexural frequency, 0.20 below 1 Hz, rising to 0.40 between 2.5 and 4.5 Hz where trucks
  bounce, falling to 0.25 above 6 Hz (linear between), as reviewed by Billing (1984) and
  Paultre, Chaallal and Proulx (1992).
"""

from __future__ import annotations

import numpy as np

from .units import ft

#: AASHTO LRFD Table 3.6.2.1-1 dynamic load allowance by component / limit state.
AASHTO_LRFD_IM = {"all other limit states": 0.33, "fatigue and fracture": 0.15, "deck joints": 0.75}

# OHBDC (1983) dynamic load allowance against first flexural frequency [Hz]
_OHBDC_FREQUENCY_HZ = np.array([1.0, 2.5, 4.5, 6.0])
_OHBDC_ALLOWANCE = np.array([0.20, 0.40, 0.40, 0.25])


def impact_factor(dynamic: float | np.ndarray, static: float | np.ndarray) -> np.ndarray:
    """``IM = (Q_dyn - Q_sta) / Q_sta`` (16), :eq:`study-16`.

    >>> round(float(impact_factor(1.3, 1.0)), 12)
    0.3
    """
    static = np.asarray(static, dtype=float)
    if np.any(static == 0):
        raise ValueError("static response is zero: the impact factor is undefined")
    return (np.asarray(dynamic, dtype=float) - static) / static


def dynamic_amplification_factor(
    dynamic: float | np.ndarray, static: float | np.ndarray
) -> np.ndarray:
    """``DAF = Q_dyn / Q_sta = 1 + IM`` (17), :eq:`study-17`.

    >>> float(dynamic_amplification_factor(-1.25, -1.0))
    1.25
    """
    static = np.asarray(static, dtype=float)
    if np.any(static == 0):
        raise ValueError("static response is zero: the DAF is undefined")
    return np.asarray(dynamic, dtype=float) / static


def live_load_response(static: float | np.ndarray, impact: float | np.ndarray) -> np.ndarray:
    """Design live-load response ``Q_LL = Q_sta (1 + IM)`` (18), :eq:`study-18`.

    >>> float(live_load_response(100.0, 0.33))
    133.0
    """
    return np.asarray(static, dtype=float) * (1.0 + np.asarray(impact, dtype=float))


def aashto_lrfd_allowance(component: str = "all other limit states") -> float:
    """AASHTO LRFD dynamic load allowance (Table 3.6.2.1-1).

    Parameters
    ----------
    component
        ``"all other limit states"`` (0.33), ``"fatigue and fracture"`` (0.15) or
        ``"deck joints"`` (0.75, all limit states).

    >>> aashto_lrfd_allowance("fatigue and fracture")
    0.15
    """
    if component not in AASHTO_LRFD_IM:
        raise ValueError(f"component={component!r} is not one of {sorted(AASHTO_LRFD_IM)}")
    return AASHTO_LRFD_IM[component]


def aashto_standard_impact(loaded_length: float | np.ndarray) -> np.ndarray:
    """AASHTO Standard Specifications impact ``I = 50 / (L + 125) <= 0.30``, ``L`` in feet.

    Parameters
    ----------
    loaded_length
        Length of the loaded span [m] (converted to feet inside).

    >>> from vbi_lib import units as u
    >>> round(float(aashto_standard_impact(100 * u.ft)), 4)
    0.2222
    """
    length = np.asarray(loaded_length, dtype=float)
    if np.any(~np.isfinite(length)) or np.any(length <= 0):
        raise ValueError(f"loaded_length={loaded_length!r} must be positive lengths in metres")
    return np.minimum(50.0 / (length / ft + 125.0), 0.30)


def ohbdc_1983_allowance(first_frequency_hz: float | np.ndarray) -> np.ndarray:
    """Ontario (OHBDC 1983) dynamic load allowance against the first flexural frequency.

    0.20 up to 1 Hz, linear to 0.40 at 2.5 Hz, 0.40 to 4.5 Hz, linear to 0.25 at 6 Hz,
    0.25 above.

    >>> [float(ohbdc_1983_allowance(f)) for f in (0.5, 3.0, 5.25, 10.0)]
    [0.2, 0.4, 0.325, 0.25]
    """
    frequency = np.asarray(first_frequency_hz, dtype=float)
    if np.any(~np.isfinite(frequency)) or np.any(frequency <= 0):
        raise ValueError(f"first_frequency_hz={first_frequency_hz!r} must be positive")
    return np.interp(frequency, _OHBDC_FREQUENCY_HZ, _OHBDC_ALLOWANCE)
