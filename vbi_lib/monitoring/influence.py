r"""The quasi-static response a gauge should read, fitted to its record (influence lines).

A linear bridge's static response at a gauge to a vehicle is the sum of each axle's load times
the influence line :math:`I(a)` of that response at the gauge's section, read at the axle's
position :math:`a` (superposition).  With the first axle at :math:`p = v (t - t_0)` (speed
:math:`v`, arrival time :math:`t_0`) and axle :math:`k` a distance :math:`d_k` behind it with
a share :math:`w_k` of the load, a record :math:`y(t)` is modelled as

.. math::
    y(t) \approx s \sum_k w_k\, I\big(v (t - t_0) - d_k\big) + c_0 + c_1 t,

a scaled quasi-static response plus a straight baseline (gauge offset, drift).  The model is
linear in :math:`s, c_0, c_1`, which are solved exactly for every trial :math:`t_0` (and
:math:`v` when the speed is unknown); only those one or two are searched (variable
projection: Golub and Pereyra 1973, *SIAM J. Numer. Anal.* 10(2), 413-432).  The search scans
every sample shift with one correlation per trial speed, then refines the best one below a
sample.  A vibration about the quasi-static response is nearly orthogonal to its slow shape;
when the first frequency :math:`f_1` is known the refinement compares record and model after
the same zero-phase low-pass at :math:`f_1/2`, which removes what is left of the vibration's
pull while rounding any kink in both alike.

The same least squares with known influence lines and unknown axle loads is the bridge
weigh-in-motion algorithm of Moses (1979, *J. Transp. Eng.* 105(3), 233-249); OBrien,
Quilligan and Karoumi (2006, *Proc. ICE Bridge Eng.* 159(1), 31-34) turn it round to find an
influence line from a record of a known truck.  Here the shapes come from the exact statics
of :func:`vbi_lib.closed_forms.point_load_statics` (Euler-Bernoulli, one simple span or two
equal continuous spans; moment, hence strain and stress, or deflection), and the vehicle's
total load is the one unknown scale, so a kink in a strain record (an axle passing the gauge)
is reproduced exactly rather than rounded off as a low-pass filter does.  A crawl run of the
same vehicle can stand for the shape instead (:func:`crawl_shape`, scale fixed at 1).

Limits: one vehicle on the bridge, at constant speed, entering at the first support; the
supports act as the ideal pins of the formulas (real bearings, skew, composite action and
load sharing between girders change the influence line's shape; a crawl run captures them).
The scale absorbs the vehicle's mean force over the crossing, which the vehicle's own bounce
can move by a few per cent away from its weight, and the slow forced response, which at speed
parameter :math:`\alpha = v / (2 f_1 L)` is itself amplified by about :math:`1/(1-\alpha^2)`
(Frýba 1972): the DAF then reads low by about :math:`\alpha^2`.  The axles must be right: an
axle group assumed where there is one axle (or the reverse) changes the peak as much as the
kink is rounded, yet leaves little slow residual to show it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from scipy import fft as _fft
from scipy import optimize
from scipy import signal as _signal

from .. import _validation as check
from ..closed_forms import point_load_statics
from .filtering import without_straight_baseline

#: Response kinds a gauge can record, and the beam quantity whose influence line shapes it.
RESPONSES = {"deflection": "deflection", "moment": "moment", "strain": "moment", "stress": "moment"}
#: Responses whose influence line has a kink where an axle passes the gauge section.
KINKED_RESPONSES = ("moment", "strain", "stress")
#: Speeds [m/s] searched when a record's speed is not given (3.6 to 216 km/h).
SPEED_BOUNDS = (1.0, 60.0)
#: Ratio between neighbouring trial speeds of the coarse speed search.
_RATE_STEP = 1.02


@dataclass(frozen=True)
class Axles:
    """A vehicle's axles: spacings from the front and the share of the load on each.

    Parameters
    ----------
    spacings
        Distances between consecutive axles, front to back [m]; empty for a single axle
        (or a vehicle short against the span, treated as one load).
    loads
        Relative axle loads, front to back, one more than ``spacings`` (any scale: only the
        ratios matter); ``None`` for equal loads.

    Raises
    ------
    ValueError
        A spacing or load that is not a finite positive number, or a number of loads that
        does not match the spacings.

    Examples
    --------
    A five-axle semi-trailer, steer axle lighter:

    >>> truck = Axles(spacings=(3.6, 1.3, 6.0, 1.3), loads=(6, 10, 10, 9, 9))
    >>> truck.n_axles, round(truck.length, 6), truck.offsets.round(6).tolist()
    (5, 12.2, [0.0, 3.6, 4.9, 10.9, 12.2])
    """

    spacings: tuple[float, ...] = ()
    loads: tuple[float, ...] | None = None

    def __post_init__(self) -> None:
        spacings = tuple(float(d) for d in np.atleast_1d(np.asarray(self.spacings, dtype=float)))
        if any(not (math.isfinite(d) and d > 0) for d in spacings):
            raise ValueError(f"spacings={self.spacings!r} must be finite distances > 0 [m]")
        loads = (1.0,) * (len(spacings) + 1) if self.loads is None else self.loads
        loads = tuple(float(w) for w in np.atleast_1d(np.asarray(loads, dtype=float)))
        if len(loads) != len(spacings) + 1:
            raise ValueError(
                f"loads={self.loads!r} has {len(loads)} values for {len(spacings) + 1} axles "
                f"(spacings={spacings!r}): give one relative load per axle"
            )
        if any(not (math.isfinite(w) and w > 0) for w in loads):
            raise ValueError(f"loads={self.loads!r} must be finite relative loads > 0")
        object.__setattr__(self, "spacings", spacings)
        object.__setattr__(self, "loads", loads)

    @property
    def n_axles(self) -> int:
        """Number of axles."""
        return len(self.loads)

    @property
    def offsets(self) -> np.ndarray:
        """Distance of each axle behind the first [m], shape ``(n_axles,)``."""
        return np.concatenate([[0.0], np.cumsum(self.spacings)])

    @property
    def length(self) -> float:
        """Distance from the first to the last axle [m]."""
        return float(sum(self.spacings))

    @property
    def weights(self) -> np.ndarray:
        """Each axle's share of the total load [-], summing to 1."""
        loads = np.asarray(self.loads)
        return loads / loads.sum()


