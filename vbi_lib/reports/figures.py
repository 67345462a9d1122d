"""The report's figures: each a block of heading, text and an inline SVG scaled to the page.

Matplotlib draws them (``svg.hashsalt`` set by the template, metadata dropped, so the same
report gives the same SVG); long histories are cut to each bucket's extremes, every peak
kept (:func:`_decimated`).
"""

from __future__ import annotations

import io
import re

import numpy as np

from .. import display
from ..units import ft
from ..vehicles import as_system
from .analysis import ReportAnalysis
from .render import _arrow, _e, _p, _speed, block, number, position_html

__all__ = [
    "envelopes_figure",
    "figure_html",
    "position_figure",
    "road_figure",
    "sweep_figure",
    "worst_figure",
    "worst_title",
    "worst_window",
]


def figure_html(fig: object, caption: str = "") -> str:
    """A matplotlib figure as inline SVG, scaled to the page's width (the figure is closed)."""
    import matplotlib.pyplot as plt

    buffer = io.StringIO()
    fig.savefig(buffer, format="svg", bbox_inches="tight", metadata={"Date": None})
    plt.close(fig)
    svg = buffer.getvalue()
    svg = re.sub(r"<metadata>.*?</metadata>", "", svg[svg.index("<svg") :], flags=re.DOTALL)
    note = f'<figcaption class="vbi-caption">{_e(caption)}</figcaption>' if caption else ""
    return f'<figure class="vbi-figure">{svg}{note}</figure>'


# ---------------------------------------------------------------------------- figures
def sweep_figure(analysis: ReportAnalysis) -> str:
    """DAF against speed, one panel per effect."""
    import matplotlib.pyplot as plt

    effects = list(analysis.inputs.effects)
    fig, axes = plt.subplots(len(effects), 1, figsize=(7.2, 2.5 * len(effects)), sharex=True)
    axes = np.atleast_1d(axes)
    for ax, effect in zip(axes, effects, strict=True):
        analysis.sweep.plot(ax, effect=effect, allowance=analysis.allowances.aashto_lrfd)
        if ax is not axes[-1]:
            ax.set_xlabel("")
    fig.tight_layout()
    text = (
        "One crossing's DAF depends strongly on speed: the sweep runs from half the slowest to "
        f"1.2 times the fastest requested speed with {analysis.sweep.vehicle}. Solid lines "
        "forward, dashed backward; the dotted line is AASHTO LRFD's 1 + IM; crosses mark "
        "crossings whose contact became tensile (outside validity)."
    )
    return block("DAF against speed", _p(text), figure_html(fig), css="vbi-keep")


def envelopes_figure(analysis: ReportAnalysis) -> str:
    """Static and dynamic envelopes along the bridge, one panel per effect."""
    import matplotlib.pyplot as plt

    effects = list(analysis.inputs.effects)
    fig, axes = plt.subplots(len(effects), 1, figsize=(7.2, 2.3 * len(effects)), sharex=True)
    axes = np.atleast_1d(axes)
    for ax, effect in zip(axes, effects, strict=True):
        analysis.envelopes.plot(ax, effect=effect)
        if ax is not axes[-1]:
            ax.set_xlabel("")
    fig.tight_layout()
    text = (
        "The largest and smallest value of each effect at every station along the bridge: "
        "static (dashed: the axles crawling across, every position, the directions asked) and "
        f"dynamic (solid: over the requested crossings of {analysis.envelopes.vehicle}). The "
        "shear is drawn on both faces of each interior support, so it jumps there by the "
        "reaction."
    )
    return block("Envelopes along the bridge", _p(text), figure_html(fig), css="vbi-keep")


def _decimated(x: np.ndarray, y: np.ndarray, count: int = 1200) -> tuple[np.ndarray, np.ndarray]:
    """``(x, y)`` cut to about ``2 count`` points for a plot, keeping each bucket's smallest
    and largest value in order (so every peak is drawn)."""
    if x.size <= 2 * count:
        return x, y
    edges = np.linspace(0, x.size, count + 1).astype(int)
    keep = []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        part = y[lo:hi]
        keep += sorted({lo + int(np.argmin(part)), lo + int(np.argmax(part))})
    keep = np.array(keep)
    return x[keep], y[keep]


