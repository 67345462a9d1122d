"""The study's assessment design rebuilt from its printed tables (the one design of the library).

References: the printed Tables 2.13.8-2.13.11 (beams, trucks, road spectra), the study's
text (650 ft roads at 1 in; the longest path 600 ft), the spectrum fitted back from each
generated road (:func:`vbi_lib.fit_iso8608`), and, when present, the study's own scenario
table: every one of its generated-road scenarios is in the design.
"""

from __future__ import annotations

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import study_data as sd
from vbi_lib import units as u
from vbi_lib.assessment_design import ROAD_SPECTRA, published_assessment_design

LB_IN2 = u.lbf * u.inch**2


@pytest.fixture(scope="module")
def design() -> sd.AssessmentSet:
    return published_assessment_design()


def test_the_full_factorial_of_the_printed_tables(design) -> None:  # noqa: ANN001
    table, roads = design
    assert len(table) == 12 * 2 * 6 * 2 and len(roads) == 12
    assert set(sd.SCENARIO_COLUMNS) <= set(table.columns)
    assert set(zip(table.c10_m3, table.waviness, strict=True)) == set(ROAD_SPECTRA)
    assert sorted({(c, w) for c in (300e-6, 600e-6) for w in (2, 3, 4)}) == sorted(ROAD_SPECTRA)
    assert table.groupby(["span_ft", "n_spans", "path"]).size().eq(24).all()
    bridges, trucks, _ = sd.assessment_inputs(table, roads)
    printed = sd.table_2_13_8().set_index(["span_ft", "n_spans", "path"])["EI_lbf_in2"]
    for row, bridge in zip(table.itertuples(), bridges, strict=True):
        expected = printed.loc[(row.span_ft, row.n_spans, row.path)]
        assert bridge.EI / LB_IN2 == pytest.approx(expected, rel=1e-3)
    matching = sd.table_2_13_9()["damped_frequency_hz"]
    for row, truck in zip(table.itertuples(), trucks, strict=True):
        assert truck.mass == pytest.approx(200 * u.slinch)
        if row.vehicle.startswith("2.8 Hz"):
            assert truck.frequency_hz == pytest.approx(2.8, rel=1e-4)
            assert truck.damping_ratio == pytest.approx(0.20, rel=1e-4)
        else:
            assert truck.damped_frequency_hz == pytest.approx(matching[row.span_ft], rel=1e-4)
            assert truck.damping_ratio == pytest.approx(0.10, rel=1e-4)


def test_roads_have_the_printed_spectra(design) -> None:  # noqa: ANN001
    table, roads = design
    for name, group in table.groupby("profile"):
        road = roads[name]
        assert road.elevation[0] == 0.0 and road.spacing == pytest.approx(1 * u.inch)
        assert road.length == pytest.approx(650 * u.ft, abs=1 * u.inch)
        fit = vbi.fit_iso8608(road)
        assert fit.c10 == pytest.approx(group.c10_m3.iloc[0], rel=0.15)
        assert fit.waviness == pytest.approx(group.waviness.iloc[0], abs=0.1)
    assert len({tuple(r.elevation[:50]) for r in roads.values()}) == 12  # every draw differs


def test_the_study_set_is_inside_the_design(design, shared_data) -> None:  # noqa: ANN001
    """Each of the study's scenarios on a generated road is a row of the design."""
    study, _ = sd.read_assessment_set(shared_data / "seed-study")
    generated = study[study.profile.str.startswith("ISO_")].copy()
    assert len(generated) > 150
    generated["profile"] = generated.profile.str.removesuffix(".csv")
    keys = ["span_ft", "n_spans", "path", "k_mid_lbf_per_in", "bridge_f1_hz",
            "vehicle_k_lbf_per_in", "vehicle_c_lbf_s_per_in", "profile"]  # fmt: skip
    table, _ = design
    ours = table[keys].astype({"span_ft": float}).round(2)
    theirs = generated[keys].astype({"span_ft": float}).round(2)
    merged = theirs.merge(ours.drop_duplicates(), on=keys, how="left", indicator=True)
    assert (merged["_merge"] == "both").all(), merged[merged["_merge"] != "both"].head()


def test_bad_input_is_named() -> None:
    with pytest.raises(ValueError, match=r"seeds=\(\) must be one or more different integers"):
        published_assessment_design(seeds=())
    with pytest.raises(ValueError, match=r"seeds=\(1, 1\)"):
        published_assessment_design(seeds=(1, 1))
    with pytest.raises(TypeError, match="seeds=3 must be a list"):
        published_assessment_design(seeds=3)
    with pytest.raises(ValueError, match="length=152.4 m must cover the longest path"):
        published_assessment_design(length=500 * u.ft)
    one, roads = published_assessment_design(seeds=(7,))
    assert len(one) == 144 and all(name.endswith("_7") for name in roads)
    assert np.isin(one.seed, [7]).all()


def test_the_design_is_an_assessment_set_of_the_printed_trucks(design) -> None:  # noqa: ANN001
    """Every Table 2.13.8 beam with its Table 2.13.9 truck and the 2.8 Hz truck on the twelve
    ISO roads of Table 2.13.11, in the columns the model inputs are built from, as the
    study's own set is read (an AssessmentSet)."""
    table, roads = design
    assert design.folder is None and "generated" in repr(design)
    assert len(table) == 12 * 2 * 12 and len(roads) == 12
    assert set(table.vehicle) == {
        "10.5 Hz damped (10%)",
        "4.5 Hz damped (10%)",
        "2.5 Hz damped (10%)",
        "2.8 Hz (20%)",
    }
    beams = sd.table_2_13_8()
    assert table.groupby(["span_ft", "n_spans", "path"]).size().eq(24).all()
    assert len(table.groupby(["span_ft", "n_spans", "path"])) == len(beams)
    for name, road in roads.items():
        assert road.name == name and road.elevation[0] == 0.0
        assert road.length == pytest.approx(650 * u.ft)
        assert road.spacing == pytest.approx(1 * u.inch)
    # the roads are those of Profile.iso8608 with the stated parameters and seeds
    again = vbi.Profile.iso8608(650 * u.ft, 1 * u.inch, c10=600e-6, waviness=3, seed=2)
    np.testing.assert_allclose(
        roads["ISO_C10-600e-06_w-3_2"].elevation, again.elevation - again.elevation[0]
    )
    bridges, trucks, _ = sd.assessment_inputs(table, roads)
    slow = [t for t, v in zip(trucks, table.vehicle, strict=True) if v.startswith("2.8")]
    assert {round(t.frequency_hz, 3) for t in slow} == {2.8}
    assert {round(b.first_frequency_hz, 2) for b in bridges} == {9.95, 9.98, 3.99, 2.08}
