r"""The study's six schematic figures, drawn by code (matplotlib).

Each function draws one of the study's diagrams of the vehicle-bridge system on a matplotlib
axes (a new figure about 7 in wide when none is given), labels it with the symbols of the
book's notation page, and returns the axes:

=============================  ==============  ===============================================
function                       study figure    what it shows
=============================  ==============  ===============================================
:func:`combined_systems`       Figure 2.10.1   the parts any vehicle-bridge model needs
:func:`simplified_model`       Figure 2.13.1   the 2-DOF model: a sprung mass on one coordinate
:func:`single_span_model`      Figure 2.13.2   the single-span 2-DOF model (equations 33-58)
:func:`two_span_model`         Figure 2.13.3   the two-span 2-DOF model (equations 59-81)
:func:`decoupled_model`        Figure 2.15.1   the decoupled model (equations 92-99)
:func:`coupled_model`          Figure 2.15.2   the coupled 2-DOF model and its contact force
=============================  ==============  ===============================================

The symbols: span :math:`L`, flexural rigidity :math:`EI`, mass per length :math:`\bar m`,
bridge damping ratio :math:`\zeta_b`, shape function :math:`\psi(x)`, generalised coordinate
:math:`z_b` with generalised mass, stiffness and damping :math:`m^*, k^*, c^*`, vehicle mass,
suspension stiffness and damping :math:`m_v, k_v, c_v`, the vehicle's displacement
:math:`u_v`, the bridge's deflection under the wheel :math:`u_b`, the wheel's station
:math:`x_v`, speed :math:`v`, road profile :math:`\Delta(x)`, suspension force :math:`F` and
contact force :math:`F_c = m_v g + F`.  Displacements are drawn positive up, as the library
counts them.

The drawings are schematic: proportions are chosen to be read, not to scale.

Examples
--------
>>> import matplotlib
>>> matplotlib.use("Agg")
>>> from vbi_lib import schematics
>>> ax = schematics.single_span_model()
>>> any("$EI$" in t.get_text() for t in ax.texts)
True
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "STUDY_FIGURES",
    "combined_systems",
    "coupled_model",
    "decoupled_model",
    "simplified_model",
    "single_span_model",
    "two_span_model",
]

#: Line width of structural members and of the thin lines (springs, hatching, arrows).
_THICK, _THIN = 3.0, 1.2
#: Font size of the labels [pt]; the figures are drawn about 7 in wide.
_FONT = 11
_BEAM, _VEHICLE, _ROAD, _FORCE = "0.15", "C0", "0.45", "C3"


# ---------------------------------------------------------------------------- the axes
def _axes(
    ax: Axes | None, size: tuple[float, float], limits: tuple[float, float, float, float]
) -> Axes:
    """The axes to draw on (a new figure of ``size`` inches when ``ax`` is None), cleared of
    ticks and frame, with equal scales on ``limits = (x0, x1, y0, y1)``."""
    import matplotlib.pyplot as plt
    from matplotlib.axes import Axes

    if ax is None:
        _, ax = plt.subplots(figsize=size)
    elif not isinstance(ax, Axes):
        raise TypeError(f"ax={ax!r} must be a matplotlib Axes or None; pass plt.gca() or None")
    ax.set_xlim(limits[0], limits[1])
    ax.set_ylim(limits[2], limits[3])
    ax.set_aspect("equal")
    ax.set_axis_off()
    return ax


def _text(ax: Axes, x: float, y: float, text: str, **kw) -> None:  # noqa: ANN003
    ax.text(x, y, text, fontsize=kw.pop("fontsize", _FONT), **kw)


# ---------------------------------------------------------------------------- parts
def _spring(ax: Axes, x: float, y0: float, y1: float, width: float = 0.35, coils: int = 5) -> None:
    """A vertical zigzag spring from ``(x, y0)`` up to ``(x, y1)``."""
    lead = 0.15 * (y1 - y0)
    ys = np.linspace(y0 + lead, y1 - lead, 2 * coils + 1)
    xs = np.full_like(ys, x)
    xs[1:-1:2] -= width / 2
    xs[2:-1:2] += width / 2
    ax.plot([x, *xs, x], [y0, *ys, y1], color="k", lw=_THIN, solid_joinstyle="miter")


def _damper(ax: Axes, x: float, y0: float, y1: float, width: float = 0.35) -> None:
    """A vertical dashpot from ``(x, y0)`` up to ``(x, y1)``: a cylinder and a piston."""
    h = y1 - y0
    bottom, top = y0 + 0.25 * h, y0 + 0.65 * h
    w = width / 2
    ax.plot([x, x], [y0, bottom], color="k", lw=_THIN)
    ax.plot([x - w, x - w, x + w, x + w], [top, bottom, bottom, top], color="k", lw=_THIN)
    piston = y0 + 0.5 * h
    ax.plot([x - 0.8 * w, x + 0.8 * w], [piston, piston], color="k", lw=2 * _THIN)
    ax.plot([x, x], [piston, y1], color="k", lw=_THIN)


def _suspension(ax: Axes, x: float, y0: float, y1: float, labels: tuple[str, str]) -> None:
    """A spring (left) and a damper (right) in parallel between two levels, labelled."""
    gap = 0.45
    ax.plot([x - gap, x + gap], [y0, y0], color="k", lw=_THIN)
    ax.plot([x - gap, x + gap], [y1, y1], color="k", lw=_THIN)
    _spring(ax, x - gap, y0, y1)
    _damper(ax, x + gap, y0, y1)
    middle = 0.5 * (y0 + y1)
    _text(ax, x - gap - 0.3, middle, labels[0], ha="right", va="center")
    _text(ax, x + gap + 0.3, middle, labels[1], ha="left", va="center")


def _mass(
    ax: Axes, x: float, y: float, w: float, h: float, label: str, color: str = _VEHICLE
) -> None:
    """A block of mass centred at ``x`` with its bottom at ``y``."""
    from matplotlib.patches import Rectangle

    ax.add_patch(Rectangle((x - w / 2, y), w, h, facecolor=color, edgecolor="k", alpha=0.25))
    ax.add_patch(Rectangle((x - w / 2, y), w, h, fill=False, edgecolor="k", lw=_THIN))
    _text(ax, x, y + h / 2, label, ha="center", va="center")


def _wheel(ax: Axes, x: float, y: float, r: float = 0.22) -> None:
    """A wheel standing on ``(x, y)``."""
    from matplotlib.patches import Circle

    ax.add_patch(Circle((x, y + r), r, facecolor="white", edgecolor="k", lw=_THIN, zorder=3))


def _ground(ax: Axes, x0: float, x1: float, y: float, ticks: float = 0.25) -> None:
    """A fixed ground line with hatching below."""
    ax.plot([x0, x1], [y, y], color="k", lw=_THIN)
    for xt in np.arange(x0 + ticks / 2, x1, ticks):
        ax.plot([xt, xt - ticks], [y, y - ticks], color="k", lw=0.7 * _THIN)


def _support(ax: Axes, x: float, y: float, roller: bool, size: float = 0.35) -> None:
    """A pin (or roller) support whose apex is at ``(x, y)``."""
    from matplotlib.patches import Circle, Polygon

    base = y - size
    ax.add_patch(
        Polygon(
            [(x, y), (x - size / 1.4, base), (x + size / 1.4, base)],
            closed=True,
            facecolor="white",
            edgecolor="k",
            lw=_THIN,
            zorder=2,
        )
    )
    if roller:
        r = size / 6
        for dx in (-size / 2.5, 0.0, size / 2.5):
            ax.add_patch(Circle((x + dx, base - r), r, fill=False, edgecolor="k", lw=0.8 * _THIN))
        base -= 2 * r
    _ground(ax, x - size, x + size, base, ticks=size / 2.5)


def _arrow(
    ax, start: tuple, end: tuple, color: str = "k", lw: float = _THIN, both: bool = False
) -> None:
    style = "<|-|>" if both else "-|>"
    ax.annotate(
        "",
        xy=end,
        xytext=start,
        arrowprops={
            "arrowstyle": style,
            "color": color,
            "lw": lw,
            "shrinkA": 0,
            "shrinkB": 0,
            "mutation_scale": 12,
        },
    )


def _dimension(ax: Axes, x0: float, x1: float, y: float, text: str) -> None:
    """A dimension line between two stations, with ticks and its text below."""
    _arrow(ax, (x0, y), (x1, y), both=True, lw=0.8 * _THIN)
    for xe in (x0, x1):
        ax.plot([xe, xe], [y - 0.15, y + 0.15], color="k", lw=0.8 * _THIN)
    _text(ax, 0.5 * (x0 + x1), y - 0.15, text, ha="center", va="top")


def _bumps(x: np.ndarray, amplitude: float = 0.06) -> np.ndarray:
    """A made-up rough profile, the same on every call (sum of three sines)."""
    return amplitude * (np.sin(2.3 * x) + 0.6 * np.sin(5.1 * x + 1.0) + 0.3 * np.sin(11.0 * x))


def _beam(
    ax: Axes, x0: float, spans: int, span: float, y: float, sag: float, rough: bool = True
) -> None:
    """A beam of ``spans`` equal spans on supports at height ``y``: the undeformed axis dotted,
    the deflected shape ``sag * sin(pi (x - x0) / span)`` (positive up) drawn thick, with the
    road profile on top when ``rough``."""
    x = np.linspace(x0, x0 + spans * span, 400)
    shape = sag * np.sin(np.pi * (x - x0) / span)
    ax.plot([x[0], x[-1]], [y, y], color=_BEAM, lw=0.8, ls=":")
    ax.plot(x, y + shape, color=_BEAM, lw=_THICK, solid_capstyle="butt")
    if rough:
        ax.plot(x, y + shape + 0.12 + _bumps(x), color=_ROAD, lw=_THIN)
    for i in range(spans + 1):
        _support(ax, x0 + i * span, y - 0.05, roller=i > 0)


def _vehicle(
    ax: Axes, x: float, road: float, speed: str | None = r"$v$", gap: float = 0.0
) -> float:
    """A sprung mass whose wheel stands ``gap`` above the road at ``(x, road)``, with its
    displacement ``u_v`` marked on the left and, unless ``speed`` is None, a speed arrow
    above; returns the height of the top of its block."""
    bottom = road + gap
    _wheel(ax, x, bottom)
    axle = bottom + 0.44
    body = axle + 1.1
    ax.plot([x, x], [bottom + 0.22, axle], color="k", lw=_THIN)
    _suspension(ax, x, axle, body, (r"$k_v$", r"$c_v$"))
    _mass(ax, x, body, 1.5, 0.7, r"$m_v$")
    top = body + 0.7
    _displacement_arrow(ax, x - 1.05, body + 0.15, r"$u_v$", length=0.5, left=True)
    if speed is not None:
        _arrow(ax, (x - 0.7, top + 0.35), (x + 0.8, top + 0.35), lw=2 * _THIN)
        _text(ax, x + 0.95, top + 0.35, speed, va="center")
    return top


def _displacement_arrow(
    ax,
    x: float,
    y: float,
    text: str,
    length: float = 0.7,
    left: bool = False,
) -> None:
    """An upward arrow from a reference tick at ``(x, y)``, labelled at its tip (positive up)."""
    ax.plot([x - 0.12, x + 0.12], [y, y], color="k", lw=_THIN)
    _arrow(ax, (x, y), (x, y + length))
    dx = -0.12 if left else 0.12
    _text(ax, x + dx, y + length, text, ha="right" if left else "left", va="center")


# ---------------------------------------------------------------------------- figures
def combined_systems(ax: Axes | None = None) -> Axes:
    r"""Figure 2.10.1: the vehicle and the bridge as one system.

    A truck (sprung mass :math:`m_v` on a suspension :math:`k_v, c_v`) drives at speed
    :math:`v` from the approach road onto a bridge (mass per length :math:`\bar m`,
    stiffness :math:`EI`, damping :math:`\zeta_b`); the tyre presses on the road with the
    contact force :math:`F_c`, which depends on the road profile :math:`\Delta(x)` under the
    wheel and on the bridge's own motion.  These are the parts the study lists as needed by
    any vehicle-bridge model (its chapter 10).

    Parameters
    ----------
    ax
        A matplotlib axes, or None for a new figure (7 x 3.2 in).

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    TypeError
        ``ax`` is not a matplotlib axes.
    """
    ax = _axes(ax, (7.0, 3.0), (-0.2, 14.6, -2.4, 3.7))
    x0, span = 6.0, 8.0
    approach = np.linspace(0.0, x0, 150)
    ax.fill_between(approach, -0.6, 0.12 + _bumps(approach), color="0.88", lw=0)
    ax.plot(approach, 0.12 + _bumps(approach), color=_ROAD, lw=_THIN)
    _beam(ax, x0, 1, span, 0.0, sag=-0.35)
    xv = 3.4
    road = 0.12 + float(_bumps(np.array([xv]))[0])
    top = _vehicle(ax, xv, road, speed=r"speed $v$")
    _text(ax, xv + 0.95, top - 0.35, "vehicle", ha="left", va="center")
    _arrow(ax, (xv + 0.55, -0.75), (xv + 0.55, road - 0.02), color=_FORCE)
    _text(ax, xv + 0.55, -0.8, r"contact force $F_c$", color=_FORCE, ha="center", va="top")
    _text(ax, 0.15, -0.3, "approach road", ha="left", va="center")
    _text(ax, x0 + span / 2, 0.75, r"road profile $\Delta(x)$", ha="center", va="center")
    bridge = r"bridge: $\bar m$, $EI$, $\zeta_b$"
    _text(ax, x0 + span / 2, -0.75, bridge, ha="center", va="center")
    _dimension(ax, x0, x0 + span, -1.55, r"span $L$")
    return ax


def simplified_model(ax: Axes | None = None) -> Axes:
    r"""Figure 2.13.1: the simplified two-degree-of-freedom model.

    The truck is one sprung mass (coordinate :math:`u_v`); the bridge is one generalised
    oscillator (coordinate :math:`z_b`, mass :math:`m^*`, stiffness :math:`k^*`, damping
    :math:`c^*`).  They meet at the wheel, which follows the road
    :math:`r = \psi(x_v)\, z_b + \Delta(x_v)`: the shape function read at the wheel's
    station :math:`x_v` is the lever between the two.

    Parameters
    ----------
    ax
        A matplotlib axes, or None for a new figure (7 x 3.6 in).

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    TypeError
        ``ax`` is not a matplotlib axes.
    """
    ax = _axes(ax, (7.0, 3.4), (-0.4, 12.6, -0.9, 5.9))
    # the bridge's generalised oscillator, on the ground
    xb = 2.6
    _ground(ax, xb - 1.6, xb + 1.6, 0.0)
    _suspension(ax, xb, 0.0, 1.5, (r"$k^*$", r"$c^*$"))
    _mass(ax, xb, 1.5, 2.2, 0.8, r"$m^*$", color="0.5")
    _displacement_arrow(ax, xb + 1.45, 1.65, r"$z_b$", length=0.5)
    _text(ax, xb - 1.6, -0.5, "bridge: one generalised coordinate", ha="left", va="center")
    # the deck under the wheel moves with the coordinate, scaled by psi(x_v)
    deck = 2.9
    ax.plot([xb - 1.1, xb + 4.9], [deck, deck], color=_BEAM, lw=_THICK)
    ax.plot([xb, xb], [2.3, deck], color=_BEAM, lw=_THIN, ls="--")
    xs = np.linspace(xb + 2.4, xb + 4.9, 80)
    ax.plot(xs, deck + 0.12 + _bumps(xs), color=_ROAD, lw=_THIN)
    xv = xb + 3.7
    road = deck + 0.12 + float(_bumps(np.array([xv]))[0])
    top = _vehicle(ax, xv, road)
    _text(ax, xv + 1.0, top - 0.35, "vehicle: one sprung mass", ha="left", va="center")
    under = "road under the wheel:\n$r = \\psi(x_v)\\,z_b + \\Delta(x_v)$"
    _text(ax, xb + 5.2, deck + 0.15, under, ha="left", va="center")
    return ax


def _span_model(ax: Axes | None, spans: int) -> Axes:
    """The single- and two-span 2-DOF diagrams (Figures 2.13.2 and 2.13.3)."""
    span = 9.0 if spans == 1 else 6.0
    length = spans * span
    ax = _axes(ax, (7.0, 3.3), (-0.8, length + 0.8, -2.7, 3.4))
    sag = -0.45
    _beam(ax, 0.0, spans, span, 0.0, sag)
    xv = 0.3 * span
    under = sag * np.sin(np.pi * xv / span)
    surface = under + 0.12 + float(_bumps(np.array([xv]))[0])
    _vehicle(ax, xv, surface)
    # the wheel's station and the deflection under it
    _arrow(ax, (0.0, -1.2), (xv, -1.2))
    _text(ax, xv / 2, -1.25, r"$x_v = x_0 + v\,t$", ha="center", va="top")
    ax.plot([xv, xv], [-1.2, under], color="k", lw=0.6, ls=":")
    _arrow(ax, (xv + 0.5, 0.0), (xv + 0.5, under), color=_BEAM)
    _text(ax, xv + 0.6, under - 0.3, r"$u_b = \psi(x_v)\,z_b$", ha="left", va="top")
    for i in range(spans):
        _dimension(ax, i * span, (i + 1) * span, -1.95, r"$L$")
    end = "L" if spans == 1 else "2L"
    shape = rf"$\psi(x) = \sin(\pi x / L)$, $0 \leq x \leq {end}$"
    _text(ax, length, 2.6, shape, ha="right", va="center")
    _text(ax, length, 2.0, r"beam: $EI$, $\bar m$, $\zeta_b$", ha="right", va="center")
    _text(ax, length, 1.4, r"road profile $\Delta(x)$", color=_ROAD, ha="right", va="center")
    return ax


def single_span_model(ax: Axes | None = None) -> Axes:
    r"""Figure 2.13.2: the single-span 2-DOF model.

    A sprung mass (:math:`m_v`, :math:`k_v`, :math:`c_v`, displacement :math:`u_v`) at the
    station :math:`x_v = x_0 + v t` of a simply supported beam of span :math:`L`
    (:math:`EI`, :math:`\bar m`, damping ratio :math:`\zeta_b`) that deflects in the half
    sine :math:`\psi(x) = \sin(\pi x/L)` times the generalised coordinate :math:`z_b`; under
    the wheel the bridge has moved :math:`u_b = \psi(x_v) z_b` and the road adds the profile
    :math:`\Delta(x_v)` (equations 33-35).

    Parameters
    ----------
    ax
        A matplotlib axes, or None for a new figure (7 x 3.4 in).

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    TypeError
        ``ax`` is not a matplotlib axes.
    """
    return _span_model(ax, 1)


def two_span_model(ax: Axes | None = None) -> Axes:
    r"""Figure 2.13.3: the two-span 2-DOF model.

    As :func:`single_span_model` on two equal continuous spans: the shape function
    :math:`\psi(x) = \sin(\pi x/L)` runs over both spans (:math:`0 \le x \le 2L`), so the
    second span rises while the first deflects, as in the beam's first mode (equations
    59-61).

    Parameters
    ----------
    ax
        A matplotlib axes, or None for a new figure (7 x 3.4 in).

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    TypeError
        ``ax`` is not a matplotlib axes.
    """
    return _span_model(ax, 2)


def decoupled_model(ax: Axes | None = None) -> Axes:
    r"""Figure 2.15.1: the decoupled model.

    Left, the truck drives over the profile :math:`\Delta(x)` as if the road were rigid;
    its suspension force :math:`F = k_v(\Delta - u_v) + c_v(\dot\Delta - \dot u_v)` (92) is
    computed without the bridge.  Right, the bridge carries that force plus the weight,
    :math:`m_v g + F`, moving at :math:`v`; its motion does not feed back into :math:`F`
    (equations 93-99).

    Parameters
    ----------
    ax
        A matplotlib axes, or None for a new figure (7 x 3.0 in).

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    TypeError
        ``ax`` is not a matplotlib axes.
    """
    ax = _axes(ax, (7.0, 3.0), (-0.6, 15.6, -1.6, 4.6))
    # left: the vehicle on a rigid road
    xs = np.linspace(0.0, 5.0, 150)
    ax.fill_between(xs, -0.6, 0.12 + _bumps(xs), color="0.88", lw=0)
    ax.plot(xs, 0.12 + _bumps(xs), color=_ROAD, lw=_THIN)
    xv = 2.6
    road = 0.12 + float(_bumps(np.array([xv]))[0])
    top = _vehicle(ax, xv, road)
    _text(ax, 2.5, -1.0, r"rigid road, profile $\Delta(x)$", ha="center", va="center")
    _text(ax, -0.4, top + 1.0, "1. the truck alone gives $F(t)$", ha="left", va="center")
    # the hand-over: one way only
    _arrow(ax, (5.4, 1.8), (7.5, 1.8), color=_FORCE, lw=2 * _THIN)
    _text(ax, 6.45, 2.0, "$m_v g + F$", color=_FORCE, ha="center", va="bottom")
    _text(ax, 6.45, 1.6, "no feedback", ha="center", va="top", fontsize=_FONT - 1)
    # right: the bridge under the moving force
    x0, span = 8.2, 7.0
    _beam(ax, x0, 1, span, 0.0, sag=-0.4, rough=False)
    xf = x0 + 0.45 * span
    surface = -0.4 * np.sin(np.pi * (xf - x0) / span)
    _arrow(ax, (xf, surface + 1.6), (xf, surface + 0.05), color=_FORCE, lw=2 * _THIN)
    _text(ax, xf + 0.15, surface + 1.1, "$m_v g + F$ at $x_v$", color=_FORCE, va="center")
    _arrow(ax, (xf - 0.5, surface + 2.1), (xf + 1.0, surface + 2.1), lw=2 * _THIN)
    _text(ax, xf + 1.15, surface + 2.1, r"$v$", va="center")
    _text(ax, x0 + span / 2, top + 1.0, "2. the bridge carries it", ha="center", va="center")
    _text(ax, x0 + span / 2, -1.0, r"$m^*$, $k^*$, $c^*$; coordinate $z_b$", ha="center")
    return ax


def coupled_model(ax: Axes | None = None) -> Axes:
    r"""Figure 2.15.2: the coupled 2-DOF model.

    The truck rides the moving bridge: the wheel follows
    :math:`r = \psi(x_v) z_b + \Delta(x_v)`, the suspension force
    :math:`F = k_v(r - u_v) + c_v(\dot r - \dot u_v)` (46) depends on both, and the contact
    force :math:`F_c = m_v g + F` pushes the bridge down and the wheel up, equal and
    opposite (equations 47-48).

    Parameters
    ----------
    ax
        A matplotlib axes, or None for a new figure (7 x 3.4 in).

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    TypeError
        ``ax`` is not a matplotlib axes.
    """
    ax = _axes(ax, (7.0, 3.4), (-0.8, 13.4, -1.6, 4.9))
    span, sag = 7.5, -0.45
    _beam(ax, 0.0, 1, span, 0.0, sag)
    xv = 0.45 * span
    under = sag * np.sin(np.pi * xv / span)
    surface = under + 0.12 + float(_bumps(np.array([xv]))[0])
    gap = 1.2  # the wheel drawn apart from the deck to show the force between them
    _vehicle(ax, xv, surface, gap=gap)
    middle = surface + gap / 2
    _arrow(ax, (xv, middle), (xv, surface + gap), color=_FORCE, lw=2 * _THIN)
    _arrow(ax, (xv, middle), (xv, surface), color=_FORCE, lw=2 * _THIN)
    _text(ax, xv + 0.25, middle, "contact force $F_c$", color=_FORCE, ha="left", va="center")
    _text(ax, span + 0.4, 3.2, "$F_c = m_v g + F$", ha="left", va="center")
    force = "$F = k_v(r - u_v) + c_v(\\dot r - \\dot u_v)$"
    _text(ax, span + 0.4, 2.4, force, ha="left", va="center")
    _text(ax, span + 0.4, 1.6, "$r = \\psi(x_v)\\,z_b + \\Delta(x_v)$", ha="left", va="center")
    _text(ax, span / 2, -1.0, r"bridge: $m^*$, $k^*$, $c^*$; coordinate $z_b$", ha="center")
    return ax


#: The drawing of each of the study's schematic figures, by the study's figure number.
STUDY_FIGURES = {
    "2.10.1": combined_systems,
    "2.13.1": simplified_model,
    "2.13.2": single_span_model,
    "2.13.3": two_span_model,
    "2.15.1": decoupled_model,
    "2.15.2": coupled_model,
}
