"""Warnings the library raises when a result leaves the model's range of validity.

Every warning is a :class:`VbiWarning`, so one filter silences or raises them all
(``warnings.simplefilter("error", vbi.VbiWarning)``).  Results that leave validity also say so
in their ``notes`` and summary columns; the warning is the signal for scripts.

The ranges of validity of the inputs, and the checks that raise
:class:`OutsideValidityWarning`, are in :mod:`vbi_lib.ranges`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "LOST_CONTACT_LABEL",
    "ContactFlags",
    "ContactLossWarning",
    "CostWarning",
    "FailedRowsWarning",
    "OutsideValidityWarning",
    "TruncationWarning",
    "UnresolvedRoadWarning",
    "VbiWarning",
    "WorkerLostWarning",
    "contact_note",
    "flight_note",
    "mark_lost_contact",
]

#: The legend entry of the crosses :func:`mark_lost_contact` draws.
LOST_CONTACT_LABEL = "contact lost (outside validity)"


class VbiWarning(UserWarning):
    """Base class of the library's warnings."""


class ContactLossWarning(VbiWarning):
    """The contact force fell below zero: the tyre would have to pull the road down.

    The study's sprung mass is attached to the road; a real tyre can only push.  A crossing in
    which the computed contact force becomes tensile is outside the model's validity, and its
    DAF is not a prediction of a real truck's effect.
    """


class OutsideValidityWarning(VbiWarning):
    """An input lies inside its hard limits but outside the model's intended use.

    The result is computed, but it is not a prediction the model was built and checked for;
    :data:`vbi_lib.ranges.RANGES` gives the intended (soft) range of each input and why.
    """


class TruncationWarning(VbiWarning):
    """A model's own truncation may mislead for this crossing: the modal model's ``modes``
    leave out a span's own fundamental, or its N-mode series DAF and its mode-acceleration DAF
    (the headline, which converges) differ by more than 1 %.  The note says by how much."""


class UnresolvedRoadWarning(OutsideValidityWarning):
    """A crossing's contact force is set by a road feature sharper than the profile's sampling.

    A point contact with a damper (the study's sprung mass, a bilateral axle, a damped tyre
    without a footprint) presses on the road with ``c v dr/dx``; over a feature whose rise
    fits within one sample interval (a step, a joint's edge) that slope, and the force, grow
    as the sampling is refined, so the peak contact force is the sampling's, not the road's.
    The test is :func:`vbi_lib.vehicles.footprint.unresolved_road_note`; a ``footprint``
    (the tyre's contact length) makes the force converge.

    A subclass of :class:`OutsideValidityWarning` (the road's sampling is an input outside
    what the contact force needs), of its own so that a study that reads only the bridge's
    response, which converges whatever the sampling, can silence it alone.
    """


class FailedRowsWarning(VbiWarning):
    """Some rows of a study failed; the others are kept and the ``error`` column says why."""


class WorkerLostWarning(VbiWarning):
    """A worker process of a study died (killed, perhaps by the out-of-memory killer); the
    chunks it held were run again, and the study went on."""


class CostWarning(VbiWarning):
    """A computation about to start is estimated to take longer than about a minute."""


class ContactFlags:
    """The two loss-of-contact flags of a result, from its ``min_contact_force_ratio`` and
    ``flight_fraction`` (one crossing: numbers; several: arrays of one shape).

    Mixed into every result that carries those two fields, so that all of them mean the same.
    """

    min_contact_force_ratio: float | np.ndarray
    flight_fraction: float | np.ndarray

    @property
    def outside_validity(self) -> bool | np.ndarray:
        """A bilateral contact force became tensile on the bridge: the tyre would have pulled
        the road down, the model's contact assumption failed and the DAF is no prediction
        (a ``bool`` for one crossing, else an array shaped as ``min_contact_force_ratio``)."""
        flag = np.asarray(self.min_contact_force_ratio) < 0.0
        return flag if flag.ndim else bool(flag)

    @property
    def lost_contact(self) -> bool | np.ndarray:
        """An axle lost contact on the bridge: tension (:attr:`outside_validity`) or a tyre's
        flight (a quarter car's, modelled and so inside validity)."""
        flag = (np.asarray(self.min_contact_force_ratio) < 0.0) | (
            np.asarray(self.flight_fraction) > 0.0
        )
        return flag if flag.ndim else bool(flag)


def contact_note(min_ratio: float, tension_fraction: float) -> str:
    """One sentence on a loss of contact, for notes and warnings.

    >>> contact_note(-1.5, 0.12)[:62]
    'contact lost: the contact force fell to -1.50 times the weight'
    """
    return (
        f"contact lost: the contact force fell to {min_ratio:.2f} times the weight and was "
        f"tensile for {tension_fraction:.0%} of the time on the bridge; the model assumes the "
        "tyre never leaves the road, so this result is outside its validity (a real tyre "
        "would lift off)"
    )


def flight_note(flight_fraction: float) -> str:
    """One sentence on tyres that left the road, for notes (no warning: it is modelled).

    >>> flight_note(0.05)[:48]
    'a tyre left the road for 5% of the time on the b'
    """
    text = (
        f"a tyre left the road for {flight_fraction:.0%} of the time on the bridge: its contact "
        "force cannot pull, so the wheel flew and landed again (modelled, within validity)"
    )
    if flight_fraction > 0.25:
        text += (
            "; a wheel that bounces this much makes the crossing a chain of impacts whose "
            "timing grows sensitive to every input (halve dt to see how much the DAF moves)"
        )
    return text


def mark_lost_contact(
    ax: Axes,
    x: object,
    y: object,
    lost: object,
    *,
    color: str = "k",
    label: str | None = LOST_CONTACT_LABEL,
    size: float = 6.0,
) -> int:
    """Cross the points of the crossings that lost contact, as every figure of the book does.

    A crossing whose contact force turned tensile is outside the model's validity; a figure
    that shows its DAF marks it with a cross over its point, so that no such value is shown
    bare.

    Parameters
    ----------
    ax
        The matplotlib axes the points are drawn on.
    x, y
        The points' coordinates, one per crossing (array-likes of one length).
    lost
        Whether each crossing lost contact (``lost_contact``), booleans of the same length.
    color
        Colour of the crosses (that of the points' series, or black).
    label
        Legend entry, given once per axes (a second call with the same label adds none);
        ``None`` for no entry.
    size
        Marker size [points].

    Returns
    -------
    int
        How many points were crossed.

    Raises
    ------
    ValueError
        ``x``, ``y`` and ``lost`` differ in length.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> mark_lost_contact(ax, [1, 2, 3], [1.2, 1.5, 2.4], [False, True, True])
    2
    >>> plt.close(fig)
    """
    xs, ys = np.asarray(x, dtype=float).ravel(), np.asarray(y, dtype=float).ravel()
    out = np.asarray(lost, dtype=bool).ravel()
    if not xs.size == ys.size == out.size:
        raise ValueError(
            f"x, y and lost must have one entry per crossing; got {xs.size}, {ys.size} and "
            f"{out.size}"
        )
    if label is not None and label in ax.get_legend_handles_labels()[1]:
        label = None
    if out.any():
        ax.plot(xs[out], ys[out], "x", color=color, ms=size, mew=1.2, ls="none", label=label,
                zorder=5)  # fmt: skip
    return int(out.sum())
