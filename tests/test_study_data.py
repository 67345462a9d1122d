"""The study's tables and its assessment set, against the study's own printed numbers.

References: the printed tables reproduced by the study's equations (82)-(85) through
``Bridge`` and ``Vehicle`` (the printed values are rounded: tolerances are half a unit of
the last printed digit), the frequencies stated for Table 2.13.1, the data set's README
(239 scenarios, 15 profiles, ~1 in spacing, ~656 ft), and the exact statics of
``closed_forms`` for the "exact" beams.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import vbi_lib as vbi
from vbi_lib import study_data as sd
from vbi_lib import units as u
from vbi_lib.closed_forms import point_load_statics

LB_IN = u.lbf / u.inch
LB_IN2 = u.lbf * u.inch**2


def _half_unit(printed: float, digits: int) -> float:
    """Half a unit of the last of ``digits`` significant digits of ``printed``."""
    return 0.5 * 10.0 ** (np.floor(np.log10(abs(printed))) - digits + 1)


# ---------------------------------------------------------------------------- printed tables
def test_table_2_13_8_follows_from_k_mid_and_frequency() -> None:
    """(82)-(84): each row's EI and mass per span from its K_mid and first frequency."""
    table = sd.table_2_13_8()
    assert len(table) == 12 and list(table.index) == list(range(1, 13))
    for row in table.itertuples():
        bridge = vbi.Bridge.from_midspan_stiffness(
            row.span_ft * u.ft, row.n_spans, row.k_mid_lbf_per_in * LB_IN, row.f1_hz
        )
        assert bridge.EI / LB_IN2 == pytest.approx(
            row.EI_lbf_in2, abs=_half_unit(row.EI_lbf_in2, 4)
        ), row
        assert bridge.mass_per_span / u.slinch == pytest.approx(
            row.mass_per_span_slinch, abs=0.005 + 1e-9
        ), row
        assert bridge.first_frequency_hz == pytest.approx(row.f1_hz)


def test_table_2_13_9_trucks_from_their_damped_frequency() -> None:
    table = sd.table_2_13_9()
    assert list(table.index) == [40.0, 100.0, 140.0]
    for row in table.itertuples():
        truck = vbi.Vehicle.from_frequency(
            row.mass_slinch * u.slinch, row.damped_frequency_hz, row.damping_ratio, damped=True
        )
        k = truck.stiffness / LB_IN
        assert k == pytest.approx(row.k_lbf_per_in, abs=_half_unit(row.k_lbf_per_in, 5))
        assert truck.damping / LB_IN == pytest.approx(row.c_lbf_s_per_in, abs=0.005 + 1e-9)


def test_table_2_13_10_truck() -> None:
    row = sd.table_2_13_10().iloc[0]
    truck = vbi.Vehicle.from_frequency(row.mass_slinch * u.slinch, row.frequency_hz, 0.20)
    assert truck.stiffness / LB_IN == pytest.approx(row.k_lbf_per_in, abs=0.05 + 1e-9)
    assert truck.damping / LB_IN == pytest.approx(row.c_lbf_s_per_in, abs=0.005 + 1e-9)
    assert truck.damping_ratio == pytest.approx(row.damping_ratio)


def test_table_2_15_3_and_2_15_4_parametric_study() -> None:
    for row in sd.table_2_15_3().itertuples():
        bridge = vbi.Bridge.from_frequency(
            row.span_ft * u.ft,
            1,
            row.total_mass_slinch * u.slinch / (row.span_ft * u.ft),
            row.f1_hz,
        )
        assert bridge.EI / LB_IN2 == pytest.approx(
            row.EI_lbf_in2, abs=_half_unit(row.EI_lbf_in2, 4)
        )
    for row in sd.table_2_15_4().itertuples():
        truck = vbi.Vehicle.from_frequency(row.mass_slinch * u.slinch, row.frequency_hz, 0.10)
        assert truck.stiffness / LB_IN == pytest.approx(row.k_lbf_per_in, abs=0.05 + 1e-9)


def test_table_2_13_1_gives_the_stated_frequencies() -> None:
    """The text: the validation beam vibrates at 3.00 Hz, the sprung mass at 4.00 Hz."""
    row = sd.table_2_13_1().iloc[0]
    bridge = vbi.Bridge(
        row.span_ft * u.ft,
        1,
        row.EI_lbf_in2 * LB_IN2,
        row.mass_per_length_kip_per_ft * u.kip / u.ft / u.g,
    )
    truck = vbi.Vehicle(row.vehicle_mass_slinch * u.slinch, row.vehicle_k_lbf_per_in * LB_IN)
    assert round(bridge.first_frequency_hz, 2) == 3.00
    assert round(truck.frequency_hz, 2) == 4.00


