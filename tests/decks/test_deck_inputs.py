"""Bad input to a deck is refused by name, value and what is allowed; odd input is warned of."""

from __future__ import annotations

import warnings

import pandas as pd
import pytest

import vbi_lib as vbi
from vbi_lib import study_data as sd
from vbi_lib.decks import (
    Deck,
    Diaphragms,
    EdgeBeam,
    Girders,
    GirderSection,
    WheelPath,
    midspan_stiffness,
)
from vbi_lib.decks.study import study_deck, study_site

SLAB = dict(width=10.0, thickness=0.2, E=30e9, poisson=0.2, density=2400.0)
GIRDERS = Girders(4, 2.5, EI=4e9, mass_per_length=400.0)


def deck(**changes: object) -> Deck:
    arguments = dict(spans=(20.0,), **SLAB, girders=GIRDERS)
    arguments.update(changes)
    return Deck(**arguments)


REFUSED = [
    ("a negative span", lambda: deck(spans=(-20.0,)), ValueError, "spans[0]=-20.0"),
    ("a span as text", lambda: deck(spans=("20",)), TypeError, "spans[0]='20'"),
    ("no spans", lambda: deck(spans=()), ValueError, "spans=()"),
    ("a width as text", lambda: deck(width="10 m"), TypeError, "width='10 m'"),
    ("Poisson 0.5", lambda: deck(poisson=0.5), ValueError, "poisson=0.5 must be"),
    ("a zero thickness", lambda: deck(thickness=0.0), ValueError, "thickness=0.0 must be"),
    ("a skew without hand", lambda: deck(skew=20.0), ValueError, "skew_hand='left'"),
    ("a skew of 70", lambda: deck(skew=70.0, skew_hand="left"), ValueError, "skew=70.0"),
    ("an unknown hand", lambda: deck(skew=20.0, skew_hand="up"), ValueError, "skew_hand='up'"),
    (
        "girders wider than the deck",
        lambda: deck(girders=Girders(6, 2.5, EI=4e9, mass_per_length=400.0)),
        ValueError,
        "more than width=10 m",
    ),  # fmt: skip
    ("an overhang too long", lambda: deck(overhang=4.0), ValueError, "overhang=4 m puts"),
    (
        "a bare slab with an overhang",
        lambda: Deck(20.0, **SLAB, overhang=1.0),
        ValueError,
        "overhang=1.0 needs girders",
    ),  # fmt: skip
    (
        "a girder count as float",
        lambda: Girders(2.0, 2.5, EI=4e9, mass_per_length=1.0),
        TypeError,
        "count=2.0",
    ),  # fmt: skip
    ("girders without EI", lambda: Girders(3, 2.5), ValueError, "EI=None"),
    (
        "EI for the wrong number of girders",
        lambda: Girders(3, 2.5, EI=(1e9, 2e9), mass_per_length=1.0),
        ValueError,
        "one per girder (3 of them)",
    ),  # fmt: skip
    (
        "a section and an EI",
        lambda: Girders(
            3,
            2.5,
            EI=1e9,
            mass_per_length=1.0,
            section=GirderSection(0.01, 1e-3, 0.7, 200e9, 7850.0),
        ),
        ValueError,
        "not both",
    ),  # fmt: skip
    (
        "an EI below the slab's own",
        lambda: deck(girders=Girders(4, 2.5, EI=1e6, mass_per_length=1.0)),
        ValueError,
        "must exceed the slab's own rigidity",
    ),  # fmt: skip
    (
        "a diaphragm off the deck",
        lambda: deck(diaphragms=Diaphragms(1e8, stations=(25.0,))),
        ValueError,
        "off the deck",
    ),  # fmt: skip
    ("edge beams as a number", lambda: deck(edge_beams=3.0), TypeError, "edge_beams=3.0"),
    (
        "an edge beam of negative mass",
        lambda: EdgeBeam(mass_per_length=-1.0),
        ValueError,
        "mass_per_length=-1.0",
    ),  # fmt: skip
    ("a resolution of zero", lambda: deck(resolution=(0, 5)), ValueError, "resolution[0]=0"),
    (
        "a resolution of floats",
        lambda: deck(resolution=(12.0, 5)),
        TypeError,
        "resolution[0]=12.0",
    ),  # fmt: skip
    (
        "sides neither free nor supported",
        lambda: deck(sides="clamped"),
        ValueError,
        "sides='clamped'",
    ),  # fmt: skip
    ("a path to the side", lambda: WheelPath(1.0, direction=2), ValueError, "direction=2"),
    ("a negative track", lambda: WheelPath(1.0, track=-1.0), ValueError, "track=-1.0"),
    ("the 140 ft deck", lambda: study_deck(140, 1), ValueError, "span_ft=140"),
    ("a skewed 100 ft deck", lambda: study_deck(100, 1, "left"), ValueError, "skew_hand='left'"),
    ("a path the study lacks", lambda: study_site(40, 1, 3, 5e8, 9.95), ValueError, "path=3"),
]


