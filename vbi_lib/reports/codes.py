"""The design codes' dynamic allowances for the report's places and effects.

AASHTO LRFD (Table 3.6.2.1-1: 33 %, 15 % for fatigue and fracture), the AASHTO Standard
Specifications (3.8.2.1: 50 / (L + 125) <= 0.30, its loaded length L in feet for each place
and effect by 3.8.2.2) and the Ontario code of 1983 (from the first frequency), from
:mod:`vbi_lib.amplification`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import pandas as pd

from .. import amplification as amp
from ..bridges import Bridge
from ..units import ft

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from .columns import Column

__all__ = ["Allowances", "allowances", "loaded_length"]


# ---------------------------------------------------------------------------- design codes
@dataclass(frozen=True)
class Allowances:
    """Design DAF ``1 + IM`` of the codes for this bridge, by code (see :mod:`amplification`).

    ``daf`` are the bridge-wide values (the AASHTO Standard's at the longest span);
    ``by_column`` the values of each place and effect (the AASHTO Standard's loaded length
    depends on them, 3.8.2.2).
    """

    daf: dict[str, float]
    #: AASHTO LRFD Table 3.6.2.1-1, all limit states but fatigue and deck joints.
    aashto_lrfd: float
    #: AASHTO LRFD Table 3.6.2.1-1, fatigue and fracture.
    aashto_fatigue: float = 1.15
    by_column: tuple[dict[str, float], ...] = ()

    def to_dataframe(self) -> pd.DataFrame:
        """One row per code: its design DAF."""
        return pd.DataFrame({"design DAF (1 + IM)": self.daf}).rename_axis("code")

    def plot(self, ax: Axes | None = None) -> Axes:
        """Horizontal bars of the design DAFs."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6, 2))
        ax.barh(list(self.daf), list(self.daf.values()), color="0.6")
        ax.set_xlabel("design DAF (1 + IM) [-]")
        return ax


def loaded_length(bridge: Bridge, column: Column) -> float:
    """The AASHTO Standard's loaded length of a place and effect [m] (3.8.2.2): the span for
    a displacement or a moment in a span, the mean of the two spans at an interior support
    (negative moment), for the shear the longer part of the span on its face's side."""
    spans, supports = bridge.spans, bridge.supports
    place = column.place
    if place.interior_support:
        left, right = spans[place.support - 1], spans[place.support]
        if column.effect == "moment":
            return 0.5 * (left + right)
        return left if column.face == "left" else right
    if place.support is not None:
        return spans[0] if place.support == 0 else spans[-1]
    j = place.span
    if column.effect == "shear":
        s = place.x - supports[j]
        return max(s, spans[j] - s)
    return spans[j]


def allowances(bridge: Bridge, cols: tuple[Column, ...] = ()) -> Allowances:
    """AASHTO LRFD (33 %, 15 % for fatigue), AASHTO Standard (loaded length in feet) and
    OHBDC 1983 (first frequency)."""
    lrfd = amp.aashto_lrfd_allowance()
    fatigue = amp.aashto_lrfd_allowance("fatigue and fracture")
    ohbdc = 1.0 + float(amp.ohbdc_1983_allowance(bridge.first_frequency_hz))
    by_column = []
    for col in cols:
        length = loaded_length(bridge, col)
        by_column.append({
            "AASHTO LRFD": 1.0 + lrfd,
            "AASHTO LRFD fatigue": 1.0 + fatigue,
            "AASHTO Standard": 1.0 + float(amp.aashto_standard_impact(length)),
            "OHBDC 1983": ohbdc,
            "loaded length [m]": length,
        })  # fmt: skip
    return Allowances(
        aashto_lrfd=1.0 + lrfd,
        aashto_fatigue=1.0 + fatigue,
        daf={
            f"AASHTO LRFD, Table 3.6.2.1-1 (IM {lrfd:.0%})": 1.0 + lrfd,
            f"AASHTO LRFD, fatigue and fracture (IM {fatigue:.0%})": 1.0 + fatigue,
            f"AASHTO Standard, 50 / (L + 125) <= 0.30, at L = {bridge.span / ft:.0f} ft": 1.0
            + float(amp.aashto_standard_impact(bridge.span)),
            f"OHBDC 1983, at f1 = {bridge.first_frequency_hz:.2f} Hz": ohbdc,
        },
        by_column=tuple(by_column),
    )