def test_validation_models_are_table_2_13_1() -> None:
    """Both validation beams carry the table's numbers; 3.00 Hz and 4.00 Hz as the text says."""
    row = sd.table_2_13_1().iloc[0]
    for n_spans in (1, 2):
        bridge, truck = sd.validation_models(n_spans)
        assert bridge.n_spans == n_spans
        assert bridge.span == pytest.approx(row.span_ft * 0.3048, rel=1e-15)
        assert bridge.EI / LB_IN2 == pytest.approx(row.EI_lbf_in2, rel=1e-12)
        # 4.6 kip/ft is a weight per length: times g per ft it is a mass per length
        weight_per_ft = bridge.mass_per_length * u.g * u.ft / u.kip
        assert weight_per_ft == pytest.approx(row.mass_per_length_kip_per_ft, rel=1e-12)
        assert round(bridge.first_frequency_hz, 2) == 3.00
        assert truck.stiffness / LB_IN == pytest.approx(row.vehicle_k_lbf_per_in, rel=1e-12)
        assert truck.damping_ratio == pytest.approx(row.vehicle_damping_ratio, rel=1e-12)
        assert round(truck.frequency_hz, 2) == 4.00
    with pytest.raises(ValueError, match="n_spans=3 must be 1 or 2"):
        sd.validation_models(3)


def test_reported_fe_tables_are_consistent_as_printed() -> None:
    """The study's per cent columns follow from its inch columns (to the printed rounding)."""
    t2 = sd.table_2_13_2().iloc[0]
    assert t2.max_diff_percent > t2.mae_percent > 0
    t3 = sd.table_2_13_3()
    for n_spans, row in t3.iterrows():
        diff = 100 * abs(row.state_space_max_in - row.fe_max_in) / abs(row.fe_max_in)
        assert diff == pytest.approx(row.diff_percent, abs=0.006), n_spans
        assert 100 * row.mae_in / abs(row.fe_max_in) == pytest.approx(row.mae_percent, abs=0.006)
    t4 = sd.table_2_13_4().iloc[0]
    diff = 100 * abs(t4.one_mode_max_in - t4.five_modes_max_in) / abs(t4.five_modes_max_in)
    # peaks printed to 1e-4 in: the difference of two of them is known to +-0.03 %
    assert diff == pytest.approx(t4.diff_percent, abs=0.03)
    mae = 100 * t4.mae_in / abs(t4.five_modes_max_in)  # MAE printed to 1e-4 in: +-0.02 %
    assert mae == pytest.approx(t4.mae_percent, abs=0.02)
    decisions = sd.table_2_13_12()
    assert decisions.loc["modes solved for and included", "selection"] == "15"
    assert decisions.loc["time step", "selection"] == "0.0015 s"


def test_tables_are_fresh_copies() -> None:
    table = sd.table_2_13_8()
    table.loc[1, "k_mid_lbf_per_in"] = 0.0
    assert sd.table_2_13_8().loc[1, "k_mid_lbf_per_in"] == 587723


# ---------------------------------------------------------------------------- assessment set
@pytest.fixture(scope="module")
def assessment(shared_data: Path) -> sd.AssessmentSet:
    return sd.read_assessment_set(shared_data / "seed-study")


def test_the_assessment_set_is_what_its_readme_says(assessment, shared_data: Path) -> None:  # noqa: ANN001
    table, profiles = assessment
    assert len(table) == len(assessment) == 239
    assert len(profiles) == 15
    assert set(table["profile"]) == set(profiles)
    for name, road in profiles.items():
        assert road.name == name
        assert road.spacing == pytest.approx(1 * u.inch, rel=0.02)
        assert road.length == pytest.approx(656 * u.ft, rel=0.01)
        assert road.start == 0.0 and road.elevation[0] == 0.0
    # the same numbers as a plain reading of one file (inches, first elevation subtracted)
    raw = np.loadtxt(shared_data / "seed-study" / "profiles" / "real_2.csv", delimiter=",")
    np.testing.assert_allclose(profiles["real_2.csv"].x, raw[:, 0] * u.inch, rtol=1e-15)
    np.testing.assert_allclose(
        profiles["real_2.csv"].elevation, (raw[:, 1] - raw[0, 1]) * u.inch, atol=1e-15
    )
    assert "239 scenarios, 15 profiles" in repr(assessment)


def test_every_scenario_is_a_printed_beam_and_a_printed_truck(assessment) -> None:  # noqa: ANN001
    """The data set's rows against Tables 2.13.8, 2.13.9 and 2.13.10."""
    beams = {
        (r.span_ft, r.n_spans, r.k_mid_lbf_per_in, r.f1_hz) for r in sd.table_2_13_8().itertuples()
    }
    trucks = sd.table_2_13_9()
    common = sd.table_2_13_10().iloc[0]
    for row in assessment.table.itertuples():
        assert (row.span_ft, row.n_spans, row.k_mid_lbf_per_in, row.bridge_f1_hz) in beams
        own = trucks.loc[float(row.span_ft)]
        truck = (row.vehicle_mass_slinch, row.vehicle_k_lbf_per_in, row.vehicle_c_lbf_s_per_in)
        assert truck in {
            (own.mass_slinch, own.k_lbf_per_in, own.c_lbf_s_per_in),
            (common.mass_slinch, common.k_lbf_per_in, common.c_lbf_s_per_in),
        }, row


