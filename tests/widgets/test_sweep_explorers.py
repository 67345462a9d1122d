"""The speed and frequency-matching explorers: every control, checked crossing by crossing
against direct ``vbi.simulate`` calls, the resonances where physics puts them, progress."""

from __future__ import annotations

import numpy as np
import pytest
from explorer_cases import CHANGES, direct_crossing, resolve, write_profiles

from vbi_lib import amplification
from vbi_lib import units as u
from vbi_lib.widgets import FrequencyExplorer, FrequencyMap, SpeedExplorer

SPEED_KEYS = sorted(SpeedExplorer.parameters)
FREQUENCY_KEYS = sorted(FrequencyExplorer.parameters)
SMALL_SPEED = {"n_speeds": 3, "speed_range_mph": (30.0, 60.0)}
SMALL_MAP = {"n_ratios": 3, "n_speeds": 3, "speed_range_mph": (40.0, 60.0)}


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    return write_profiles(tmp_path_factory.mktemp("profiles"))


def speed_sweep_by_hand(explorer: SpeedExplorer) -> np.ndarray:
    """DAF of each span at each speed of the sweep, one ``vbi.simulate`` each."""
    values = explorer.values()
    low, high = values["speed_range_mph"]
    out = np.full((values["n_speeds"], 2), np.nan)
    for i, mph in enumerate(np.linspace(low, high, values["n_speeds"])):
        daf = direct_crossing({**values, "speed_mph": mph}).daf
        out[i, : daf.size] = daf
    return out


def frequency_map_by_hand(explorer: FrequencyExplorer) -> np.ndarray:
    """DAF of each span in each (speed, ratio) cell, one ``vbi.simulate`` each."""
    values = explorer.values()
    ratios = np.linspace(*values["ratio_range"], values["n_ratios"])
    speeds = np.linspace(*values["speed_range_mph"], values["n_speeds"])
    out = np.full((speeds.size, ratios.size, 2), np.nan)
    for i, mph in enumerate(speeds):
        for j, ratio in enumerate(ratios):
            cell = {
                **values,
                "speed_mph": mph,
                "truck_frequency_hz": ratio * values["bridge_frequency_hz"],
            }
            daf = direct_crossing(cell).daf
            out[i, j, : daf.size] = daf
    return out


def test_the_sweeps_offer_every_input_but_the_one_they_sweep() -> None:
    assert "speed_mph" not in SPEED_KEYS and {"speed_range_mph", "n_speeds"} <= set(SPEED_KEYS)
    assert not {"speed_mph", "truck_frequency_hz"} & set(FREQUENCY_KEYS)
    assert {"ratio_range", "n_ratios", "speed_range_mph", "n_speeds"} <= set(FREQUENCY_KEYS)
    assert set(SPEED_KEYS) | set(FREQUENCY_KEYS) <= set(CHANGES)


@pytest.mark.parametrize("name", SPEED_KEYS)
def test_every_control_of_the_speed_explorer(name: str, files: dict[str, str]) -> None:
    setup, new = CHANGES[name]
    explorer = SpeedExplorer(**resolve({**SMALL_SPEED, **setup}, files))
    before = explorer.result.daf.copy()
    explorer.controls[name].value = resolve({name: new}, files)[name]
    after = explorer.result
    assert after is not None, explorer.error
    np.testing.assert_allclose(after.daf, speed_sweep_by_hand(explorer), rtol=1e-9)
    assert after.daf.shape != before.shape or not np.allclose(after.daf, before, equal_nan=True)


@pytest.mark.parametrize("name", FREQUENCY_KEYS)
def test_every_control_of_the_frequency_explorer(name: str, files: dict[str, str]) -> None:
    setup, new = CHANGES[name]
    explorer = FrequencyExplorer(**resolve({**SMALL_MAP, **setup}, files))
    before = explorer.result
    explorer.controls[name].value = resolve({name: new}, files)[name]
    assert explorer.result is before, "the map waits for its button"
    assert "The controls changed" in explorer.readout.value
    explorer.button.click()
    after = explorer.result
    assert after is not None, explorer.error
    np.testing.assert_allclose(after.daf, frequency_map_by_hand(explorer), rtol=1e-9)
    assert after.daf.shape != before.daf.shape or not np.allclose(
        after.daf, before.daf, equal_nan=True
    )
    assert "The controls changed" not in explorer.readout.value


