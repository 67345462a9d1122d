"""The tests' reference crossing (deck_crossing.py) against the library's modal beam model.

The reference integrates the study's sprung mass on a bridge given as data (solve_ivp,
DOP853, interval by interval of the road).  On a beam, with its own N-mode statics (no
mode-acceleration part), it is the library's modal model's series (``series_daf``); with the
mode-acceleration part over the exact statics, its headline ``daf`` (vbi.simulate,
model="modal", Newmark in a compiled kernel): two independent integrations of one set of
equations.  The
road is one of the study's, scaled so that the tyre never leaves it (the reference, like the
study's FE runs, keeps the tyre on the road).
"""

from __future__ import annotations

import warnings

import deck_crossing as dc
import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import study_data as sd


def test_the_reference_crossing_is_the_library_s_modal_beam(shared_data) -> None:  # noqa: ANN001
    table, profiles = sd.read_assessment_set(shared_data / "seed-study")
    row = table[(table.span_ft == 100) & (table.n_spans == 1) & (table.path == 3)].iloc[[0]]
    beams, trucks, roads = sd.assessment_inputs(row, profiles, beam="exact")
    beam, truck, road = beams[0], trucks[0], roads[0]
    gentle = vbi.Profile(road.x, 0.2 * road.elevation)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)
        library = vbi.simulate(beam, truck, gentle, sd.ASSESSMENT_SPEED,
                               sd.ASSESSMENT_BRIDGE_START, model="modal", modes=5)  # fmt: skip
    data = dc.beam_data(beam, 5, list(beam.midspans))
    series = dc.BridgeData(data.stations, data.shape, data.slope, data.omega, data.zeta,
                           data.response_shape, data.static - data.residual,
                           np.zeros_like(data.residual), data.entry, data.exit)  # fmt: skip
    out = dc.crossing(series, (truck.mass, truck.stiffness, truck.damping),
                      (gentle.x, gentle.elevation), sd.ASSESSMENT_SPEED,
                      sd.ASSESSMENT_BRIDGE_START)  # fmt: skip
    assert out["min_contact"] > 0.5  # the tyre stays on the road
    assert out["daf"][0] == pytest.approx(library.series_daf[0], rel=1e-4)
    assert out["daf"][0] > 1.1
    # with its mode-acceleration part, over the exact statics: the library's headline DAF
    full = dc.crossing(data, (truck.mass, truck.stiffness, truck.damping),
                       (gentle.x, gentle.elevation), sd.ASSESSMENT_SPEED,
                       sd.ASSESSMENT_BRIDGE_START)  # fmt: skip
    assert full["daf"][0] == pytest.approx(library.daf[0], rel=1e-4)