def test_assessment_inputs_study_and_exact_beams(assessment) -> None:  # noqa: ANN001
    table, profiles = assessment
    study, trucks, roads = sd.assessment_inputs(table, profiles, beam="study")
    exact, _, _ = sd.assessment_inputs(table, profiles, beam="exact")
    assert len(study) == len(trucks) == len(roads) == len(exact) == 239
    for row, b, e, t, r in zip(table.itertuples(), study, exact, trucks, roads, strict=True):
        k_mid = row.k_mid_lbf_per_in * LB_IN
        # the study's beam: the one-coordinate model's midspan stiffness is K_mid
        model = b.static_deflection(1.0) if b.n_spans == 2 else b.exact_static_deflection(1.0)
        assert 1.0 / model == pytest.approx(k_mid, rel=1e-12)
        # the exact beam: a real beam's midspan stiffness (closed-form statics) is K_mid
        w = point_load_statics(e.span / 2, e.span / 2, e.span, e.EI, e.n_spans).deflection
        assert 1.0 / float(w) == pytest.approx(k_mid, rel=1e-12)
        assert b.first_frequency_hz == pytest.approx(row.bridge_f1_hz)
        assert e.first_frequency_hz == pytest.approx(row.bridge_f1_hz)
        assert b.damping_ratio == e.damping_ratio == 0.01
        assert t.mass == pytest.approx(row.vehicle_mass_slinch * u.slinch)
        assert t.damping == pytest.approx(row.vehicle_c_lbf_s_per_in * LB_IN)
        assert r is profiles[row.profile]


def test_assessment_inputs_errors_name_the_row() -> None:
    row = dict(
        span_ft=40,
        n_spans=2,
        k_mid_lbf_per_in=721006,
        bridge_f1_hz=9.98,
        vehicle_mass_slinch=200,
        vehicle_k_lbf_per_in=879290.0,
        vehicle_c_lbf_s_per_in=2652.23,
        profile="flat",
    )
    road = {"flat": vbi.Profile.flat(200.0, 0.0254)}
    with pytest.raises(ValueError, match="beam='fe' must be 'study', 'exact' or 'deck'"):
        sd.assessment_inputs(pd.DataFrame([row]), road, beam="fe")
    with pytest.raises(ValueError, match="row 1: profile 'rough' is not among"):
        sd.assessment_inputs(pd.DataFrame([row, {**row, "profile": "rough"}]), road)
    with pytest.raises(ValueError, match="row 0: n_spans=3 is not supported"):
        sd.assessment_inputs(pd.DataFrame([{**row, "n_spans": 3}]), road)


def _write_set(folder: Path, profile_text: str = "0,0.5\n1,0.75\n2,0.25\n") -> None:
    folder.mkdir()
    (folder / "profiles").mkdir()
    (folder / "profiles" / "p.csv").write_text(profile_text)
    columns = ",".join(sd.SCENARIO_COLUMNS)
    (folder / "scenarios-239.csv").write_text(
        f"{columns}\n100,1,497527,3.99,200,161500,1136.67,p.csv\n"
    )


def test_a_small_set_reads_in_metres_from_zero(tmp_path: Path) -> None:
    _write_set(tmp_path / "set")
    table, profiles = sd.read_assessment_set(tmp_path / "set")
    assert len(table) == 1
    np.testing.assert_allclose(profiles["p.csv"].x, [0.0, 0.0254, 0.0508])
    np.testing.assert_allclose(profiles["p.csv"].elevation, [0.0, 0.25 * 0.0254, -0.25 * 0.0254])


def test_reader_errors_name_the_path(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError, match="no assessment data set at .*nothere"):
        sd.read_assessment_set(tmp_path / "nothere")
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(FileNotFoundError, match="empty/scenarios-239.csv' does not exist"):
        sd.read_assessment_set(empty)
    _write_set(tmp_path / "short")
    (tmp_path / "short" / "scenarios-239.csv").write_text("span_ft,n_spans\n100,1\n")
    with pytest.raises(ValueError, match="lacks the column.*k_mid_lbf_per_in"):
        sd.read_assessment_set(tmp_path / "short")
    _write_set(tmp_path / "lost")
    (tmp_path / "lost" / "profiles" / "p.csv").unlink()
    with pytest.raises(FileNotFoundError, match="lost/profiles/p.csv' does not exist"):
        sd.read_assessment_set(tmp_path / "lost")
    _write_set(tmp_path / "bad", profile_text="0,0\n1,x\n")
    with pytest.raises(vbi.ProfileFileError, match="p.csv, line 2: elevation 'x'"):
        sd.read_assessment_set(tmp_path / "bad")
