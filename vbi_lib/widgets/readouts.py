"""The explorers' readouts: the DAF in words, never without the model's validity beside it.

Every readout that shows a DAF says in the same sentence whether the truck kept contact with
the road.  The study's sprung mass is attached to the road; when the computed contact force
becomes tensile a real tyre would lift off, so such a DAF is printed only with the words
"outside the model's validity" (see :mod:`vbi_lib.validity`).  A quarter car's tyre can
leave the road: its flights are modelled (the wheel flies and lands again), so the DAF stays
valid and the readout says for how long the wheel was off the road.  Code allowances come from
:mod:`vbi_lib.amplification` as DAFs (``1 + IM``).

>>> daf_text([1.0874, float("nan")])
'DAF 1.087'
>>> daf_text([1.0874, 1.05])
'DAF 1.087 (span 1), 1.050 (span 2)'
"""

from __future__ import annotations

import html
from collections.abc import Callable, Sequence

import numpy as np

from .. import amplification, display
from ..bridges import Bridge
from ..models import Crossing

__all__ = [
    "code_allowances",
    "crossing_html",
    "daf_text",
    "error_html",
    "largest_daf",
    "sweep_html",
]

_BAD = "color:#a40000"
_GOOD = "color:#1f6f1f"
_WARN = "color:#8a5a00"


def code_allowances(bridge: Bridge) -> dict[str, float]:
    """The design codes' DAF (``1 + IM``) for this bridge, by code.

    AASHTO LRFD (Table 3.6.2.1-1, all limit states but fatigue and joints), AASHTO Standard
    (``1 + 50 / (L + 125)``, ``L`` the span in feet) and OHBDC 1983 (from the first frequency).
    """
    return {
        "AASHTO LRFD": 1.0 + amplification.aashto_lrfd_allowance(),
        "AASHTO Standard": 1.0 + float(amplification.aashto_standard_impact(bridge.span)),
        "OHBDC 1983": 1.0 + float(amplification.ohbdc_1983_allowance(bridge.first_frequency_hz)),
    }


def daf_text(dafs: Sequence[float]) -> str:
    """``"DAF 1.087"`` for one span, one value per span otherwise (NaN spans left out; none
    finite: says that no span was pushed down)."""
    values = [float(d) for d in dafs if np.isfinite(d)]
    if not values:
        return "no DAF (no span was pushed down during the crossing)"
    if len(values) == 1:
        return f"DAF {values[0]:.3f}"
    return "DAF " + ", ".join(f"{d:.3f} (span {j + 1})" for j, d in enumerate(values))


def _codes(bridge: Bridge) -> str:
    codes = ", ".join(f"{name} {value:.2f}" for name, value in code_allowances(bridge).items())
    return f"design codes' DAF: {codes}"


#: The readout's line when an input is outside its intended range (the note line says which).
OUTSIDE = (
    f'<span style="{_BAD}"><b>inputs outside their intended ranges</b> (the note below '
    "says which): these results are outside the model's validity</span>"
)


def _contact(min_ratio: float, tension: float) -> str:
    if min_ratio < 0.0:
        return (
            f'<span style="{_BAD}"><b>the tyre would leave the road</b> (the contact force '
            f"fell to {min_ratio:.2f} &times; the weight and was tensile for {tension:.0%} of "
            "the time on the bridge): this DAF is outside the model's validity</span>"
        )
    return (
        f'<span style="{_GOOD}">contact held</span> (smallest contact force '
        f"{min_ratio:.2f} &times; the weight)"
    )


def _wheel(min_ratio: float, flight: float) -> str:
    """A tyre that can leave the road: whether and for how long it did (modelled, valid)."""
    if flight > 0.0:
        text = (
            f'<span style="{_WARN}"><b>the wheel left the road for {flight:.0%} of the time on '
            "the bridge</b></span> (the tyre cannot pull: the wheel flew and landed again, "
            "which the quarter car models, so this DAF counts the landings)"
        )
        if flight > 0.25:
            text += (
                "; a wheel bouncing this much makes the DAF sensitive to every input, so read "
                "it as a rough value"
            )
        return text
    return (
        f'<span style="{_GOOD}">the wheel stayed on the road</span> (smallest tyre force '
        f"{min_ratio:.2f} &times; the weight)"
    )


def crossing_html(
    crossing: Crossing, road: str, model: str, vehicle: str, outside: bool = False
) -> str:
    """The readout of one crossing: DAF and contact, codes, inputs and the model that ran.

    ``outside``: an input is outside its intended range, which the readout then says
    under the DAF (the explorer's note line names the input).

    ``road``, ``model`` and ``vehicle`` describe the inputs in words
    (:meth:`~vbi_lib.widgets.Scenario.road_text` and its siblings).  Whether the contact
    could leave the road is read from the crossing's vehicle: a tyre that can (a quarter
    car) gets the flight fraction, a contact that cannot (the study's sprung mass) the
    tension check.
    """
    bridge = crossing.bridge
    if crossing.system.has_unilateral:
        contact = "quarter car: " + _wheel(crossing.min_contact_force_ratio,
                                           crossing.flight_fraction)  # fmt: skip
    else:
        contact = "sprung mass: " + _contact(
            crossing.min_contact_force_ratio, crossing.tension_fraction
        )
    lines = [
        f"<b>{daf_text(crossing.daf)}</b> &mdash; {contact}",
        *([OUTSIDE] if outside else []),
        f"largest contact force {crossing.contact_force_amplification:.2f} &times; the weight; "
        + _codes(bridge),
        f"bridge {display.fmt(bridge.span, 'length')} &times; {bridge.n_spans}, "
        f"f&#8321; {bridge.first_frequency_hz:.2f} Hz; speed "
        f"{display.fmt(crossing.speed, 'speed')}; road: {html.escape(road, quote=False)}",
        f"truck: {html.escape(vehicle, quote=False)}",
        f"model: {html.escape(model, quote=False)}; largest step {crossing.dt * 1e3:.2f} ms",
    ]
    return '<div class="vbi-readout">' + "<br>".join(lines) + "</div>"


