"""The deck's default Ritz basis is converged: a convergence study on the study's decks.

The default (12 beam modes per span along, 30 polynomials across, one end function at each
end of a skewed deck) against 24 per span and 44 (two spans: 16 and 38): the frequencies
below 4 f1 (the modes kept by default) within 0.1 %, the first eight within 0.2 %, the
twin-load deflection within 0.3 %, and every frequency of the finer basis at or below the
default's (nested bases: Rayleigh-Ritz upper bounds fall as functions are added).  What
remains is the slow convergence of point loads on a plate and of the skewed deck's corners;
the independent plate FE (test_statics.py) agrees to 0.2 %.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from vbi_lib.decks import WheelPath, axle_deflection
from vbi_lib.decks.study import STUDY_PATHS, study_deck

CASES = [(40, 1, None, 1), (40, 1, "left", 2), (40, 2, "right", 1), (100, 1, None, 1)]
FINER = {1: (24, 44), 2: (16, 38)}  # functions (along per span, across)


@pytest.mark.parametrize(("span_ft", "n_spans", "hand", "path"), CASES)
def test_the_default_basis_is_converged(span_ft: int, n_spans: int, hand: str | None,
                                        path: int) -> None:  # fmt: skip
    default = study_deck(span_ft, n_spans, hand)
    finer = replace(default, resolution=FINER[n_spans])
    f_default, f_finer = default.frequencies_hz(8), finer.frequencies_hz(8)
    kept = f_default < 4.0 * f_default[0]  # the modes deck.modes() keeps by default
    assert f_finer[kept] == pytest.approx(f_default[kept], rel=1e-3)
    assert f_finer == pytest.approx(f_default, rel=2e-3)
    assert (f_finer <= f_default * (1 + 1e-9)).all()
    where = STUDY_PATHS[(span_ft, n_spans, path)]
    wheel_path = WheelPath.from_girder(default, where.distance)
    response = [(default.midspans[0], default.girder_y(where.girder))]
    d_default = axle_deflection(default, wheel_path, default.midspans[0], response)
    d_finer = axle_deflection(finer, wheel_path, default.midspans[0], response)
    assert d_finer == pytest.approx(d_default, rel=3e-3)
