r"""Displacement, bending moment and shear at any section, from a crossing's histories.

A crossing model integrates the modal coordinates :math:`q_n(t)`; the responses at a section
:math:`x` follow after the run, with no change to the kernels.  With
:math:`r_n(x) = \phi_n(x), EI\phi_n''(x), EI\phi_n'''(x)` for the displacement (up
positive), the moment (sagging positive) and the shear (:math:`V = dM/dx`):

* **mode-displacement** method: :math:`r(x, t) = \sum_{n \le N} r_n(x)\, q_n(t)`.  The
  moment converges slowly in :math:`N` (terms fall as :math:`1/n^2`) and the shear hardly at
  all under a concentrated load (terms as :math:`1/n`, with Gibbs' overshoot at the load);
* **mode-acceleration** method (the default; e.g. Craig & Kurdila, *Fundamentals of
  Structural Dynamics*; Chopra, *Dynamics of Structures*): each
  :math:`q_n` is split by its equation of motion into the static response to the current
  loads and an inertia and damping part; the static part, summed over *all* modes, is the
  exact static response of the beam to the axle loads :math:`R_i(t)` at their positions
  :math:`a_i(t)` (:func:`vbi_lib.beam_statics.continuous_statics`), so

  .. math:: r(x, t) = \sum_{n \le N} r_n(x)\, q_n(t)
      + \sum_i R_i(t) \Big[\eta_r(x, a_i) + \sum_{n \le N} r_n(x)\,
      \frac{\phi_n(a_i)}{\omega_n^2}\Big],

  with :math:`\eta_r` the exact influence line.  A crawling truck then gives the exact
  statics whatever :math:`N`, and only the dynamic part is truncated.  Against Frýba's
  moving force on a simple span (``tests/models/test_sections.py``), 8 modes give the
  moment to 0.1 % of its peak (the mode-displacement series: 4-5 %) and the shear to about
  1 % (the series: 30-60 %, Gibbs' overshoot); the shear's dynamic part, the free vibration
  of the high modes set off as the axle enters, falls only as about
  :math:`(2/\pi)\,\alpha/N` of the load (:math:`\alpha = v / 2 f_1 L`).

The *static counterpart* of an effect is its extreme when the same axle loads crawl across
(:func:`vbi_lib.beam_statics.static_envelope`, the exact influence lines; for the
mode-displacement method the N-mode influence lines, so that each method is compared with
its own statics), and the **DAF of a section and effect** is the dynamic extreme over the
static extreme of the same sense, the sense in which the static extreme is larger.  The
dynamic extremes are taken at the crossing's nodes (steps of ``speed * dt``).

For the one-coordinate model (one span or two equal spans) the same formulas hold with its
single shape, the first mode: it gives the exact statics plus one mode's dynamics.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import display
from ..beam_statics import (
    EFFECTS,
    QUANTITY,
    StaticEnvelope,
    continuous_statics,
    effect_index,
    envelope,
    static_envelope,
)
from ..bridges import Bridge
from ..modes import BeamModes

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["EFFECTS", "METHODS", "SectionResponse", "section_history", "static_counterpart"]

#: How section responses are computed from the modal coordinates.
METHODS = ("mode-acceleration", "mode-displacement")
_ORDER = {"displacement": 0, "moment": 2, "shear": 3}


def check_method(method: object) -> str:
    """A method name of :data:`METHODS`."""
    if method not in METHODS:
        raise ValueError(f"method={method!r} is not known; use one of {', '.join(METHODS)}")
    return str(method)


def _modal_shapes(modes: BeamModes, effect: str, x: np.ndarray) -> np.ndarray:
    """``r_n(x)``, shape ``(n_x, N)``: phi (displacement), EI phi'' (moment), EI phi'''."""
    values = modes.derivative(x, _ORDER[effect])
    return values if effect == "displacement" else modes.bridge.EI * values


def section_history(
    modes: BeamModes,
    q: np.ndarray,
    loads: np.ndarray,
    positions: np.ndarray,
    sections: np.ndarray,
    effect: str,
    method: str = "mode-acceleration",
) -> np.ndarray:
    """History of one effect at sections, shape ``(n_time, n_s)``.

    Parameters
    ----------
    modes
        The bridge's modes.
    q
        Modal coordinates ``(n_time, N)`` [kg^1/2 m].
    loads
        Downward axle loads on the bridge ``(n_time, n_axles)`` [N] (0 when off).
    positions
        Axle stations from the bridge start ``(n_time, n_axles)`` [m].
    sections
        Stations from the bridge start ``(n_s,)`` [m].
    effect
        ``"displacement"`` [m, up], ``"moment"`` [N m, sagging], ``"shear"`` [N, dM/dx].
    method
        ``"mode-acceleration"`` or ``"mode-displacement"`` (module docstring).
    """
    effect_index(effect)
    check_method(method)
    shapes = _modal_shapes(modes, effect, sections)  # (n_s, N)
    values = q @ shapes.T
    if method == "mode-displacement":
        return values
    bridge = modes.bridge
    length = bridge.length
    e = EFFECTS.index(effect)
    for i in range(loads.shape[1]):
        on = (positions[:, i] >= 0.0) & (positions[:, i] <= length) & (loads[:, i] != 0.0)
        if not on.any():
            continue
        a = positions[on, i]
        statics = continuous_statics(sections[None, :], a[:, None], bridge.spans, bridge.EI)
        exact = (-statics.deflection, statics.moment, statics.shear)[e]
        truncated = -(modes.shape(a) / modes.omega**2) @ shapes.T
        values[on] += loads[on, i, None] * (exact - truncated)
    return values


def _modal_envelope(
    modes: BeamModes, sections: np.ndarray, axle_loads: np.ndarray, axle_offsets: np.ndarray
) -> StaticEnvelope:
    shapes = [_modal_shapes(modes, effect, sections) for effect in EFFECTS]

    def influence(a: np.ndarray) -> np.ndarray:
        static = -modes.shape(a) / modes.omega**2  # (n_a, N): q_n under a unit load
        return np.stack([static @ r.T for r in shapes])

    return envelope(influence, modes.supports, sections, axle_loads, axle_offsets)


def static_counterpart(
    modes: BeamModes,
    sections: np.ndarray,
    axle_loads: np.ndarray,
    axle_offsets: np.ndarray,
    method: str = "mode-acceleration",
) -> StaticEnvelope:
    """The static envelope the method's DAF divides by: exact, or from the N modes.

    Memoised: a study asks for the same bridge, axles and sections crossing after crossing.
    """
    method = check_method(method)
    key = tuple(float(x) for x in np.ravel(sections))
    loads = tuple(float(p) for p in np.ravel(axle_loads))
    offsets = tuple(float(o) for o in np.ravel(axle_offsets))
    if method == "mode-displacement":
        return _cached_modal(modes, key, loads, offsets)
    return _cached_exact(modes.bridge.spans, modes.bridge.EI, key, loads, offsets)


def _frozen(envelope_: StaticEnvelope) -> StaticEnvelope:
    for array in vars(envelope_).values():
        array.setflags(write=False)
    return envelope_


@lru_cache(maxsize=256)
def _cached_exact(spans: tuple, EI: float, sections: tuple, loads: tuple, offsets: tuple):  # noqa: ANN202, N803
    return _frozen(static_envelope(spans, EI, sections, loads, offsets))


@lru_cache(maxsize=256)
def _cached_modal(modes: BeamModes, sections: tuple, loads: tuple, offsets: tuple):  # noqa: ANN202
    arrays = (np.array(sections), np.array(loads), np.array(offsets))
    return _frozen(_modal_envelope(modes, *arrays))


@dataclass(frozen=True, eq=False, kw_only=True)
class SectionResponse:
    """Displacement, moment and shear at sections over a crossing, with their static DAFs.

    Arrays of effects are ``(3, n_s)`` in the order of :data:`EFFECTS`; displacement [m]
    positive up, moment [N m] sagging positive, shear [N] ``= dM/dx``.

    Attributes
    ----------
    bridge
        The bridge.
    sections
        Stations from the bridge start [m], ``(n_s,)``.
    time, position
        Time [s] and first-axle station from the bridge start [m] at every node.
    displacement, moment, shear
        Histories ``(n_time, n_s)``.
    static
        The static counterpart (:class:`~vbi_lib.beam_statics.StaticEnvelope`).
    method, modes
        How the responses were computed, and the number of modes.
    lost_contact
        The crossing's contact force became tensile: every number here is outside the
        model's validity.
    notes
        Sentences on how the responses were computed.
    """

    bridge: Bridge
    sections: np.ndarray
    time: np.ndarray
    position: np.ndarray
    displacement: np.ndarray
    moment: np.ndarray
    shear: np.ndarray
    static: StaticEnvelope
    method: str
    modes: int
    lost_contact: bool = False
    notes: tuple[str, ...] = ()

    def history(self, effect: str) -> np.ndarray:
        """History of one effect at every section, ``(n_time, n_s)``."""
        return (self.displacement, self.moment, self.shear)[effect_index(effect)]

    @property
    def _stack(self) -> np.ndarray:
        return np.stack([self.displacement, self.moment, self.shear])  # (3, n_t, n_s)

    @property
    def maximum(self) -> np.ndarray:
        """Largest value of each effect over the crossing, ``(3, n_s)``."""
        return self._stack.max(axis=1)

    @property
    def minimum(self) -> np.ndarray:
        """Smallest value of each effect over the crossing, ``(3, n_s)``."""
        return self._stack.min(axis=1)

    @property
    def governing(self) -> np.ndarray:
        """``+1`` where the static maximum is the larger in size, else ``-1``; ``(3, n_s)``."""
        return np.where(self.static.maximum >= -self.static.minimum, 1, -1)

    def _ratio(self, dynamic: np.ndarray, static: np.ndarray) -> np.ndarray:
        scale = np.maximum(np.abs(self.static.maximum), np.abs(self.static.minimum))
        meaningful = (np.abs(static) > 1e-9 * scale) & (scale > 0)
        return np.divide(dynamic, static, out=np.full(static.shape, np.nan), where=meaningful)

    @property
    def daf_maximum(self) -> np.ndarray:
        """Dynamic over static maximum, ``(3, n_s)`` (NaN where the static maximum is 0)."""
        return self._ratio(self.maximum, self.static.maximum)

    @property
    def daf_minimum(self) -> np.ndarray:
        """Dynamic over static minimum, ``(3, n_s)`` (NaN where the static minimum is 0)."""
        return self._ratio(self.minimum, self.static.minimum)

    @property
    def daf(self) -> np.ndarray:
        """DAF of each effect at each section in its governing sense, ``(3, n_s)``."""
        return np.where(self.governing > 0, self.daf_maximum, self.daf_minimum)

    def extreme_index(self, effect: str, sense: str) -> np.ndarray:
        """Node of the extreme (``sense`` ``"max"`` or ``"min"``) at each section, ``(n_s,)``."""
        if sense not in ("max", "min"):
            raise ValueError(f"sense={sense!r} must be 'max' or 'min'")
        values = self.history(effect)
        return np.argmax(values, axis=0) if sense == "max" else np.argmin(values, axis=0)

    def coincident(self, effect: str, sense: str, other: str) -> np.ndarray:
        """``other`` at each section at the instant of the extreme of ``effect``, ``(n_s,)``.

        E.g. ``coincident("moment", "max", "shear")``: the shear that occurs together with
        the largest moment.
        """
        index = self.extreme_index(effect, sense)
        return self.history(other)[index, np.arange(self.sections.size)]

    # ------------------------------------------------------------------ export
    def to_dataframe(self) -> pd.DataFrame:
        """One row per section, effect and sense, in display units.

        Columns: section, effect, sense (``max``/``min``), whether it governs the DAF, the
        effect's unit, the dynamic and static extremes (in that unit), their ratio (the
        DAF; NaN where the static extreme is 0), the time and first-axle position of the
        dynamic extreme, the three effects at that instant and ``lost contact``.
        """
        rows = []
        governing = self.governing
        for e, effect in enumerate(EFFECTS):
            quantity = QUANTITY[effect]
            for sense, dynamic, static, ratio in (
                ("max", self.maximum, self.static.maximum, self.daf_maximum),
                ("min", self.minimum, self.static.minimum, self.daf_minimum),
            ):
                index = self.extreme_index(effect, sense)
                for i, x in enumerate(self.sections):
                    row = {
                        display.label("section", "length"): display.value(x, "length"),
                        "effect": effect,
                        "sense": sense,
                        "governs": bool(governing[e, i] == (1 if sense == "max" else -1)),
                        "unit": display.symbol(quantity),
                        "dynamic": display.value(dynamic[e, i], quantity),
                        "static": display.value(static[e, i], quantity),
                        "daf": ratio[e, i],
                        display.label("time", "time"): self.time[index[i]],
                        display.label("position", "length"): display.value(
                            self.position[index[i]], "length"
                        ),
                    }
                    for other in EFFECTS:
                        row[display.label(f"coincident {other}", QUANTITY[other])] = display.value(
                            self.history(other)[index[i], i], QUANTITY[other]
                        )
                    row["lost contact"] = self.lost_contact
                    rows.append(row)
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None, effect: str = "moment") -> Axes:
        """Plot one effect at every section against the first axle's position, with the
        static extremes as dashed lines (display units)."""
        import matplotlib.pyplot as plt

        e = effect_index(effect)
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        quantity = QUANTITY[effect]
        x = display.value(self.position, "length")
        history = self.history(effect)
        for i, section in enumerate(self.sections):
            line = ax.plot(
                x,
                display.value(history[:, i], quantity),
                label=display.fmt(section, "length"),
            )[0]
            for bound in (self.static.maximum[e, i], self.static.minimum[e, i]):
                ax.axhline(display.value(bound, quantity), color=line.get_color(), ls="--", lw=0.8)
        ax.axvspan(0, display.value(self.bridge.length, "length"), color="0.93", zorder=0)
        ax.set_xlabel(display.label("first axle from the start of the bridge", "length"))
        ax.set_ylabel(display.label(effect, quantity))
        title = f"{self.method}, {self.modes} modes; dashed: static extremes"
        if self.lost_contact:
            title += " (CONTACT LOST: outside validity)"
        ax.set_title(title, fontsize="small")
        ax.legend(loc="best", title="section", fontsize="small")
        return ax

    def __repr__(self) -> str:
        parts = []
        for e, effect in enumerate(EFFECTS):
            daf = self.daf[e]
            if np.isfinite(daf).any():
                parts.append(f"{effect} {np.nanmin(daf):.3f}-{np.nanmax(daf):.3f}")
        text = (
            f"SectionResponse({self.sections.size} sections, {self.method}, {self.modes} "
            f"modes: DAF {', '.join(parts)}"
        )
        if self.lost_contact:
            text += "; CONTACT LOST (outside validity)"
        return text + ")"
