"""Along the bridge: the static and dynamic envelopes, and the flights of the tyres.

The crossings are keyed ``(direction, rear spacing, speed)``; a backward crossing's stations
and faces are turned back to the forward ones (``L - x``, left and right swapped) and its
shear's sign with them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import display
from ..beam_statics import EFFECTS, QUANTITY, StaticEnvelope, field_envelope
from ..vehicles import as_system
from .inputs import ReportInputs

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["Envelopes", "Flights", "envelopes", "flights", "flip", "vehicle_label"]


def vehicle_label(vehicle: object) -> str:
    """How the report names a vehicle: the design truck's own name, else what it is."""
    from ..vehicles import QuarterCar, Vehicle

    if isinstance(vehicle, Vehicle):
        return "the truck (the study's sprung mass)"
    if isinstance(vehicle, QuarterCar):
        return "the truck (a quarter car)"
    return as_system(vehicle).name or "the vehicle"


def flip(face: str) -> str:
    """The same face seen from the other end of the bridge: ``"left"`` <-> ``"right"``."""
    return {"left": "right", "right": "left"}.get(face, face)


# ---------------------------------------------------------------------------- envelopes
@dataclass(frozen=True, eq=False)
class Envelopes:
    """Static and dynamic envelopes along the bridge (forward stations and signs).

    ``static`` is the exact static envelope of the vehicle's axles over the directions
    asked (:func:`vbi_lib.beam_statics.field_envelope`, each interior support twice, both
    faces); ``maximum`` and ``minimum`` ``(3, n)`` are the dynamic extremes over the
    requested crossings of that vehicle at the same stations (crossings that lost contact
    left out, unless all did).
    """

    static: StaticEnvelope
    maximum: np.ndarray
    minimum: np.ndarray
    supports: tuple[float, ...]
    vehicle: str

    def to_dataframe(self) -> pd.DataFrame:
        """One row per station and effect: static and dynamic extremes (display units)."""
        rows = []
        faces = self.static.faces
        for e, effect in enumerate(EFFECTS):
            quantity = QUANTITY[effect]
            for i, x in enumerate(self.static.sections):
                rows.append({
                    display.label("station", "length"): display.value(x, "length"),
                    "effect": effect,
                    "face": faces[i] if effect == "shear" else "",
                    "unit": display.symbol(quantity),
                    "static maximum": display.value(self.static.maximum[e, i], quantity),
                    "static minimum": display.value(self.static.minimum[e, i], quantity),
                    "dynamic maximum": display.value(self.maximum[e, i], quantity),
                    "dynamic minimum": display.value(self.minimum[e, i], quantity),
                })  # fmt: skip
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None, effect: str = "moment") -> Axes:
        """Static (dashed) and dynamic (solid) envelope of ``effect`` along the bridge."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 2.6))
        e = EFFECTS.index(effect)
        quantity = QUANTITY[effect]
        x = display.value(self.static.sections, "length")
        for bound, static, dynamic, color in (
            ("maximum", self.static.maximum[e], self.maximum[e], "C3"),
            ("minimum", self.static.minimum[e], self.minimum[e], "C0"),
        ):
            ax.plot(x, display.value(dynamic, quantity), color=color, lw=1.3,
                    label=f"dynamic {bound}")  # fmt: skip
            ax.plot(x, display.value(static, quantity), "--", color=color, lw=0.9,
                    label=f"static {bound}")  # fmt: skip
        for s in self.supports:
            ax.axvline(display.value(s, "length"), color="0.6", lw=0.6)
        ax.axhline(0.0, color="k", lw=0.6)
        ax.set_xlabel(display.label("station from the first support", "length"))
        ax.set_ylabel(display.label(effect, quantity))
        ax.legend(loc="best", fontsize="x-small", ncol=2)
        return ax


def envelopes(inputs: ReportInputs, vehicle: object, crossings: dict, spacing: float | None,
               count: int) -> Envelopes:  # fmt: skip
    """The static envelope of ``vehicle`` along the bridge and the dynamic one over its
    requested ``crossings`` of rear ``spacing`` (forward stations and signs)."""
    system = as_system(vehicle)
    static = field_envelope(inputs.bridge.spans, inputs.bridge.EI, system.static_loads,
                            system.offsets, count=count,
                            direction=inputs.parameters.direction)  # fmt: skip
    faces = tuple(f or "left" for f in static.faces)
    maximum = np.full((3, static.sections.size), -np.inf)
    minimum = np.full((3, static.sections.size), np.inf)
    keys = [k for k in crossings if k[1] == spacing]
    valid = [k for k in keys if not crossings[k].lost_contact] or keys
    for key in valid:
        direction = key[0]
        crossing = crossings[key]
        x = inputs.to_run(static.sections, direction)
        side = faces if direction == "forward" else tuple(flip(f) for f in faces)
        response = crossing.sections(x, side=side)
        high, low = response.maximum.copy(), response.minimum.copy()
        if direction == "backward":
            high[2], low[2] = -response.minimum[2], -response.maximum[2]
        maximum = np.maximum(maximum, high)
        minimum = np.minimum(minimum, low)
    return Envelopes(static, maximum, minimum, inputs.bridge.supports, vehicle_label(vehicle))


# ---------------------------------------------------------------------------- flights
@dataclass(frozen=True, eq=False)
class Flights:
    """Every flight of a tyre in the requested crossings (forward stations), and the
    tyres' footprint."""

    table: pd.DataFrame
    footprint: tuple[float, ...]
    unilateral: bool

    def to_dataframe(self) -> pd.DataFrame:
        """One row per flight: direction, speed, axle, take-off and landing station [m] from
        the first support, duration [s]."""
        return self.table.copy()

    def plot(self, ax: Axes | None = None) -> Axes:
        """Where the tyres flew: a bar from take-off to landing station, one row per flight."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 2.0))
        for k, row in enumerate(self.table.itertuples()):
            start = display.value(min(row.take_off_m, row.landing_m), "length")
            size = display.value(abs(row.landing_m - row.take_off_m), "length")
            ax.barh(k, size, left=start, color="C3")
        ax.set_xlabel(display.label("station from the first support", "length"))
        ax.set_yticks([])
        return ax


def flights(inputs: ReportInputs, crossings: dict) -> Flights:
    """Every flight of a tyre in ``crossings``, at forward stations from the first support."""
    rows = []
    length = inputs.bridge.length
    for (direction, spacing, speed), crossing in crossings.items():
        start = crossing.bridge_start
        for row in crossing.flights().itertuples(index=False):
            take_off, landing = row[3] - start, row[4] - start
            if direction == "backward":
                take_off, landing = length - take_off, length - landing
            rows.append({
                "direction": direction,
                "speed_m_s": float(speed),
                "rear_axle_spacing_m": spacing,
                "axle": int(row[0]),
                "take_off_m": float(take_off),
                "landing_m": float(landing),
                "duration_s": float(row[5]),
                "on_bridge": bool(-1e-9 <= take_off <= length + 1e-9),
            })  # fmt: skip
    columns = ["direction", "speed_m_s", "rear_axle_spacing_m", "axle", "take_off_m",
               "landing_m", "duration_s", "on_bridge"]  # fmt: skip
    system = as_system(inputs.vehicle)
    return Flights(
        pd.DataFrame(rows, columns=columns),
        tuple(float(f) for f in system.footprint),
        bool(system.has_unilateral),
    )