def test_more_bridge_damping_lowers_the_peak_daf_over_speed() -> None:
    explorer = SpeedExplorer(amplitude_in=0.1, n_speeds=15)
    peaks = []
    for zeta in (0.0, 0.01, 0.03, 0.1):
        explorer.controls["bridge_damping"].value = zeta
        assert not explorer.result.lost_contact.any()
        peaks.append(np.nanmax(explorer.result.daf))
    assert np.all(np.diff(peaks) < 0), peaks


def test_the_bridge_resonates_where_the_road_drives_it_at_its_frequency() -> None:
    """Harmonic road, truck and bridge both at 3 Hz: the DAF peaks at v = f1 * wavelength."""
    explorer = FrequencyExplorer(
        amplitude_in=0.1, ratio_range=(0.5, 1.5), n_ratios=3, speed_range_mph=(30, 90), n_speeds=31
    )
    result = explorer.result
    column = result.daf[:, 1, 0]  # ratio 1
    resonance = 3.0 * 30 * u.ft  # m/s
    step = result.speed[1] - result.speed[0]
    assert abs(result.speed[np.argmax(column)] - resonance) <= step
    assert result.truck_frequency_hz[1] == pytest.approx(3.0)


def test_the_speed_explorer_draws_the_codes_and_the_forcing_frequency() -> None:
    explorer = SpeedExplorer(span_ft=80.0, bridge_frequency_hz=5.25, **SMALL_SPEED)
    lines = explorer.code_lines
    assert lines["AASHTO LRFD"].get_ydata()[0] == 1 + amplification.aashto_lrfd_allowance()
    assert lines["AASHTO Standard"].get_ydata()[0] == pytest.approx(1 + 50 / (80 + 125))
    assert lines["OHBDC 1983"].get_ydata()[0] == pytest.approx(1.325)  # halfway 4.5-6 Hz
    # harmonic road of 30 ft: the top axis reads v / wavelength
    v = explorer.daf_lines[0].get_xdata()
    forcing = explorer.frequency_axis._functions[0](v)
    np.testing.assert_allclose(forcing, explorer.result.speed / (30 * u.ft))
    np.testing.assert_allclose(explorer.daf_lines[0].get_ydata(), explorer.result.daf[:, 0])


def test_a_sweep_that_loses_contact_says_so_and_marks_it() -> None:
    explorer = SpeedExplorer(amplitude_in=0.5, n_speeds=12, speed_range_mph=(40, 90))
    lost = explorer.result.lost_contact
    assert lost.any() and not lost.all()
    text = explorer.readout.value
    assert f"{lost.sum()} of {lost.size} crossings lost contact" in text
    assert "outside the model's validity" in text
    assert len(explorer.lost_daf.get_xdata()) == lost.sum()


def test_a_long_sweep_is_drawn_progressively() -> None:
    explorer = SpeedExplorer(n_speeds=3)
    explorer.render_interval = 0.0
    seen: list[str] = []
    explorer.readout.observe(lambda change: seen.append(change["new"]), names="value")
    renders = explorer.view.renders
    explorer.set(n_speeds=80)  # two chunks of 64 and 16
    assert explorer.view.renders == renders + 2
    assert any("computing: 64 of 80 crossings done" in text for text in seen)
    assert "computing" not in explorer.readout.value


def test_bad_settings_empty_the_map_and_say_why() -> None:
    explorer = FrequencyExplorer(**SMALL_MAP)
    explorer.controls["road"].value = "measured"
    assert explorer.result is None
    assert "profile_path is empty" in explorer.readout.value
    explorer.controls["road"].value = "harmonic"
    assert explorer.result is None  # still waits for the button
    explorer.button.click()
    assert explorer.result is not None


def test_the_frequency_map_exports_and_plots_itself() -> None:
    import matplotlib

    matplotlib.use("Agg")
    result = FrequencyExplorer(**SMALL_MAP).result
    assert isinstance(result, FrequencyMap)
    table = result.to_dataframe()
    assert len(table) == 9
    np.testing.assert_allclose(table["daf span 1"], result.daf[..., 0].ravel())
    np.testing.assert_allclose(table["truck frequency [Hz]"].iloc[:3], result.ratio * 3.0)
    ax = result.plot()
    np.testing.assert_allclose(ax.images[0].get_array(), result.largest_daf)
