"""Property tests (Hypothesis): realistic inputs give finite results; any other is refused.

Two kinds of property:

* over wide, realistic ranges of bridges (3 to 150 m, one or two spans, first frequencies
  around the empirical ``82 / L^0.9`` Hz), vehicles (the study's sprung mass, quarter cars,
  the HS20 truck), speeds (2 to 40 m/s) and roads (flat, ISO 8608 classes A to D), every
  crossing of both models gives finite histories, contact checks in range and a DAF that
  is finite and positive, or NaN for a span the vehicle never pushed down, with a note; the
  run time is bounded by Hypothesis' deadline and by the number of nodes, which the inputs
  bound;
* any float at all (NaN, infinities, zeros, huge and tiny numbers) given to a bridge, a
  vehicle or a road either builds one whose derived quantities are finite, or is refused
  with a ``ValueError`` naming the parameter; text is refused with a ``TypeError``.

Examples are derandomised (the same on every run) and no example database is written.
"""

from __future__ import annotations

import math
import warnings
from datetime import timedelta

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import vbi_lib as vbi
from vbi_lib.units import ft
from vbi_lib.vehicles import hs20

SETTINGS = {
    "derandomize": True,
    "database": None,
    "suppress_health_check": [HealthCheck.too_slow],
}
CROSSINGS = settings(max_examples=30, deadline=timedelta(seconds=20), **SETTINGS)
EDGES = settings(max_examples=150, deadline=timedelta(seconds=5), **SETTINGS)

ANY_FLOAT = st.floats(allow_nan=True, allow_infinity=True) | st.sampled_from(
    [0.0, -0.0, 1e-300, 1e300, -1.0, float("nan"), float("inf")]
)


# ---------------------------------------------------------------------------- realistic inputs
@st.composite
def bridges(draw: st.DrawFn) -> vbi.Bridge:
    span = draw(st.floats(3.0, 150.0))
    typical = 82.0 / span**0.9  # an empirical first frequency of road bridges [Hz]
    frequency = draw(st.floats(max(0.5, 0.6 * typical), min(50.0, 1.6 * typical)))
    return vbi.Bridge.from_frequency(
        span,
        draw(st.sampled_from([1, 2])),
        draw(st.floats(500.0, 50_000.0)),
        frequency,
        draw(st.floats(0.0, 0.05)),
    )


@st.composite
def vehicles(draw: st.DrawFn) -> object:
    kind = draw(st.sampled_from(["sprung mass", "quarter car", "hs20"]))
    if kind == "sprung mass":
        return vbi.Vehicle.from_frequency(
            draw(st.floats(1e3, 4e4)), draw(st.floats(1.0, 5.0)), draw(st.floats(0.02, 0.4))
        )
    if kind == "quarter car":
        sprung = draw(st.floats(1e3, 2e4))
        return vbi.QuarterCar.from_frequencies(
            sprung,
            sprung * draw(st.floats(0.1, 0.2)),  # the wheel's share of a quarter car
            draw(st.floats(1.0, 2.0)),  # body bounce
            draw(st.floats(9.0, 15.0)),  # axle hop
            draw(st.floats(0.05, 0.4)),
        )
    return hs20(draw(st.floats(14 * ft, 30 * ft)), tyres=draw(st.booleans()))


@st.composite
def crossings(draw: st.DrawFn) -> tuple:
    bridge, vehicle = draw(bridges()), draw(vehicles())
    approach = draw(st.floats(10.0, 60.0))
    wheelbase = vbi.vehicles.as_system(vehicle).wheelbase
    length = wheelbase + approach + bridge.length + wheelbase + 1.0
    roughness = draw(st.sampled_from([None, "A", "B", "C", "D"]))
    if roughness is None:
        road = vbi.Profile.flat(length, 0.05)
    else:
        seed = draw(st.integers(0, 2**31 - 1))
        road = vbi.Profile.iso8608(length, 0.05, iso_class=roughness, seed=seed)
    modes = draw(st.sampled_from([None, 1, 3, 6]))
    options = {} if modes is None else {"model": "modal", "modes": modes}
    speed = draw(st.floats(2.0, 40.0))
    return bridge, vehicle, road, speed, wheelbase + approach, options


