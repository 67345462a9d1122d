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

**Both faces of a support.**  The shear jumps by the reaction at an interior support, and the
design shear is on the larger face.  Every shear here is on a named face (``side``:
``"left"``, just left of the station, the default; ``"right"``, just right of it), the
exact part from :func:`~vbi_lib.beam_statics.continuous_statics` on that face and the modal
part from the third derivative of the modes in the span on that side.  :meth:`Crossing.sections
<vbi_lib.models.results.Crossing.sections>` gives, at a support station, the face whose
static shear is the larger in size (:func:`governing_faces`) and names it
(:attr:`SectionResponse.faces`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property, lru_cache
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import display
from ..beam_statics import (
    EFFECTS,
    QUANTITY,
    SIDES,
    StaticEnvelope,
    continuous_statics,
    effect_index,
    envelope,
    static_envelope,
    support_face,
)
from ..bridges import Bridge
from ..modes import BeamModes

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "EFFECTS",
    "FACES",
    "METHODS",
    "SectionResponse",
    "from_first_load",
    "governing_faces",
    "section_histories",
    "section_history",
    "snap_to_supports",
    "static_counterpart",
]

#: How section responses are computed from the modal coordinates.
METHODS = ("mode-acceleration", "mode-displacement")
#: Which face of a support a section's shear is given on: the larger (the design shear), or
#: one side (:data:`vbi_lib.beam_influence.SIDES`).
FACES = ("governing", *SIDES)
_ORDER = {"displacement": 0, "moment": 2, "shear": 3}


def check_method(method: object) -> str:
    """A method name of :data:`METHODS`."""
    if method not in METHODS:
        raise ValueError(f"method={method!r} is not known; use one of {', '.join(METHODS)}")
    return str(method)


def check_side(side: object, allowed: tuple[str, ...] = SIDES) -> str:
    """A face name of ``allowed``; ``ValueError`` naming them otherwise."""
    if side not in allowed:
        raise ValueError(f"side={side!r} is not known; use one of {', '.join(allowed)}")
    return str(side)


def _sides(side: str | tuple[str, ...], n: int) -> tuple[str, ...]:
    if isinstance(side, str):
        return (check_side(side),) * n
    sides = tuple(check_side(s) for s in side)
    if len(sides) != n:
        raise ValueError(f"side={side!r} must be one face, or one for each of the {n} sections")
    return sides


def _interior_support(modes: BeamModes, x: np.ndarray) -> np.ndarray:
    """Whether each station is an interior support (to rounding), ``(n_x,)``."""
    inner = modes.supports[1:-1]
    if inner.size == 0:
        return np.zeros(x.shape, dtype=bool)
    return np.abs(x[:, None] - inner[None, :]).min(axis=1) <= 1e-9 * modes.bridge.length


def snap_to_supports(supports: np.ndarray, x: np.ndarray) -> np.ndarray:
    """``x`` with every station within 1e-9 of the bridge's length of a support moved onto it
    (so that ``L - x`` of a support, or a station typed to a few digits, is that support)."""
    supports = np.asarray(supports, dtype=float)
    x = np.array(x, dtype=float)
    near = np.abs(x[..., None] - supports) <= 1e-9 * supports[-1]
    hit = near.any(axis=-1)
    x[hit] = supports[np.argmax(near[hit], axis=-1)]
    return x


def _third_right(modes: BeamModes, x: np.ndarray) -> np.ndarray:
    """The third derivative of the modes just right of stations ``x``, ``(n_x, N)``.

    In span ``j`` (``s`` from its left support) mode ``n`` has ``phi''' = k^3 (-a cos ks +
    b sin ks - c e^(-ks) + d e^(-k (L_j - s)))``; just right of a support, ``s = 0`` of the
    span on its right.
    """
    supports = modes.supports
    j = np.clip(np.searchsorted(supports, x, side="right") - 1, 0, supports.size - 2)
    k = modes.wavenumber[None, :]
    coef = modes.coefficients[:, j, :].transpose(1, 0, 2)  # (n_x, N, 4)
    length = (supports[j + 1] - supports[j])[:, None]
    return k**3 * (-coef[..., 0] - coef[..., 2] + coef[..., 3] * np.exp(-k * length))


def _modal_shapes(
    modes: BeamModes, effect: str, x: np.ndarray, side: str | tuple[str, ...] = "left"
) -> np.ndarray:
    """``r_n(x)``, shape ``(n_x, N)``: phi (displacement), EI phi'' (moment) or EI phi'''
    (the shear, on face ``side`` at an interior support: one for all stations or one each)."""
    values = modes.derivative(x, _ORDER[effect])
    if effect == "shear":
        right = np.array([s == "right" for s in _sides(side, x.size)], dtype=bool)
        right &= _interior_support(modes, x)
        if right.any():
            values[right] = _third_right(modes, x[right])
    return values if effect == "displacement" else modes.bridge.EI * values