@pytest.mark.parametrize(("case", "call", "error", "says"), REFUSED, ids=[c[0] for c in REFUSED])
def test_bad_input_is_refused_by_name(case: str, call, error: type, says: str) -> None:  # noqa: ANN001
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)
        with pytest.raises(error) as caught:
            call()
    assert says in str(caught.value), str(caught.value)


def test_bad_positions_and_counts_on_the_modes_are_refused() -> None:
    modes = deck().modes(4)
    with pytest.raises(ValueError, match="y must lie on the deck"):
        modes.shape([5.0], [11.0])
    with pytest.raises(ValueError, match="must be finite"):
        modes.shape([float("nan")], [1.0])
    with pytest.raises(TypeError, match="x="):
        modes.shape("5", [1.0])
    with pytest.raises(ValueError, match=r"loads must be \(x, y\) points"):
        modes.static_flexibility([1.0, 2.0, 3.0], [(5.0, 5.0)])
    with pytest.raises(ValueError, match="n=0"):
        deck().modes(0)
    with pytest.raises(ValueError, match="at most second derivatives"):
        modes.derivative([5.0], [5.0], along=2, across=1)
    with pytest.raises(ValueError, match="off the deck"):
        modes.path_tables(WheelPath(9.5), [(10.0, 5.0)])
    with pytest.raises(ValueError, match="girder=5"):
        midspan_stiffness(deck(), WheelPath(5.0), girder=5)
    with pytest.raises(ValueError, match="span=2"):
        midspan_stiffness(deck(), WheelPath(5.0), girder=1, span=2)


def test_odd_input_is_warned_of() -> None:
    with pytest.warns(vbi.OutsideValidityWarning, match="skew=40"):
        deck(skew=40.0, skew_hand="right")
    with pytest.warns(vbi.OutsideValidityWarning, match="thickness=0.05"):
        deck(thickness=0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.OutsideValidityWarning)
        deck(skew=16.0, skew_hand="left")


def test_assessment_inputs_refuse_a_hand_without_decks_and_a_table_without_paths() -> None:
    row = dict(span_ft=40, n_spans=1, path=1, k_mid_lbf_per_in=587723, bridge_f1_hz=9.95,
               vehicle_mass_slinch=200, vehicle_k_lbf_per_in=879290.0,
               vehicle_c_lbf_s_per_in=2652.23, profile="flat")  # fmt: skip
    roads = {"flat": vbi.Profile.flat(200.0, 0.0254)}
    with pytest.raises(ValueError, match="skew_hand='left' applies to beam='deck' only"):
        sd.assessment_inputs(pd.DataFrame([row]), roads, beam="exact", skew_hand="left")
    no_path = {k: v for k, v in row.items() if k != "path"}
    with pytest.raises(ValueError, match="'path' column"):
        sd.assessment_inputs(pd.DataFrame([no_path]), roads, beam="deck")
    with pytest.raises(ValueError, match="row 0: skew_hand='up' must be"):
        sd.assessment_inputs(pd.DataFrame([row]), roads, beam="deck", skew_hand="up")
    with pytest.raises(ValueError, match="beam='plate' must be 'study', 'exact' or 'deck'"):
        sd.assessment_inputs(pd.DataFrame([row]), roads, beam="plate")


def test_a_deck_is_frozen_and_equal_to_its_twin() -> None:
    a, b = deck(), deck()
    assert a == b and hash(a) == hash(b)
    with pytest.raises(AttributeError):
        a.width = 12.0  # type: ignore[misc]
    assert "4 girders at 2.500 m" in repr(a)
    assert repr(Deck.plate(10.0, 8.0, 0.2, 30e9, 0.2, 2400.0)).startswith("Deck(spans 10.00 m")