def check_response(response: object) -> str:
    """``response`` if it is one of :data:`RESPONSES`, else a ``ValueError`` saying which are."""
    if response not in RESPONSES:
        raise ValueError(
            f"response={response!r} must be one of {', '.join(map(repr, RESPONSES))}: the "
            "quantity the gauge records"
        )
    return str(response)


def influence_line(
    position: float | np.ndarray,
    section: float,
    span: float,
    *,
    n_spans: int = 1,
    response: str = "moment",
    axles: Axles | None = None,
    EI: float = 1.0,
) -> np.ndarray:
    """Static response at a gauge section to a vehicle of unit total load, against its position.

    The sum over the axles of each axle's share times the influence line of
    :func:`vbi_lib.closed_forms.point_load_statics`; axles off the bridge add nothing.

    Parameters
    ----------
    position
        Distance of the first axle from the support where the vehicle enters [m]; any value
        (before the bridge negative, past it beyond ``n_spans * span``).
    section
        The gauge's distance from that support [m], on the bridge.
    span
        Length of each span [m].
    n_spans
        1 (simple span) or 2 (two equal continuous spans).
    response
        ``"moment"``, ``"strain"`` or ``"stress"`` (all shaped like the bending moment, sagging
        positive) or ``"deflection"`` (downward positive).
    axles
        The vehicle's axles (:class:`Axles`); ``None`` for a single axle.
    EI
        Flexural rigidity [N m^2], used only for deflection.

    Returns
    -------
    numpy.ndarray
        Same shape as ``position``: moment per newton of total load [N m / N = m] or
        deflection per newton [m / N].

    Examples
    --------
    One axle at midspan of a 10 m simple span: the moment there is ``L / 4`` per newton;
    two equal axles 2 m apart centred on it give ``(4 + 4) / 2 / 2 = 2.0``:

    >>> float(influence_line(5.0, 5.0, 10.0))
    2.5
    >>> float(influence_line(6.0, 5.0, 10.0, axles=Axles(spacings=(2.0,))))
    2.0
    """
    kind = RESPONSES[check_response(response)]
    axles = Axles() if axles is None else axles
    if not isinstance(axles, Axles):
        raise TypeError(f"axles={axles!r} must be an Axles(spacings=..., loads=...) or None")
    span = check.positive("span", span)
    length = check.n_spans(n_spans) * span
    section = check.number("section", section)
    if not (0.0 <= section <= length):
        raise ValueError(
            f"section={section!r} must lie on the bridge, 0 to {length:g} m from the support "
            "where the vehicle enters"
        )
    position = np.asarray(position, dtype=float)
    out = np.zeros(position.shape)
    for offset, weight in zip(axles.offsets, axles.weights, strict=True):
        at = position - offset
        on = (at >= 0.0) & (at <= length)
        if on.any():
            statics = point_load_statics(section, at[on], span, EI, n_spans)
            out[on] += weight * getattr(statics, kind)
    return out


