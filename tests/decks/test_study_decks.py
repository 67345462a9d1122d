"""The study's decks: the seed's geometry, its paths and girders, fitted to every row.

Facts from the seed (Chapter 13, "Bridge Models"): 40 ft, seven girders at 84 in, an 8.5 in
slab, path 1 over the first interior girder and path 2 16 ft from the exterior girder
(Table 2.13.7 names girders 2 and 3); 100 ft, five girders at 99 in, a 9.5 in slab, paths
4, 10.5 and 16.5 ft from the exterior girder (Table 2.13.6 names girders 1, 2, 3 on one span
and 2, 3, 3 on two); 140 ft, no geometry.  Each row's deck has the row's K_mid and f1.
"""

from __future__ import annotations

import numpy as np
import pytest

from vbi_lib import study_data as sd
from vbi_lib import units as u
from vbi_lib.decks import Deck, midspan_stiffness
from vbi_lib.decks.study import STUDY_SKEW, StudyDeck, study_deck


def test_the_40_ft_deck_is_the_seed_s() -> None:
    deck = study_deck(40, 1)
    assert deck.girders.count == 7
    assert deck.girders.spacing == pytest.approx(84 * u.inch)
    assert deck.thickness == pytest.approx(8.5 * u.inch)
    assert deck.spans == pytest.approx((40 * u.ft,))
    assert deck.skew == 0.0 and deck.skew_hand is None  # the default: square
    skewed = study_deck(40, 2, "right")
    assert skewed.skew == STUDY_SKEW == 16.0 and skewed.skew_hand == "right"
    assert skewed.spans == pytest.approx((40 * u.ft, 40 * u.ft))


def test_the_100_ft_deck_is_the_seed_s() -> None:
    deck = study_deck(100, 2)
    assert deck.girders.count == 5
    assert deck.girders.spacing == pytest.approx(99 * u.inch)
    assert deck.thickness == pytest.approx(9.5 * u.inch)
    assert deck.diaphragm_stations == pytest.approx((50 * u.ft, 150 * u.ft))


@pytest.fixture(scope="module")
def assessment(shared_data):  # noqa: ANN001, ANN201
    table, profiles = sd.read_assessment_set(shared_data / "seed-study")
    sites, _, _ = sd.assessment_inputs(table, profiles, beam="deck")
    return table, sites


EXPECTED_PATHS = {  # (span, spans, path) -> (feet from the exterior girder, named girder)
    (40, 1, 1): (7.0, 2),
    (40, 1, 2): (16.0, 3),
    (40, 2, 1): (7.0, 2),
    (40, 2, 2): (16.0, 3),
    (100, 1, 1): (4.0, 1),
    (100, 1, 2): (10.5, 2),
    (100, 1, 3): (16.5, 3),
    (100, 2, 1): (4.0, 2),
    (100, 2, 2): (10.5, 3),
    (100, 2, 3): (16.5, 3),
}


def test_every_row_s_deck_has_its_path_girder_k_mid_and_f1(assessment) -> None:  # noqa: ANN001
    table, sites = assessment
    assert len(sites) == 239 and all(isinstance(s, StudyDeck) for s in sites)
    seen = set()
    for row, site in zip(table.itertuples(), sites, strict=True):
        if row.span_ft == 140:
            assert site.deck is None and site.beam is not None
            assert "140 ft" in site.notes[0] and "exact beam" in site.notes[0]
            assert site.beam.first_frequency_hz == pytest.approx(row.bridge_f1_hz)
            continue
        key = (int(row.span_ft), int(row.n_spans), int(row.path))
        feet, girder = EXPECTED_PATHS[key]
        deck = site.deck
        assert isinstance(deck, Deck) and site.girder == girder
        assert site.path.offset - deck.girder_y(1) == pytest.approx(feet * u.ft)
        assert site.path.track == pytest.approx(6 * u.ft)
        if key in seen:
            continue
        seen.add(key)
        k = midspan_stiffness(deck, site.path, girder)
        assert k == pytest.approx(row.k_mid_lbf_per_in * u.lbf / u.inch, rel=1e-9)
        assert deck.first_frequency_hz() == pytest.approx(row.bridge_f1_hz, rel=1e-12)
        assert len(site.responses) == row.n_spans
        if row.span_ft == 40:
            assert "does not say which way" in site.notes[0]
    assert seen == set(EXPECTED_PATHS)


def test_the_skew_hand_changes_the_40_ft_decks_only(assessment, shared_data) -> None:  # noqa: ANN001
    table, square = assessment
    rows = table.groupby(["span_ft", "n_spans", "path"]).head(1)
    _, profiles = sd.read_assessment_set(shared_data / "seed-study")
    left, _, _ = sd.assessment_inputs(rows, profiles, beam="deck", skew_hand="left")
    for row, site in zip(rows.itertuples(), left, strict=True):
        if row.span_ft == 40:
            assert site.deck.skew == 16.0 and site.deck.skew_hand == "left" and not site.notes
        elif row.span_ft == 100:
            assert site.deck.skew == 0.0
    # skewing a deck changes its frequency ratios (the fit keeps f1 and K_mid)
    i = int(np.flatnonzero((rows.span_ft == 40).to_numpy())[0])
    j = int(np.flatnonzero((table.span_ft == 40).to_numpy())[0])
    f_skew = left[i].deck.frequencies_hz(3)
    f_square = square[j].deck.frequencies_hz(3)
    assert f_skew[0] == pytest.approx(f_square[0], rel=1e-12)
    assert abs(f_skew[1] / f_skew[0] - f_square[1] / f_square[0]) > 1e-4


def test_the_barriers_act_as_asked_and_by_default_as_the_seed_reads() -> None:
    """The seed says the 40 ft barriers were "modeled with a rectangular section" (composite
    with the exterior girder, as eccentric beams are); of the 100 ft ones only their size."""
    for span, default in ((40, "composite"), (100, "own")):
        assert study_deck(span, 1) == study_deck(span, 1, barriers=default)
        other = "own" if default == "composite" else "composite"
        stiff = study_deck(span, 1, barriers="composite")
        alone = study_deck(span, 1, barriers="own")
        assert study_deck(span, 1) != study_deck(span, 1, barriers=other)
        # composite action puts most of the edge's rigidity on the barrier line
        assert stiff.edge_beams[0].EI > 3 * alone.edge_beams[0].EI
        assert stiff.edge_beams[0].mass_per_length == pytest.approx(
            alone.edge_beams[0].mass_per_length
        )
    with pytest.raises(ValueError, match="barriers='eccentric'"):
        study_deck(40, 1, barriers="eccentric")
