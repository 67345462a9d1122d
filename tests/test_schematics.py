"""The study's six schematics draw on the axes they are given, with the notation's symbols."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Circle, Polygon, Rectangle  # noqa: E402

from vbi_lib import schematics  # noqa: E402

#: Symbols each figure must show (as matplotlib mathtext, the notation page's symbols).
SYMBOLS = {
    "2.10.1": [r"$k_v$", r"$c_v$", r"$m_v$", r"$EI$", r"$\bar m$", r"$\Delta(x)$", r"$F_c$", "$L$"],
    "2.13.1": [r"$k_v$", r"$c_v$", r"$m_v$", r"$u_v$", r"$m^*$", r"$k^*$", r"$c^*$", r"$z_b$"],
    "2.13.2": [r"$u_v$", r"$u_b = \psi(x_v)", r"$EI$", r"$\bar m$", r"$x_v = x_0 + v", "$L$"],
    "2.13.3": [r"$u_v$", r"$u_b = \psi(x_v)", r"$EI$", r"0 \leq x \leq 2L", "$L$"],
    "2.15.1": [r"$m_v$", r"$\Delta(x)$", "$m_v g + F$", "no feedback", r"$z_b$"],
    "2.15.2": ["$F_c = m_v g + F$", r"$F = k_v(r - u_v)", r"$r = \psi(x_v)", "contact force $F_c$"],
}


def texts(ax: plt.Axes) -> list[str]:
    return [t.get_text() for t in ax.texts]


@pytest.fixture(autouse=True)
def close_figures():  # noqa: ANN201
    yield
    plt.close("all")


def test_every_schematic_of_the_study_is_drawn() -> None:
    assert sorted(schematics.STUDY_FIGURES) == sorted(SYMBOLS)


@pytest.mark.parametrize("number", sorted(SYMBOLS))
def test_draws_on_the_given_axes_with_its_symbols(number: str) -> None:
    fig, ax = plt.subplots(figsize=(7, 3))
    returned = schematics.STUDY_FIGURES[number](ax)
    assert returned is ax, "the drawing must return the axes it was given"
    assert len(fig.axes) == 1, "no extra axes"
    shown = texts(ax)
    for symbol in SYMBOLS[number]:
        assert any(symbol in t for t in shown), f"Figure {number} lacks {symbol!r}: {shown}"
    lines = [a for a in ax.get_children() if isinstance(a, Line2D)]
    patches = [p for p in ax.patches if isinstance(p, Rectangle | Circle | Polygon)]
    assert len(lines) >= 10, f"Figure {number}: only {len(lines)} lines drawn"
    assert patches, f"Figure {number}: no masses, wheels or supports drawn"
    assert not ax.axison, "a schematic has no axis frame or ticks"
    assert ax.get_aspect() == 1.0, "equal scales, so springs and supports are not distorted"
    fig.canvas.draw()  # renders: mathtext that matplotlib cannot parse fails here


@pytest.mark.parametrize("number", sorted(SYMBOLS))
def test_every_label_lies_inside_the_figure(number: str) -> None:
    ax = schematics.STUDY_FIGURES[number]()
    fig = ax.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    for text in ax.texts:
        box = text.get_window_extent(renderer)
        inside = (
            box.x0 >= frame.x0 - 1
            and box.x1 <= frame.x1 + 1
            and box.y0 >= frame.y0 - 1
            and box.y1 <= frame.y1 + 1
        )
        assert inside, f"Figure {number}: {text.get_text()!r} is cut off by the axes' limits"


@pytest.mark.parametrize("number", sorted(SYMBOLS))
def test_labels_do_not_overlap(number: str) -> None:
    ax = schematics.STUDY_FIGURES[number]()
    fig = ax.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in ax.texts if t.get_text()]
    for i, (a, box_a) in enumerate(boxes):
        for b, box_b in boxes[i + 1 :]:
            assert not box_a.overlaps(box_b), f"Figure {number}: {a!r} overlaps {b!r}"


@pytest.mark.parametrize("number", sorted(SYMBOLS))
def test_a_new_figure_about_seven_inches_wide(number: str) -> None:
    ax = schematics.STUDY_FIGURES[number]()
    width, height = ax.figure.get_size_inches()
    assert width == pytest.approx(7.0)
    assert 2.5 <= height <= 4.0


def test_labels_are_readable_at_page_scale() -> None:
    ax = schematics.single_span_model()
    assert min(t.get_fontsize() for t in ax.texts) >= 9


def test_not_an_axes_is_refused_by_name() -> None:
    with pytest.raises(TypeError, match="ax='left' must be a matplotlib Axes or None"):
        schematics.coupled_model("left")