class Shape(NamedTuple):
    """A quasi-static shape against the vehicle's position along an axis (zero outside it).

    ``evaluate(p)`` gives the shape at positions ``p`` in ``[0, extent]`` (metres, or crawl
    seconds for a crawl run without a known crawl speed); ``label`` names it in sentences.
    """

    evaluate: Callable[[np.ndarray], np.ndarray]
    extent: float
    label: str


def axle_shape(
    section: float, span: float, n_spans: int, response: str, axles: Axles | None
) -> Shape:
    """The influence-line shape of :func:`influence_line` as a :class:`Shape` (axis in metres).

    The one-axle line is tabulated once at 2000 intervals a span, with the gauge section and
    the supports among the nodes, and interpolated linearly: exact at the kink, and within
    ``h^2 max|I''| / 8`` (below 1e-6 of the peak) between nodes.
    """
    axles = Axles() if axles is None else axles
    length = check.n_spans(n_spans) * check.positive("span", span)
    nodes = np.union1d(np.linspace(0.0, length, 2000 * n_spans + 1), [float(section)])
    table = influence_line(nodes, section, span, n_spans=n_spans, response=response)
    offsets, weights = axles.offsets, axles.weights

    def evaluate(position: np.ndarray) -> np.ndarray:
        out = np.zeros(np.shape(position))
        for offset, weight in zip(offsets, weights, strict=True):
            out += weight * np.interp(position - offset, nodes, table, left=0.0, right=0.0)
        return out

    where = "midspan" if math.isclose(section, span / 2) else f"x = {section:.4g} m"
    count = f"{axles.n_axles} axles" if axles.n_axles > 1 else "one axle"
    spans = "1 span" if n_spans == 1 else f"{n_spans} spans"
    label = f"influence line of {RESPONSES[response]} at {where} ({spans}, {count})"
    return Shape(evaluate, length + axles.length, label)


def crawl_shape(
    crawl: np.ndarray, sample_rate_hz: float, crawl_speed: float | None, baseline_fraction: float
) -> Shape:
    """A crawl record as a :class:`Shape`: baseline removed, trimmed to its event.

    A straight line through the medians of the crawl's first and last ``baseline_fraction``
    is taken off; the crawl is then trimmed to the samples between the first and last that
    reach 0.2 % of its peak (a long crawl lead adds nothing but length).  The axis is the
    position ``crawl_speed * t`` [m] when the crawl speed is known, else the crawl's own time
    [s]; between samples the crawl is interpolated linearly, and outside it is zero.
    """
    values = without_straight_baseline(crawl, baseline_fraction)
    peak = np.max(np.abs(values))
    if peak == 0:
        raise ValueError("crawl has no static response once its baseline is removed")
    strong = np.flatnonzero(np.abs(values) >= 2e-3 * peak)
    values = values[strong[0] : strong[-1] + 1]
    step = 1.0 / sample_rate_hz if crawl_speed is None else crawl_speed / sample_rate_hz
    axis = step * np.arange(values.size)

    def evaluate(position: np.ndarray) -> np.ndarray:
        return np.interp(position, axis, values, left=0.0, right=0.0)

    return Shape(evaluate, float(axis[-1]), "crawl run")


class ShapeFit(NamedTuple):
    """A shape fitted to a record by :func:`fit_shape` (arrays on the record's clock).

    ``model`` is the scaled shape (the quasi-static estimate, baseline excluded) and
    ``baseline`` the fitted straight line; ``rate`` is the axis units the vehicle covers per
    second (its speed, for a metre axis), ``rate_at_bound`` says a searched rate ended on the
    edge of its range, and ``slow_residual`` is the fit's residual low-passed at twice the
    loading frequency (what vibration cannot explain).
    """

    model: np.ndarray
    baseline: np.ndarray
    scale: float
    arrival_s: float
    rate: float
    rate_fitted: bool
    rate_at_bound: bool
    slow_residual: np.ndarray