def sweep_html(
    daf: np.ndarray,
    min_contact_force_ratio: np.ndarray,
    bridge: Bridge,
    what: Callable[[int], str],
    model: str,
    done: int | None = None,
    flight_fraction: np.ndarray | None = None,
    outside: bool = False,
) -> str:
    """The readout of a sweep: the largest valid DAF, how many lost contact, how many flew.

    Parameters
    ----------
    daf, min_contact_force_ratio
        ``(n, 2)`` DAF of each span and ``(n,)`` smallest contact force over the weight of
        each crossing (NaN rows: not computed yet).
    bridge
        For the code allowances.
    what
        A crossing's setting in words (``"at 55 mph"``), from its index.
    model
        Which model ran, in words.
    done
        Crossings computed so far, while the sweep runs.
    flight_fraction
        ``(n,)`` fraction of the time on the bridge a tyre was off the road (a quarter car's
        modelled flights: their DAFs stay valid); ``None``: no tyre could leave the road.
    outside
        An input is outside its intended range: no DAF is then called valid, and the
        readout says why.

    A computed crossing with no finite DAF (no span pushed down: a wheel that flew over
    the bridge) is counted and said, not taken for one still to compute.
    """
    daf = largest_daf(np.asarray(daf))
    ratio = np.asarray(min_contact_force_ratio, dtype=float)
    computed = np.isfinite(ratio)  # every computed crossing has a smallest contact force
    no_daf = computed & ~np.isfinite(daf)
    lost = computed & (ratio < 0.0)
    flight = np.zeros(daf.shape) if flight_fraction is None else np.asarray(flight_fraction)
    flew = computed & ~lost & (flight > 0.0)
    kept = computed & ~lost & ~no_daf
    parts = []
    if done is not None:
        parts.append(f"<i>computing: {done} of {daf.size} crossings done&hellip;</i>")
    if kept.any():
        best = int(np.flatnonzero(kept)[np.argmax(daf[kept])])
        if outside:
            among = "that kept contact or flew (modelled)" if flew.any() else "that kept contact"
        else:
            among = "within the model's validity" if flew.any() else "that kept contact"
        parts.append(f"<b>largest DAF {daf[best]:.3f}</b> {what(best)}, among crossings {among}")
    if outside:
        parts.append(OUTSIDE)
    if no_daf.any():
        parts.append(
            f'<span style="{_WARN}"><b>{int(no_daf.sum())} of {int(computed.sum())} crossings '
            "have no DAF</b>: no span was pushed down while the truck was on it (a wheel "
            "that flew over the bridge)</span>"
        )
    if flew.any():
        longest = int(np.flatnonzero(flew)[np.argmax(flight[flew])])
        parts.append(
            f'<span style="{_WARN}"><b>the wheel left the road in {int(flew.sum())} of '
            f"{int(computed.sum())} crossings</b> (marked &times;; longest "
            f"{flight[longest]:.0%} of the time on the bridge, {what(longest)}): the tyre "
            "flew and landed again, which the quarter car models, so their DAFs count</span>"
        )
    n_lost = int(lost.sum())
    if n_lost:
        worst = int(np.flatnonzero(lost)[np.argmax(daf[lost])])
        parts.append(
            f'<span style="{_BAD}"><b>{n_lost} of {int(computed.sum())} crossings lost '
            f"contact</b> (marked &times;): the tyre would leave the road, so their DAFs (up to "
            f"{daf[worst]:.3f} {what(worst)}) are outside the model's validity</span>"
        )
    elif computed.any() and not flew.any():
        parts.append(f'<span style="{_GOOD}">every crossing kept contact</span>')
    parts.append(_codes(bridge))
    parts.append(f"model: {html.escape(model, quote=False)}")
    return '<div class="vbi-readout">' + "<br>".join(parts) + "</div>"


def largest_daf(daf: np.ndarray) -> np.ndarray:
    """The larger DAF of the spans, row by row, shape ``(n,)`` (NaN where none is computed)."""
    out = np.full(daf.shape[0], np.nan)
    rows = np.isfinite(daf).any(axis=1)
    out[rows] = np.nanmax(daf[rows], axis=1)
    return out


def error_html(message: str) -> str:
    """The readout when the controls describe no valid crossing: no number, the reason."""
    return (
        f'<div class="vbi-readout" style="{_BAD}"><b>No result for these settings.</b> '
        f"{html.escape(message, quote=False)}</div>"
    )


def notice_html(message: str) -> str:
    """A note on a control's value (refused or clamped); empty text gives an empty note."""
    if not message:
        return ""
    text = html.escape(message, quote=False)
    return f'<div class="vbi-notice" style="color:#8a5a00">&#9888; {text}</div>'
