"""Roughness metrics: IRI, ISO 8608 fit, the vehicle-only contact-force metric.

References, all independent of the stepping code under test:
- the golden car's steady-state response to a sine, solved here in complex arithmetic from
  its equations of motion (with the 250 mm moving average's gain), Sayers (1995);
- the IRI written in the header of a published ERD file (freevryheid/iri);
- the random-process IRI of a white-slope road (ISO 8608, w = 2) integrated from the same
  transfer function;
- the spectrum the ISO road was generated with;
- the steady-state base-excitation response of a sprung mass (vbi_lib.closed_forms, itself
  checked against a numerical integration), and ``vbi.simulate`` with
  ``coupled=False`` (a different integrator, RK4) for the rigid-road contact force.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy import integrate

import vbi_lib as vbi

K1, K2, C, MU = 653.0, 63.3, 6.0, 0.15
V = 80 / 3.6


def golden_car_iri_of_sine(amplitude: float, wavelength: float, base: float = 0.25) -> float:
    """Steady-state IRI [m/km] of ``amplitude sin(2 pi x / wavelength)``, from first principles.

    Displacement input y through the tyre; sprung mass zs, unsprung zu (per unit sprung mass):
        zs'' = -k2 (zs - zu) - c (zs' - zu')
        mu zu'' = k2 (zs - zu) + c (zs' - zu') - k1 (zu - y)
    The 250 mm moving average scales a sine by sinc(base / wavelength).  IRI is the mean of
    |zs' - zu'| / V: for a sine, 2/pi times its amplitude.
    """
    omega = 2 * np.pi * V / wavelength
    s = 1j * omega
    gain = np.sinc(base / wavelength)  # numpy sinc is sin(pi t)/(pi t)
    matrix = np.array(
        [[s**2 + C * s + K2, -(C * s + K2)], [-(C * s + K2), MU * s**2 + C * s + K2 + K1]]
    )
    zs, zu = np.linalg.solve(matrix, np.array([0.0, K1 * amplitude * gain]))
    return float(2 / np.pi * abs(s * (zs - zu)) / V * 1000)


def test_reference_transfer_function_gives_the_issue_numbers() -> None:
    assert golden_car_iri_of_sine(1e-3, 10.0) == pytest.approx(0.503, abs=0.0006)
    assert golden_car_iri_of_sine(1e-3, 2.0) == pytest.approx(2.99, abs=0.006)


@pytest.mark.parametrize("wavelength", [1.0, 2.0, 5.0, 10.0, 20.0, 40.0])
def test_iri_of_a_long_sine_matches_the_steady_state_closed_form(wavelength: float) -> None:
    road = vbi.Profile.harmonic(3000.0, 0.025, wavelength=wavelength, amplitude=1e-3)
    assert vbi.iri(road).iri == pytest.approx(golden_car_iri_of_sine(1e-3, wavelength), rel=0.01)


def test_a_straight_grade_has_zero_iri() -> None:
    grade = vbi.Profile.ramp(500.0, 0.025, position=0.0, rise=10.0, run=500.0)
    assert abs(vbi.iri(grade).iri) < 1e-9


def test_iri_is_linear_in_amplitude() -> None:
    road = vbi.Profile.iso8608(400.0, 0.05, c10=100e-6, seed=3)
    double = vbi.Profile(road.x, 2.5 * road.elevation)
    assert vbi.iri(double).iri == pytest.approx(2.5 * vbi.iri(road).iri, rel=1e-10)


def test_iri_of_the_published_two_channel_run(shared_data: Path) -> None:
    """The ERD header states IRILWP 183 and IRIRWP 163 in/mi."""
    erd = vbi.read_erd(shared_data / "profiles" / "basic-2channel.erd")
    left, right = (vbi.iri(channel).iri * vbi.roughness.IN_PER_MI for channel in erd)
    assert round(left) == int(erd.header["IRILWP"]) == 183
    assert round(right) == int(erd.header["IRIRWP"]) == 163


def test_iri_of_a_random_iso_road_with_w_2() -> None:
    """For w = 2 the slope is white: IRI = sqrt(2/pi) sigma, sigma from the transfer function."""
    c10 = 256e-6

    def psd_of_stroke_rate(n: float) -> float:
        stroke = golden_car_iri_of_sine(1.0, 1.0 / n) * np.pi / 2 / 1000  # |H| of unit sine
        return c10 * (n / 0.1) ** -2 * stroke**2

    variance = integrate.quad(psd_of_stroke_rate, 0.011, 2.83, limit=200, points=[0.1, 1.0])[0]
    expected = np.sqrt(2 / np.pi) * np.sqrt(variance) * 1000
    assert expected / np.sqrt(c10 / 1e-6) == pytest.approx(0.543, abs=0.002)
    values = [vbi.iri(vbi.Profile.iso8608(3000.0, 0.025, c10=c10, seed=s)).iri for s in range(4)]
    assert np.mean(values) == pytest.approx(expected, rel=0.02)


def test_segment_iri_carries_the_state_and_averages_to_the_whole() -> None:
    road = vbi.Profile.harmonic(2000.0, 0.025, wavelength=5.0, amplitude=1e-3)
    per_segment = vbi.iri(road, segment_length=160.0)
    assert len(per_segment) == 13  # 12 full segments and one of 80 m
    assert per_segment.stop[-1] == pytest.approx(2000.0)
    # with the state carried there is no restart transient: every segment is steady state
    np.testing.assert_allclose(
        per_segment.segment_iri, golden_car_iri_of_sine(1e-3, 5.0), rtol=0.01
    )
    assert per_segment.iri == pytest.approx(vbi.iri(road).iri)
    lengths = per_segment.stop - per_segment.start
    weighted = np.sum(per_segment.segment_iri * lengths) / np.sum(lengths)
    assert weighted == pytest.approx(per_segment.iri, rel=2e-3)


def test_segment_iri_sees_a_rough_patch_where_it_is() -> None:
    flat = np.zeros(4001)
    x = 0.025 * np.arange(4001)
    patch = (x > 40) & (x < 60)
    flat[patch] = 0.002 * np.sin(2 * np.pi * (x[patch] - 40) / 2.0)
    per_segment = vbi.iri(vbi.Profile(x, flat), segment_length=20.0)
    values = per_segment.segment_iri
    assert values[0] == pytest.approx(0.0, abs=1e-12)
    assert values[2] > 3.0
    assert values[2] > 5 * max(values[1], values[4])


def test_iri_returns_one_kind_of_result_whatever_is_asked() -> None:
    """Without a segment length: one segment, the whole road, holding the whole-road value."""
    road = vbi.Profile.harmonic(600.0, 0.025, wavelength=8.0, amplitude=1e-3)
    whole = vbi.iri(road)
    split = vbi.iri(road, segment_length=200.0)
    assert type(whole) is type(split) is vbi.roughness.IriResult
    assert len(whole) == 1 and whole.segment_length is None
    assert whole.segment_iri[0] == whole.iri == split.iri
    assert (whole.start[0], whole.stop[0]) == (0.0, pytest.approx(600.0))
    # the steady-state closed form, whichever way the value is read
    assert whole.iri == pytest.approx(golden_car_iri_of_sine(1e-3, 8.0), rel=0.01)
    table = split.to_dataframe()
    assert list(table.columns) == ["start_m", "stop_m", "iri_m_per_km"]
    assert table.index.name == "segment" and len(table) == 3
    np.testing.assert_allclose(table["stop_m"] - table["start_m"], 200.0)
    assert "3 segments of 200 m" in repr(split) and "IRI" in repr(whole)
    assert split.valid.all()


def test_a_last_piece_without_a_slope_step_joins_the_segment_before_it() -> None:
    """The last 0.1 m of a 100.1 m road holds no step: no NaN segment, the one before grows.

    Reference: the mean suspension stroke of the steps in each segment, from the whole
    road's IRI of a sine (the same in every segment to the accuracy of a steady state).
    """
    road = vbi.Profile.harmonic(100.1, 0.025, wavelength=8.0, amplitude=1e-3)
    result = vbi.iri(road, segment_length=50.0)
    assert len(result) == 2 and result.valid.all()
    assert result.stop.tolist() == [50.0, pytest.approx(100.1)]
    whole = vbi.iri(vbi.Profile.harmonic(3000.0, 0.025, wavelength=8.0, amplitude=1e-3)).iri
    np.testing.assert_allclose(result.segment_iri, whole, rtol=0.05)


def test_iri_rejects_too_short_and_bad_segments() -> None:
    with pytest.raises(ValueError, match="shorter than the IRI's"):
        vbi.iri(vbi.Profile(np.array([0.0, 0.1]), np.zeros(2)))
    with pytest.raises(ValueError, match="segment_length"):
        vbi.iri(vbi.Profile.flat(10.0, 0.025), segment_length=0.0)


# ---------------------------------------------------------------------------- ISO 8608 fit
@pytest.mark.parametrize(("c10", "waviness"), [(300e-6, 2.0), (600e-6, 3.0), (64e-6, 4.0)])
def test_fit_recovers_the_spectrum_of_a_generated_road(c10: float, waviness: float) -> None:
    for seed in range(3):
        road = vbi.Profile.iso8608(4000.0, 0.05, c10=c10, waviness=waviness, seed=seed)
        fitted_c10, fitted_w = vbi.fit_iso8608(road)
        assert fitted_c10 == pytest.approx(c10, rel=0.05)
        assert fitted_w == pytest.approx(waviness, abs=0.05)


def test_spectrum_bands_and_class() -> None:
    road = vbi.Profile.iso8608(2000.0, 0.05, c10=600e-6, waviness=2.0, seed=1)
    spectrum = vbi.profile_spectrum(road)
    assert spectrum.iso_class == "D"
    ratio = spectrum.band_frequency[1:] / spectrum.band_frequency[:-1]
    np.testing.assert_allclose(ratio, 2 ** (1 / 3))  # consecutive 1/3-octave bands
    # the band averages follow the generating spectrum
    generating = 600e-6 * (spectrum.band_frequency / 0.1) ** -2
    assert np.abs(np.log(spectrum.band_psd / generating)).max() < np.log(1.3)


def test_fit_of_a_too_short_road_says_why() -> None:
    with pytest.raises(ValueError, match="fewer than two 1/3-octave bands"):
        vbi.fit_iso8608(vbi.Profile.iso8608(3.0, 0.05, c10=1e-4, seed=1))


@pytest.mark.parametrize("c10", [300e-6, 600e-6])
@pytest.mark.parametrize("waviness", [2, 3, 4])
def test_fit_of_the_studys_own_iso_files(shared_data: Path, c10: float, waviness: int) -> None:
    """The study's files (inches) carry their C10 and w in their names.

    Its generator scaled the amplitudes a little differently from ISO's sqrt(2 G dn) (its
    fits come out 10-25 % above the nominal C10 and ~0.1 above w, for every file), and a
    650 ft road scatters ~10 %: the tolerance is loose, but a unit or fitting error would be
    off by far more.
    """
    for draw in (1, 2):
        name = f"ISO_C10-{c10 * 1e6:.0f}e-06_w-{waviness}_{draw}.csv"
        road = vbi.read_profile(shared_data / "seed-study" / "profiles" / name, unit="in")
        fitted_c10, fitted_w = vbi.fit_iso8608(road)
        assert fitted_c10 == pytest.approx(c10, rel=0.35)
        assert fitted_w == pytest.approx(waviness, abs=0.25)