@pytest.fixture(scope="module", autouse=True)
def compiled() -> None:
    """Load (or compile) every kernel once, so that the deadline times the crossings."""
    bridge = vbi.Bridge(20.0, 1, 5e9, 5000.0)
    road = vbi.Profile.flat(80.0, 0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)
        for vehicle in (vbi.Vehicle(1e4, 4e6, 2e4), hs20(tyres=True)):
            for options in ({}, {"model": "modal", "modes": 2}):
                vbi.simulate(bridge, vehicle, road, 20.0, 30.0, **options)


@CROSSINGS
@given(crossings())
def test_realistic_crossings_give_finite_results(inputs: tuple) -> None:
    bridge, vehicle, road, speed, start, options = inputs
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)  # contact loss, flights: said below
        run = vbi.simulate(bridge, vehicle, road, speed, start, **options)
    assert run.time.size < 2_000_000  # the work is bounded by the inputs
    for name in ("midspan_displacement", "dof_displacement", "axle_contact_force", "time"):
        assert np.isfinite(getattr(run, name)).all(), name
    assert math.isfinite(run.min_contact_force_ratio)
    assert 0.0 <= run.tension_fraction <= 1.0 and 0.0 <= run.flight_fraction <= 1.0
    assert run.daf.shape == (bridge.n_spans,)
    for j, daf in enumerate(run.daf):
        if np.isnan(daf):
            assert any(f"span {j + 1} was never pushed down" in n for n in run.notes)
        else:
            assert 0.0 < daf < 20.0, (j, daf, run.notes)
    if run.min_contact_force_ratio < 0:
        assert any("contact lost" in n for n in run.notes)


#: How close each model's DAF at its default step is to the converged DAF (the same crossing
#: at an eighth of the step): RK4 is of fourth order at omega_max dt = 0.1; Newmark's rule of
#: second order, with the default step set by the highest mode, whose phase error,
#: (omega dt)^2 / 12 a period, builds up over the run.  Measured on 40 random crossings of
#: these ranges (no contact lost): at most 4.7e-6 and 2.5e-3.
STEP = {"one-coordinate": 2e-5, "modal": 1e-2}
#: How far the DAF may move when the road is resampled twice as finely.  Without a tyre
#: footprint the road is the same (linear between samples): the change is the step's
#: (measured: at most 4.0e-6 and 6.9e-4).  A tyre sees the road averaged over its footprint,
#: evaluated at the samples: resampling refines that average too (measured: at most 5.5e-5
#: and 1.6e-3; Hypothesis found 6.9e-4, then 3.4e-3, for the one-coordinate model under a
#: quarter car heavier than its 3 m span on a class C road at 8 m/s: a discretisation of the
#: footprint average, which settles at second order as the road is sampled more finely, the
#: DAF moving 0.34, 0.44, 0.46, 0.46 % over successive halvings).
RESAMPLED = {"one-coordinate": 5e-3, "modal": 1e-2}


@pytest.mark.parametrize("model", list(STEP))
@settings(max_examples=15, deadline=timedelta(seconds=60), **SETTINGS)
@given(data=st.data())
def test_resampling_the_road_converges(model: str, data: st.DataObject) -> None:
    """The DAF at the default step is within ``STEP[model]`` of the converged DAF (reference:
    the crossing at an eighth of the step), and resampling the road twice as finely moves
    it by less than ``STEP[model]`` (no footprint: the same road) or ``RESAMPLED[model]`` (a
    tyre's footprint average is refined too).  Crossings that lose contact (no prediction)
    are left out.  About 30 s per model on a loaded 2-core machine."""
    bridge, vehicle = data.draw(bridges()), data.draw(vehicles())
    system = vbi.vehicles.as_system(vehicle)
    start = system.wheelbase + data.draw(st.floats(10.0, 30.0))
    road = vbi.Profile.iso8608(start + bridge.length + system.wheelbase + 1.0, 0.05,
                               iso_class=data.draw(st.sampled_from("ABC")),
                               seed=data.draw(st.integers(0, 2**31 - 1)))  # fmt: skip
    speed = data.draw(st.floats(8.0, 35.0))
    modes = data.draw(st.sampled_from([1, 3, 6]))
    options = {"model": "modal", "modes": modes} if model == "modal" else {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)
        given_road = vbi.simulate(bridge, vehicle, road, speed, start, **options)
        if given_road.lost_contact:
            return
        finer = vbi.simulate(bridge, vehicle, road.resampled(0.025), speed, start, **options)
        converged = vbi.simulate(bridge, vehicle, road, speed, start, dt=given_road.dt / 8,
                                 **options)  # fmt: skip
    step = np.nanmax(np.abs(given_road.daf / converged.daf - 1.0), initial=0.0)
    assert step < STEP[model], (step, given_road.notes)
    moved = np.nanmax(np.abs(finer.daf / given_road.daf - 1.0), initial=0.0)
    allowed = RESAMPLED[model] if system.footprint.max() > 0 else STEP[model]
    assert moved < allowed, (moved, finer.notes)