def fit_shape(
    record: np.ndarray,
    sample_rate_hz: float,
    shape: Shape,
    rate: float | None = None,
    rate_bounds: tuple[float, float] = SPEED_BOUNDS,
    scale: float | None = None,
    loading_frequency_hz: float | None = None,
    smoothing_hz: float | None = None,
) -> ShapeFit:
    """Least-squares fit of ``scale * shape(rate (t - t0)) + c0 + c1 t`` to a record.

    ``scale`` free (``None``) or fixed (a crawl run of the same vehicle: 1); ``rate`` known or
    searched in ``rate_bounds`` (geometric steps of 2 %, then refined with Nelder-Mead);
    ``t0`` searched over every sample shift that keeps the shape inside the record, then
    refined below a sample (Brent's bounded method).  With ``smoothing_hz`` the refinement
    compares the record and the shape after the same zero-phase low-pass (4th-order
    Butterworth, forward and backward): a vibration above the cut-off then no longer pulls
    the fit, while a kink is rounded in both alike and so biases nothing.  The slow residual
    is low-passed at twice ``loading_frequency_hz`` (default: the shape's own passage
    frequency ``rate / extent``).

    Raises
    ------
    ValueError
        The record is shorter than the vehicle's passage at every rate allowed.
    """
    fs = float(sample_rate_hz)
    norm = float(np.max(np.abs(record)))  # fitting works on O(1) numbers
    y = record / norm
    fixed = None if scale is None else scale / norm
    t = np.arange(y.size) / fs
    smooth = _Smoother(fs, smoothing_hz, y.size)
    if rate is not None:
        rates = np.array([rate])
    else:
        low = max(rate_bounds[0], shape.extent / t[-1])
        if low >= rate_bounds[1]:
            rates = np.array([])
        else:
            steps = int(math.ceil(math.log(rate_bounds[1] / low) / math.log(_RATE_STEP)))
            rates = low * _RATE_STEP ** np.arange(steps + 1)
            rates = rates[rates <= rate_bounds[1] * (1 + 1e-12)]
    best = (math.inf, 0.0, 0.0)
    for trial in rates:
        found = _scan_shifts(y, fs, shape, trial, fixed)
        if found is not None and found[0] < best[0]:
            best = (found[0], found[1], trial)
    if not math.isfinite(best[0]):
        duration = shape.extent / (rate if rate is not None else rate_bounds[1])
        raise ValueError(
            f"the record lasts {t[-1]:.3g} s, shorter than the vehicle's passage over the "
            f"{shape.label} ({duration:.3g} s at the highest speed allowed): record the whole "
            "passage, from before the vehicle arrives to after it has left"
        )
    _, arrival, found_rate = best
    target = smooth.record(y)

    def cost(t0: float, trial: float) -> float:
        return _solve(target, t, shape, t0, trial, fixed, smooth)[2]

    if rate is not None:
        result = optimize.minimize_scalar(
            lambda t0: cost(t0, found_rate),
            bounds=(arrival - 3.0 / fs, arrival + 3.0 / fs),
            method="bounded",
            options={"xatol": 1e-4 / fs},
        )
        arrival = float(result.x)
    else:
        start = np.array([arrival, math.log(found_rate)])
        simplex = np.array([start, start + [1.0 / fs, 0.0], start + [0.0, 0.01]])
        result = optimize.minimize(
            lambda z: cost(z[0], math.exp(z[1])),
            start,
            method="Nelder-Mead",
            options={"initial_simplex": simplex, "xatol": 1e-6, "fatol": 1e-12, "maxiter": 600},
        )
        arrival, found_rate = float(result.x[0]), math.exp(float(result.x[1]))
    shape_values, coefficients, _ = _solve(target, t, shape, arrival, found_rate, fixed, smooth)
    gain = coefficients[0] if fixed is None else fixed
    model = norm * gain * shape_values
    baseline = norm * (coefficients[-2] + coefficients[-1] * t)
    loading = loading_frequency_hz or found_rate / shape.extent
    slow = _Smoother(fs, 2.0 * loading, y.size).record(record - model - baseline)
    at_bound = rate is None and (
        found_rate <= rates[0] * _RATE_STEP or found_rate >= rates[-1] / _RATE_STEP
    )
    return ShapeFit(
        model=model,
        baseline=baseline,
        scale=float(norm * gain),
        arrival_s=arrival,
        rate=found_rate,
        rate_fitted=rate is None,
        rate_at_bound=bool(at_bound),
        slow_residual=slow,
    )


