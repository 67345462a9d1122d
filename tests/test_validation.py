"""The study's model assessment (Chapter 13) reproduced against its 3D finite-element DAFs.

Targets (issue 5): with the better of our two models, a mean absolute error of at most 10 %
on one-span bridges and 13 % on two-span bridges.  The study's own model scored 18 % and
26 % (recomputed from the same table; README of the data set).  No model parameter is fitted
to the finite-element results: every one comes from the row's bridge and truck data.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import study_data as sd
from vbi_lib.studies import agreement

SPEED = sd.ASSESSMENT_SPEED  # 720 in/s
BRIDGE_START = sd.ASSESSMENT_BRIDGE_START  # 3840 in


@pytest.fixture(scope="module")
def assessment(shared_data: Path):  # noqa: ANN201
    table, profiles = sd.read_assessment_set(shared_data / "seed-study")
    one_span = table.n_spans.to_numpy() == 1
    fe = table.fe_daf.to_numpy()

    # most of these crossings lose contact (the study's worst-case truck); that is
    # reported by the models and examined in the book, not here
    warnings.simplefilter("ignore", vbi.ContactLossWarning)
    study_beams, trucks, roads = sd.assessment_inputs(table, profiles, beam="study")
    two_dof = np.array(
        [
            vbi.simulate(b, t, r, SPEED, BRIDGE_START).daf.max()
            for b, t, r in zip(study_beams, trucks, roads, strict=True)
        ]
    )
    exact_beams, _, _ = sd.assessment_inputs(table, profiles, beam="exact")
    many = vbi.simulate_many(
        exact_beams, trucks, roads, SPEED, BRIDGE_START, model="modal", modes=5
    )
    return {
        "table": table,
        "fe": fe,
        "one": one_span,
        "two_dof": two_dof,
        "many": np.nanmax(many.daf, axis=1),
    }


def test_the_table_has_239_scenarios(assessment) -> None:  # noqa: ANN001
    assert len(assessment["table"]) == 239
    assert assessment["one"].sum() + (~assessment["one"]).sum() == 239


def test_the_study_scores_are_those_published(assessment) -> None:  # noqa: ANN001
    """The metric code against the numbers stated for the study's own model."""
    study = assessment["table"].study_statespace_daf.to_numpy()
    fe, one = assessment["fe"], assessment["one"]
    s1 = agreement(study[one], fe[one])
    s2 = agreement(study[~one], fe[~one])
    assert (s1["r2"], s2["r2"]) == pytest.approx((0.936, 0.881), abs=5e-4)
    assert (s1["mape"], s2["mape"]) == pytest.approx((0.18, 0.26), abs=5e-3)
    assert (s1["bias"], s2["bias"]) == pytest.approx((0.15, 0.25), abs=5e-3)


def test_the_better_model_meets_the_targets(assessment) -> None:  # noqa: ANN001
    fe, one = assessment["fe"], assessment["one"]
    for mask, target in ((one, 0.10), (~one, 0.13)):
        scores = [agreement(assessment[m][mask], fe[mask]) for m in ("two_dof", "many")]
        best = min(s["mape"] for s in scores)
        assert best <= target, f"best mean absolute error {best:.2%} > {target:.0%}: {scores}"


def test_many_mode_model_is_nearly_unbiased_on_both_bridge_types(assessment) -> None:  # noqa: ANN001
    """The study's model overestimated by 15 % and 25 %; the many-mode beam within 5 %."""
    fe, one = assessment["fe"], assessment["one"]
    for mask in (one, ~one):
        scores = agreement(assessment["many"][mask], fe[mask])
        assert abs(scores["bias"]) < 0.05, scores
        assert scores["mape"] < 0.13, scores