@settings(max_examples=20, deadline=timedelta(seconds=10), **SETTINGS)
@given(
    st.floats(20.0, 2000.0),
    st.sampled_from([0.025, 0.05, 0.1, 0.15]),
    st.sampled_from("ABCDE"),
    st.floats(1.5, 4.0),
    st.integers(0, 2**31 - 1),
)
def test_iri_of_realistic_roads_is_finite_and_positive(
    length: float, spacing: float, iso_class: str, waviness: float, seed: int
) -> None:
    road = vbi.Profile.iso8608(length, spacing, c10=vbi.profiles.ISO_CLASS_MEANS[iso_class],
                               waviness=waviness, seed=seed)  # fmt: skip
    result = vbi.iri(road, segment_length=max(10.0, 2 * spacing))
    assert math.isfinite(result.iri) and result.iri > 0
    assert np.isfinite(result.segment_iri).all() and (result.segment_iri > 0).all()
    assert result.stop[-1] == pytest.approx(road.end)


# ---------------------------------------------------------------------------- any number
def _refused_by_name(error: Exception, *names: str) -> bool:
    return isinstance(error, ValueError) and any(f"{n}=" in str(error) for n in names)


@EDGES
@given(ANY_FLOAT, ANY_FLOAT, ANY_FLOAT, ANY_FLOAT)
def test_any_numbers_build_a_sound_bridge_or_are_refused_by_name(
    span: float, EI: float, mass: float, damping: float
) -> None:
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
            bridge = vbi.Bridge(span, 1, EI, mass, damping)
    except ValueError as exc:
        names = ("span", "EI", "mass_per_length", "damping_ratio", "first_frequency_hz")
        assert _refused_by_name(exc, *names), exc
        return
    values = [bridge.first_frequency_hz, bridge.generalized_mass, bridge.generalized_stiffness]
    assert all(math.isfinite(v) and v > 0 for v in values)


@EDGES
@given(ANY_FLOAT, ANY_FLOAT, ANY_FLOAT)
def test_any_numbers_build_a_sound_vehicle_or_are_refused_by_name(
    mass: float, frequency: float, damping: float
) -> None:
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
            vehicle = vbi.Vehicle.from_frequency(mass, frequency, damping)
            system = vehicle.system
    except ValueError as exc:
        assert _refused_by_name(exc, "mass", "frequency_hz", "damping_ratio"), exc
        return
    assert np.isfinite(system.frequencies_hz).all() and math.isfinite(vehicle.weight)


@EDGES
@given(ANY_FLOAT, ANY_FLOAT, ANY_FLOAT, ANY_FLOAT)
def test_any_numbers_build_a_sound_road_or_are_refused_by_name(
    length: float, spacing: float, c10: float, waviness: float
) -> None:
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
            # a short road: the sample count is checked before anything is allocated
            road = vbi.Profile.iso8608(min(length, 500.0) if length == length else length,
                                       spacing, c10=c10, waviness=waviness, seed=1)  # fmt: skip
    except ValueError as exc:
        assert _refused_by_name(exc, "length", "spacing", "c10", "waviness", "band"), exc
        return
    assert np.isfinite(road.elevation).all()
    assert np.std(road.elevation) < 3.0  # its rms, at most 1 m, checked before it was drawn


ROAD = vbi.Profile.flat(130.0, 0.05)


@EDGES
@given(st.text(max_size=5) | st.none() | st.booleans() | st.lists(st.floats(), max_size=2))
def test_anything_but_a_number_is_refused_with_a_type_error(value: object) -> None:
    bridge, vehicle, road = vbi.Bridge(30.0, 1, 2e10, 8000.0), vbi.Vehicle(1e4, 4e6), ROAD
    for call in (
        lambda: vbi.Bridge(value, 1, 2e10, 8000.0),
        lambda: vbi.Vehicle(value, 4e6, 0.0),
        lambda: vbi.Profile.flat(value, 0.05),
        lambda: vbi.simulate(bridge, vehicle, road, value, 50.0),
    ):
        with pytest.raises(TypeError, match="must be a number"):
            call()
