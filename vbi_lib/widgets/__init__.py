"""Interactive explorers for Jupyter and Voila (ipywidgets): what if the bridge, the truck,
the road or the speed were different?

Three explorers, each with ``.widget`` (display it), ``.controls`` (the controls by the
parameter each sets) and ``.result`` (the last computation, for checking without a browser):

* :class:`CrossingExplorer`: one crossing, every input of the model as a control: the
  midspan response and the contact force, the DAF beside the contact check;
* :class:`SpeedExplorer`: DAF and contact-force amplification against speed and forcing
  frequency, with the design codes' allowances;
* :class:`FrequencyExplorer`: DAF over the truck-to-bridge frequency ratio and the speed, as
  a heat map (:class:`FrequencyMap`).

:class:`ExplorerApp` puts the three in tabs (the app ``make explore`` serves with Voila).
In the static book the same explorers run in the reader's browser, on a JavaScript port of the
models (:mod:`vbi_lib.widgets.page`); :func:`live_and_static` shows a live explorer where a
kernel runs it and its static twin in the book.  Every explorer writes its setting as a report
parameter file (:mod:`vbi_lib.widgets.report_file`).
Controls are in the study's US customary units; readouts and plots follow
:mod:`vbi_lib.display`.  The controls describe a :class:`Scenario`:

>>> from vbi_lib.widgets import Scenario
>>> round(Scenario(span_ft=100, bridge_frequency_hz=3.0).bridge().first_frequency_hz, 6)
3.0
"""

from __future__ import annotations

import ipywidgets as w

from .controls import ControlValueError
from .crossing import CrossingExplorer
from .frequency import FrequencyExplorer, FrequencyMap
from .page import PageExplorer, live_and_static
from .scenario import ROADS, Scenario
from .speed import SpeedExplorer

__all__ = [
    "ROADS",
    "ControlValueError",
    "CrossingExplorer",
    "ExplorerApp",
    "FrequencyExplorer",
    "FrequencyMap",
    "PageExplorer",
    "Scenario",
    "SpeedExplorer",
    "live_and_static",
]


class ExplorerApp:
    """The three explorers in tabs: ``ExplorerApp().widget``.

    Attributes
    ----------
    crossing, speed, frequency
        The :class:`CrossingExplorer`, :class:`SpeedExplorer` and :class:`FrequencyExplorer`.
    widget
        The tabs to display.
    """

    def __init__(self) -> None:
        self.crossing = CrossingExplorer()
        self.speed = SpeedExplorer()
        self.frequency = FrequencyExplorer()
        self.widget = w.Tab(
            children=[self.crossing.widget, self.speed.widget, self.frequency.widget],
            titles=["One crossing", "DAF against speed", "Frequency matching"],
        )
