"""What the page shows is the figure as a full redraw would draw it (blitting never shows a
stale picture), for the figure helper and for every explorer."""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image

from vbi_lib.widgets import CrossingExplorer, FrequencyExplorer, SpeedExplorer
from vbi_lib.widgets.figure import FigureImage


def shown(view: FigureImage) -> np.ndarray:
    """The pixels of the PNG the page received."""
    return np.asarray(Image.open(io.BytesIO(view.widget.value)).convert("RGB"))


def redrawn(view: FigureImage) -> np.ndarray:
    """The pixels of the same figure drawn whole, from scratch."""
    dynamic = [a for a in view.figure.findobj() if a.get_animated()]
    for artist in dynamic:
        artist.set_animated(False)
    try:
        view.canvas.draw()
        return np.asarray(view.canvas.buffer_rgba())[..., :3].copy()
    finally:
        for artist in dynamic:
            artist.set_animated(True)


def mismatch(view: FigureImage) -> float:
    """Fraction of the pixels that differ (blitted lines lie on top of legends: a few do)."""
    return float(np.any(shown(view) != redrawn(view), axis=-1).mean())


def test_a_blitted_line_is_drawn_where_a_full_draw_puts_it() -> None:
    view = FigureImage((4, 3))
    ax = view.figure.add_subplot()
    ax.set_xlim(0, 10)
    ax.set_ylim(-1, 1)
    ax.set_axis_off()  # a full draw puts the frame over the line, blitting under it
    (line,) = ax.plot([], [])
    view.set_dynamic([line])
    x = np.linspace(0, 10, 200)
    previous = None
    for k in range(3):
        line.set_data(x, np.sin(x + k))
        view.render()
        assert mismatch(view) == 0.0
        if previous is not None:  # the frames differ, so a stale one would have been caught
            assert np.any(shown(view) != previous, axis=-1).mean() > 0.002
        previous = shown(view)
    assert view.full_draws == 1 and view.renders == 3


def test_a_figure_without_dynamic_artists_is_drawn_whole_each_time() -> None:
    view = FigureImage((4, 3))
    ax = view.figure.add_subplot()
    image = ax.imshow(np.zeros((4, 4)), vmin=0, vmax=1)
    view.render()
    image.set_data(np.eye(4))  # same limits, new picture
    view.render()
    assert mismatch(view) == 0.0
    assert view.full_draws == 2


@pytest.mark.parametrize(
    ("kind", "changes"),
    [
        (CrossingExplorer, [{"speed_mph": 45.0}, {"speed_mph": 46.0}, {"span_ft": 120.0},
                            {"n_spans": 2}, {"road": "measured"}, {"road": "bump"}]),
        (SpeedExplorer, [{"truck_damping": 0.2}, {"n_spans": 2}, {"road": "iso-class"}]),
        (FrequencyExplorer, [{"bridge_damping": 0.04}, {"n_ratios": 5}, {"road": "flat"}]),
    ],
)  # fmt: skip
def test_every_explorer_shows_its_current_figure(kind: type, changes: list[dict]) -> None:
    explorer = kind(n_speeds=5) if kind is not CrossingExplorer else kind()
    assert mismatch(explorer.view) < 0.005
    for change in changes:
        explorer.set(**change)
        assert mismatch(explorer.view) < 0.005, change