def section_history(
    modes: BeamModes,
    q: np.ndarray,
    loads: np.ndarray,
    positions: np.ndarray,
    sections: np.ndarray,
    effect: str,
    method: str = "mode-acceleration",
    side: str | tuple[str, ...] = "left",
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
    side
        Face of the shear at an interior support (``"left"`` or ``"right"``), one for every
        section or one each.
    """
    effect_index(effect)
    check_method(method)
    sides = _sides(side, sections.size)
    shapes = _modal_shapes(modes, effect, sections, sides)  # (n_s, N)
    values = q @ shapes.T
    if method == "mode-displacement":
        return values
    bridge = modes.bridge
    length = bridge.length
    e = EFFECTS.index(effect)
    groups = [(face, np.array([s == face for s in sides])) for face in sorted(set(sides))]
    for i in range(loads.shape[1]):
        on = (positions[:, i] >= 0.0) & (positions[:, i] <= length) & (loads[:, i] != 0.0)
        if not on.any():
            continue
        a = positions[on, i]
        truncated = -(modes.shape(a) / modes.omega**2) @ shapes.T
        exact = np.empty_like(truncated)
        for face, take in groups:
            statics = continuous_statics(
                sections[None, take], a[:, None], bridge.spans, bridge.EI, side=face
            )
            exact[:, take] = (-statics.deflection, statics.moment, statics.shear)[e]
        values[on] += loads[on, i, None] * (exact - truncated)
    return values


def section_histories(
    modes: BeamModes,
    q: np.ndarray,
    loads: np.ndarray,
    positions: np.ndarray,
    sections: np.ndarray,
    method: str = "mode-acceleration",
    side: str | tuple[str, ...] = "left",
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Displacement, moment and shear histories at sections, each ``(n_time, n_s)``.

    The same as :func:`section_history` for each effect, with the exact statics of each
    axle position computed once for the three.
    """
    check_method(method)
    sides = _sides(side, sections.size)
    shapes = [_modal_shapes(modes, effect, sections, sides) for effect in EFFECTS]
    values = [q @ r.T for r in shapes]
    if method == "mode-displacement":
        return tuple(values)
    bridge = modes.bridge
    length = bridge.length
    groups = [(face, np.array([s == face for s in sides])) for face in sorted(set(sides))]
    for i in range(loads.shape[1]):
        on = (positions[:, i] >= 0.0) & (positions[:, i] <= length) & (loads[:, i] != 0.0)
        if not on.any():
            continue
        a = positions[on, i]
        static_q = -modes.shape(a) / modes.omega**2  # (n_on, N)
        exact = [np.empty((a.size, sections.size)) for _ in EFFECTS]
        for face, take in groups:
            statics = continuous_statics(
                sections[None, take], a[:, None], bridge.spans, bridge.EI, side=face
            )
            for e, part in enumerate((-statics.deflection, statics.moment, statics.shear)):
                exact[e][:, take] = part
        for e in range(len(EFFECTS)):
            values[e][on] += loads[on, i, None] * (exact[e] - static_q @ shapes[e].T)
    return tuple(values)


def from_first_load(function, modes, q, loads, positions, sections, *args):  # noqa: ANN001, ANN002, ANN201
    """``function`` (:func:`section_history` or :func:`section_histories`) from the node
    before the first load on the bridge, exact zeros before it.

    Before the first axle reaches the bridge it is at rest and unloaded (every modal
    coordinate and load exactly 0), so every section response there is exactly 0; on a long
    approach most of a crossing's nodes are there.
    """
    loaded = np.flatnonzero((loads != 0.0).any(axis=1) | (q != 0.0).any(axis=1))
    start = max(0, int(loaded[0]) - 1) if loaded.size else q.shape[0]
    part = function(modes, q[start:], loads[start:], positions[start:], sections, *args)
    out = []
    for values in part if isinstance(part, tuple) else (part,):
        full = np.zeros((q.shape[0], sections.size))
        full[start:] = values
        out.append(full)
    return tuple(out) if isinstance(part, tuple) else out[0]


def _modal_envelope(
    modes: BeamModes,
    sections: np.ndarray,
    axle_loads: np.ndarray,
    axle_offsets: np.ndarray,
    sides: tuple[str, ...],
) -> StaticEnvelope:
    shapes = [_modal_shapes(modes, effect, sections, sides) for effect in EFFECTS]

    def influence(a: np.ndarray) -> np.ndarray:
        static = -modes.shape(a) / modes.omega**2  # (n_a, N): q_n under a unit load
        return np.stack([static @ r.T for r in shapes])

    result = envelope(influence, modes.supports, sections, axle_loads, axle_offsets)
    faces = tuple(
        support_face(float(x), modes.supports, s) for x, s in zip(sections, sides, strict=True)
    )
    return replace(result, faces=faces)


def static_counterpart(
    modes: BeamModes,
    sections: np.ndarray,
    axle_loads: np.ndarray,
    axle_offsets: np.ndarray,
    method: str = "mode-acceleration",
    side: str | tuple[str, ...] = "left",
) -> StaticEnvelope:
    """The static envelope the method's DAF divides by: exact, or from the N modes.

    ``side``: the face of the shear at interior supports, one for all sections or one each.
    Memoised: a study asks for the same bridge, axles and sections crossing after crossing.
    """
    method = check_method(method)
    key = tuple(float(x) for x in np.ravel(sections))
    sides = _sides(side, len(key))
    loads = tuple(float(p) for p in np.ravel(axle_loads))
    offsets = tuple(float(o) for o in np.ravel(axle_offsets))
    if method == "mode-displacement":
        return _cached_modal(modes, key, loads, offsets, sides)
    return _cached_exact(modes.bridge.spans, modes.bridge.EI, key, loads, offsets, sides)


def governing_faces(
    modes: BeamModes,
    sections: np.ndarray,
    axle_loads: np.ndarray,
    axle_offsets: np.ndarray,
    method: str = "mode-acceleration",
) -> tuple[str, ...]:
    """The face of the design shear at each section, by the method's statics.

    At an interior support the face whose static shear (its larger extreme in size) is the
    larger, ``"left"`` when they tie; ``"left"`` elsewhere (one face only).
    """
    sections = np.asarray(sections, dtype=float)
    inner = _interior_support(modes, sections)
    if not inner.any():
        return ("left",) * sections.size
    left = static_counterpart(modes, sections, axle_loads, axle_offsets, method, "left")
    right = static_counterpart(modes, sections, axle_loads, axle_offsets, method, "right")
    e = EFFECTS.index("shear")

    def size(env: StaticEnvelope) -> np.ndarray:
        return np.maximum(np.abs(env.maximum[e]), np.abs(env.minimum[e]))

    larger = inner & (size(right) > size(left) * (1.0 + 1e-12))
    return tuple("right" if bigger else "left" for bigger in larger)


def _frozen(envelope_: StaticEnvelope) -> StaticEnvelope:
    for array in vars(envelope_).values():
        if isinstance(array, np.ndarray):
            array.setflags(write=False)
    return envelope_


@lru_cache(maxsize=256)
def _cached_exact(  # noqa: ANN202
    spans: tuple,
    EI: float,
    sections: tuple,
    loads: tuple,
    offsets: tuple,
    sides: tuple,  # noqa: N803
):
    return _frozen(static_envelope(spans, EI, sections, loads, offsets, side=sides))


@lru_cache(maxsize=256)
def _cached_modal(modes: BeamModes, sections: tuple, loads: tuple, offsets: tuple, sides: tuple):  # noqa: ANN202
    arrays = (np.array(sections), np.array(loads), np.array(offsets))
    return _frozen(_modal_envelope(modes, *arrays, sides))


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
        The static counterpart (:class:`~vbi_lib.beam_statics.StaticEnvelope`); its
        ``faces`` are the faces the shear is given on (:attr:`faces`).
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

    @property
    def faces(self) -> tuple[str, ...]:
        """Face of the shear at each section: ``"left"`` or ``"right"`` at a support (the
        governing, larger one unless another was asked for), ``""`` inside a span."""
        return self.static.faces or ("",) * self.sections.size

    def history(self, effect: str) -> np.ndarray:
        """History of one effect at every section, ``(n_time, n_s)``."""
        return (self.displacement, self.moment, self.shear)[effect_index(effect)]

    def _extremes(self, pick: str) -> np.ndarray:
        histories = (self.displacement, self.moment, self.shear)
        result = np.stack([getattr(h, pick)(axis=0) for h in histories])  # (3, n_s)
        result.setflags(write=False)
        return result

    @cached_property
    def maximum(self) -> np.ndarray:
        """Largest value of each effect over the crossing, ``(3, n_s)`` (computed once)."""
        return self._extremes("max")

    @cached_property
    def minimum(self) -> np.ndarray:
        """Smallest value of each effect over the crossing, ``(3, n_s)`` (computed once)."""
        return self._extremes("min")

    @property
    def governing(self) -> np.ndarray:
        """``+1`` where the static maximum is the larger in size, else ``-1``; ``(3, n_s)``.

        Where the two are equal to rounding (1e-9 of their size: the shear at midspan of a
        symmetric span, ``+-P/2``), the sense whose dynamic extreme is the larger in size
        governs, so that rounding never picks the smaller DAF.
        """
        high, low = self.static.maximum, -self.static.minimum
        tie = np.abs(high - low) <= 1e-9 * np.maximum(np.abs(high), np.abs(low))
        dynamic = np.where(self.maximum >= -self.minimum, 1, -1)
        return np.where(tie, dynamic, np.where(high > low, 1, -1))

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

        Columns: section, effect, face (of the shear at a support, ``left`` or ``right``;
        else empty), sense (``max``/``min``), whether it governs the DAF, the effect's unit,
        the dynamic and static extremes (in that unit), their ratio (the DAF; NaN where the
        static extreme is 0), the time and first-axle position of the dynamic extreme, the
        three effects at that instant and ``lost contact``.
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
                        "face": self.faces[i] if effect == "shear" else "",
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