class _Smoother:
    """The same zero-phase low-pass for a record and for the models compared with it.

    The record goes through ``scipy.signal.sosfiltfilt`` (4th-order Butterworth forward and
    backward, odd extension at the ends); a model, zero before the vehicle arrives, is
    multiplied by that filter's ``|H(f)|^2`` on a zero-padded FFT, which is the same linear
    operation without the per-call set-up (padded by ten periods of the cut-off, where the
    impulse response has died out).  No cut-off, or one near Nyquist: the identity.
    """

    def __init__(self, fs: float, cutoff_hz: float | None, n: int) -> None:
        self.active = cutoff_hz is not None and cutoff_hz < 0.45 * fs and n > 30
        if not self.active:
            return
        self.sos = _signal.butter(4, cutoff_hz, btype="low", fs=fs, output="sos")
        self.n = n
        self.size = _fft.next_fast_len(n + int(math.ceil(10.0 * fs / cutoff_hz)), real=True)
        frequencies = np.fft.rfftfreq(self.size, 1.0 / fs)
        _, response = _signal.sosfreqz(self.sos, worN=frequencies, fs=fs)
        self.gain = np.abs(response) ** 2

    def record(self, values: np.ndarray) -> np.ndarray:
        return _signal.sosfiltfilt(self.sos, values) if self.active else values

    def model(self, values: np.ndarray) -> np.ndarray:
        if not self.active:
            return values
        spectrum = np.fft.rfft(values, self.size) * self.gain
        return np.fft.irfft(spectrum, self.size)[: self.n]


def _solve(
    target: np.ndarray,
    t: np.ndarray,
    shape: Shape,
    arrival: float,
    rate: float,
    fixed: float | None,
    smooth: _Smoother,
) -> tuple[np.ndarray, np.ndarray, float]:
    """Shape values, linear coefficients (scale if free, c0, c1) and the squared residual.

    ``target`` is the (smoothed) record; the shape is smoothed by ``smooth`` before it is
    compared with it (a straight baseline passes the smoothing unchanged).
    """
    values = shape.evaluate(rate * (t - arrival))
    smoothed = smooth.model(values)
    columns = [np.ones_like(t), t]
    if fixed is None:
        columns.insert(0, smoothed)
    else:
        target = target - fixed * smoothed
    design = np.column_stack(columns)
    coefficients, *_ = np.linalg.lstsq(design, target, rcond=None)
    residual = target - design @ coefficients
    return values, coefficients, float(residual @ residual)


def _scan_shifts(
    y: np.ndarray, fs: float, shape: Shape, rate: float, fixed: float | None
) -> tuple[float, float] | None:
    """Least-squares cost at every whole-sample arrival; (lowest cost, its arrival) or None.

    The straight baseline is projected out first: with ``e1, e2`` an orthonormal basis of
    the constant and the (centred) time, and ``P`` the projection on them, the cost of a
    free scale is ``|y'|^2 - (g_k . y')^2 / (|g_k|^2 - |P g_k|^2)`` and that of a fixed one
    ``|y'|^2 - 2 s g_k . y' + s^2 (|g_k|^2 - |P g_k|^2)``, ``y' = y - P y``: one correlation
    and a few closed-form sums for every shift ``k``.
    """
    n = y.size
    m = int(math.ceil(shape.extent / rate * fs)) + 2
    if m > n:
        return None
    j = np.arange(m)
    g = shape.evaluate(rate * j / fs)
    shifts = np.arange(n - m + 1)
    centred = np.arange(n) - (n - 1) / 2.0  # time in samples, orthogonal to the constant
    e1 = np.full(n, 1.0 / math.sqrt(n))
    e2 = centred / math.sqrt(centred @ centred)
    y_off = y - e1 * (e1 @ y) - e2 * (e2 @ y)
    gy = _signal.correlate(y_off, g, mode="valid")  # sum_j g[j] y'[k + j] for every shift k
    g1 = g.sum()
    p1 = g1 / math.sqrt(n)  # e1 . g_k, the same for every shift
    p2 = (g1 * (shifts - (n - 1) / 2.0) + j @ g) / math.sqrt(centred @ centred)  # e2 . g_k
    g_off = g @ g - p1**2 - p2**2
    if fixed is None:
        with np.errstate(divide="ignore", invalid="ignore"):
            gain = np.where(g_off > 1e-12 * (g @ g), gy**2 / g_off, 0.0)
        cost = y_off @ y_off - gain
    else:
        cost = y_off @ y_off - 2.0 * fixed * gy + fixed**2 * g_off
    if not np.isfinite(cost).any():
        return None
    k = int(np.nanargmin(cost))
    return float(cost[k]), k / fs


__all__ = [
    "KINKED_RESPONSES",
    "RESPONSES",
    "SPEED_BOUNDS",
    "Axles",
    "Shape",
    "ShapeFit",
    "axle_shape",
    "check_response",
    "crawl_shape",
    "fit_shape",
    "influence_line",
]