def worst_figure(analysis: ReportAnalysis) -> str:
    """The worst requested crossing's midspan displacements and contact forces."""
    import matplotlib.pyplot as plt

    crossing = analysis.worst
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.2, 4.4), sharex=True)
    x = display.value(crossing.position - crossing.bridge_start, "length")
    for j in range(crossing.bridge.n_spans):
        y = crossing.midspan_displacement[:, j] / crossing.static_deflection
        top.plot(*_decimated(x, y), lw=1, label=f"span {j + 1}")
    system = as_system(crossing.vehicle)
    ratios = crossing.axle_contact_force / system.static_loads[None, :]
    for a in range(system.n_axles):
        label = f"axle {a + 1}" if system.n_axles > 1 else None
        bottom.plot(*_decimated(x, ratios[:, a]), lw=1, label=label)
    bottom.axhline(0.0, color="k", lw=0.8)
    for ax in (top, bottom):
        ax.axvspan(0, display.value(crossing.bridge.length, "length"), color="0.93", zorder=0)
        if len(ax.get_lines()) > 2:
            ax.legend(loc="best", fontsize="x-small")
    top.set_xlim(*worst_window(analysis))
    top.set_ylabel("displacement / static [-]")
    bottom.set_ylabel("contact force / load [-]")
    bottom.set_xlabel(display.label("first axle from the start of the bridge", "length"))
    top.set_title(worst_title(analysis), fontsize="small")
    fig.tight_layout()
    direction, _, _ = analysis.worst_key
    seen = "as the vehicle sees it, from the far support" if direction == "backward" else "forward"
    text = (
        "The crossing with the largest valid DAF: each span's midspan displacement over the "
        "static deflection the crossing divides by, and each axle's contact force over its "
        "static load, against the first axle's position from the bridge's first support "
        f"({seen}). Where a contact force reaches zero a tyre leaves the road; below zero a "
        "bilateral contact would pull on it."
    )
    return block("The worst requested crossing", _p(text), figure_html(fig), css="vbi-keep")


def road_figure(analysis: ReportAnalysis) -> str:
    """The deck profile and the end of the approach, as a figure (no heading)."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.2, 2.4))
    analysis.roughness.plot(ax, road=analysis.inputs.road)
    fig.tight_layout()
    return figure_html(fig)


def position_figure(analysis: ReportAnalysis) -> str:
    """The position study: its table and figure."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.2, 2.8))
    analysis.position.plot(ax)
    fig.tight_layout()
    text = (
        "Where the deck's bumps lie relative to midspan matters as much as how large they are. "
        "Here the deck's roughness is moved along the bridge in even steps (wrapping round its "
        "ends, so the same roughness stays on the bridge) and each requested speed is run "
        "again, forward; the DAF shown is the largest of the spans' midspan displacement DAFs."
    )
    return block("Sensitivity to the profile's position", _p(text), position_html(analysis),
                 figure_html(fig), css="vbi-keep")  # fmt: skip


def worst_window(analysis: ReportAnalysis) -> tuple[float, float]:
    """Stations shown in the worst crossing's plots, in display units: the end of the
    approach (a quarter of the bridge's length) and the bridge with the vehicle leaving it."""
    length = analysis.inputs.bridge.length
    wheelbase = as_system(analysis.worst.vehicle).wheelbase
    return (
        display.value(-0.25 * length, "length"),
        display.value(1.02 * length + wheelbase, "length"),
    )


def worst_title(analysis: ReportAnalysis) -> str:
    """Plot title of the worst requested crossing: speed, direction and span DAFs."""
    crossing = analysis.worst
    direction, spacing, _ = analysis.worst_key
    dafs = ", ".join(f"{d:.2f}" for d in crossing.daf)
    lost = " (contact lost: outside validity)" if crossing.lost_contact else ""
    rear = f", rear spacing {number(spacing / ft)} ft" if spacing is not None else ""
    return f"{_speed(crossing.speed)} {_arrow(direction)}{rear}: span DAF {dafs}{lost}"
