"""A matplotlib figure shown as an image widget, redrawn as little as possible.

The explorers keep one :class:`~matplotlib.figure.Figure` each, built once with fixed margins
(no layout engine, no ``bbox_inches="tight"``), and update their lines' data when a control
moves.  :meth:`FigureImage.render` then sends one PNG to the page.  Lines registered as
*dynamic* are drawn over a cached image of everything else (blitting), so while the axes'
limits and the static artists stay the same an update draws only those lines; a change of
the limits, or :meth:`FigureImage.invalidate` (the caller's duty when anything else
changed), redraws the whole figure once.  A figure without dynamic artists is always drawn
whole.  No pyplot
figure is created, so nothing depends on the notebook's matplotlib backend.
"""

from __future__ import annotations

import io
from collections.abc import Iterable

import ipywidgets as w
from matplotlib.artist import Artist
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

__all__ = ["FigureImage"]


class FigureImage:
    """A figure of ``size`` inches at ``dpi`` and the image widget that shows it.

    Attributes
    ----------
    figure
        The matplotlib figure (draw on it, then call :meth:`render`).
    widget
        The ``ipywidgets.Image`` to display.
    renders, full_draws
        How many images were sent, and how many of them needed the whole figure drawn.
    """

    def __init__(self, size: tuple[float, float], dpi: int = 96) -> None:
        self.figure = Figure(figsize=size, dpi=dpi)
        self.canvas = FigureCanvasAgg(self.figure)
        width, height = (round(s * dpi) for s in size)
        self.widget = w.Image(
            format="png", layout=w.Layout(width=f"{width}px", height=f"{height}px")
        )
        self.widget.add_class("vbi-figure")
        self.renders = 0
        self.full_draws = 0
        self._dynamic: list[Artist] = []
        self._background = None
        self._limits: list = []

    def set_dynamic(self, artists: Iterable[Artist]) -> None:
        """Draw these artists over the cached rest of the figure (their data may change)."""
        for artist in self._dynamic:
            artist.set_animated(False)
        self._dynamic = list(artists)
        for artist in self._dynamic:
            artist.set_animated(True)
        self.invalidate()

    def invalidate(self) -> None:
        """Something besides the dynamic artists changed: draw the whole figure next time."""
        self._background = None

    def render(self) -> None:
        """Draw what changed and send the figure to the page as a PNG (light compression)."""
        limits = [(ax.get_xlim(), ax.get_ylim()) for ax in self.figure.axes]
        # without dynamic artists whatever changed is in the background: draw it all
        if not self._dynamic or self._background is None or limits != self._limits:
            self.canvas.draw()  # everything but the dynamic artists
            self._background = self.canvas.copy_from_bbox(self.figure.bbox)
            self._limits = limits
            self.full_draws += 1
        else:
            self.canvas.restore_region(self._background)
        for artist in self._dynamic:
            if artist.get_visible():
                artist.axes.draw_artist(artist)
        width, height = self.canvas.get_width_height()
        image = Image.frombuffer(
            "RGBA", (width, height), self.canvas.buffer_rgba(), "raw", "RGBA", 0, 1
        ).convert("RGB")  # the figure is opaque
        buffer = io.BytesIO()
        image.save(buffer, format="png", compress_level=1)
        self.widget.value = buffer.getvalue()
        self.renders += 1
