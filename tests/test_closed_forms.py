"""Textbook solutions against independent references.

- the published moving-force numbers (reference sheet, after Frýba): one-mode peak 1.7685 w0
  at alpha = 0.617 (1.743 of P L^3 / 48 EI), converged peak 1.732 of P L^3 / 48 EI;
- the modal equations of a beam crossed by a force, integrated numerically here
  (``scipy.integrate.solve_ivp``, DOP853), in SI units;
- a small Euler-Bernoulli beam finite-element model written here (Hermite cubic elements,
  nodal loads: exact at the nodes), its support reactions giving moments and shears by
  statics;
- the textbook values P L / 4, P / 2, -3 P L / 32, the study's (38) and (64), Maxwell's
  reciprocity;
- a base-excited sprung mass integrated numerically to its steady state.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from vbi_lib import closed_forms as cf

# ---------------------------------------------------------------------------- moving force


def test_published_one_mode_peak() -> None:
    assert float(cf.moving_force_peak(0.617)) == pytest.approx(1.7685, abs=5e-5)
    assert float(cf.moving_force_daf(0.617, modes=1)) == pytest.approx(1.743, abs=5e-4)


def test_published_converged_peak_near_alpha_0_62() -> None:
    alphas = np.linspace(0.55, 0.70, 31)
    dafs = cf.moving_force_daf(alphas, modes=201)
    assert dafs.max() == pytest.approx(1.732, abs=5e-4)
    assert alphas[int(np.argmax(dafs))] == pytest.approx(0.62, abs=0.011)
    # the default number of modes is converged: 201 modes change it by < 1e-5
    np.testing.assert_allclose(cf.moving_force_daf(alphas[::10]), dafs[::10], rtol=1e-5)


def _integrated_deflection(
    x: np.ndarray, alpha: float, modes: int, span: float = 20.0
) -> tuple[np.ndarray, np.ndarray]:
    """Modal equations q_n'' + w_n^2 q_n = (2 P / mbar L) sin(n pi v t / L), from rest.

    Integrated with DOP853 at tight tolerances; deflection sum q_n sin(n pi x / L) [m] over
    the crossing, and the times.
    """
    ei, mbar, force = 3e9, 4000.0, 1e5
    omega = [(n * math.pi / span) ** 2 * math.sqrt(ei / mbar) for n in range(1, modes + 1)]
    f1 = omega[0] / (2 * math.pi)
    speed = alpha * 2 * f1 * span
    duration = span / speed

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        q, dq = y[:modes], y[modes:]
        n = np.arange(1, modes + 1)
        load = 2 * force / (mbar * span) * np.sin(n * math.pi * speed * t / span)
        return np.concatenate([dq, load - np.square(omega) * q])

    times = np.linspace(0.0, duration, 401)
    solution = solve_ivp(
        rhs, (0.0, duration), np.zeros(2 * modes), "DOP853", times, rtol=1e-11, atol=1e-16
    )
    shapes = np.sin(np.outer(np.arange(1, modes + 1), math.pi * np.asarray(x) / span))
    deflection = solution.y[:modes].T @ shapes
    expected = cf.moving_force_deflection(
        np.asarray(x)[None, :], times[:, None], force, speed, span, ei, mbar, modes
    )
    return deflection, expected


@pytest.mark.parametrize("alpha", [0.15, 0.617, 1.0, 1.7, 3.0])
def test_series_matches_the_integrated_modal_equations(alpha: float) -> None:
    """Including exact resonance of mode 1 (alpha = 1) and of mode 3's neighbourhood (3.0)."""
    sections = np.array([5.0, 10.0, 13.3])
    integrated, series = _integrated_deflection(sections, alpha, modes=4)
    scale = np.abs(integrated).max()
    np.testing.assert_allclose(series, integrated, atol=1e-8 * scale)


def test_resonance_is_continuous() -> None:
    tau = np.linspace(0.0, 1.0, 101)
    at = cf.moving_force_response(1.0, tau, 0.3, modes=3)
    for offset in (1e-4, 1e-7, 1e-10):
        for side in (-1, 1):
            near = cf.moving_force_response(1.0 + side * offset, tau, 0.3, modes=3)
            np.testing.assert_allclose(near, at, atol=20 * offset)
    # and the textbook resonance form for mode 1 alone
    theta = np.pi * tau
    np.testing.assert_allclose(
        cf.moving_force_response(1.0, tau), (np.sin(theta) - theta * np.cos(theta)) / 2
    )


def test_a_crawling_force_draws_the_static_deflection_line() -> None:
    """alpha -> 0: the series tends to the statics of the load at tau L (another closed form)."""
    span, ei, force = 10.0, 2e9, 5e4
    tau = np.linspace(0.0, 1.0, 41)
    w0 = 2 * force * span**3 / (math.pi**4 * ei)
    for section in (0.5, 0.2):
        crawl = w0 * cf.moving_force_response(1e-4, tau, section, modes=61)
        static = cf.point_load_statics(section * span, tau * span, span, ei, force=force)
        np.testing.assert_allclose(crawl, static.deflection, atol=3e-4 * w0)


def test_speed_parameter_and_peak_shapes() -> None:
    assert float(cf.speed_parameter(30.0, 15.0, 2.0)) == pytest.approx(0.5)
    alphas = np.array([[0.2, 0.5], [1.0, 2.0]])
    peaks = cf.moving_force_peak(alphas)
    assert peaks.shape == (2, 2)
    assert peaks[1, 0] == pytest.approx(math.pi / 2)  # resonance: increasing to tau = 1
    # a very fast force leaves before the beam responds: the peak falls towards 0
    assert float(cf.moving_force_peak(50.0)) < 0.05


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: cf.moving_force_response(0.0, 0.5), "alpha=0.0 must be greater than zero"),
        (lambda: cf.moving_force_response(0.5, 1.2), r"tau=1.2 must lie in \[0, 1\]"),
        (lambda: cf.moving_force_response(0.5, 0.5, section=-0.1), "section=-0.1"),
        (lambda: cf.moving_force_response(0.5, 0.5, modes=0), "modes=0"),
        (lambda: cf.moving_force_peak(float("nan")), "alpha=nan must be finite"),
        (lambda: cf.speed_parameter(-1.0, 10.0, 2.0), "speed=-1.0"),
    ],
)
def test_moving_force_rejects_bad_input(call, match: str) -> None:  # noqa: ANN001
    with pytest.raises(ValueError, match=match):
        call()


# ---------------------------------------------------------------------------- statics
def _beam_fe(
    supports: list[float], load: float, sections: np.ndarray, force: float, ei: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Euler-Bernoulli FE (Hermite cubics) with nodes at supports, the load and the sections.

    Returns deflection at the sections (exact at nodes for nodal loads) and the moment and
    shear there from statics with the FE support reactions (sagging +, V = dM/dx, the value
    just left of a load or support, at x = 0 just right).
    """
    nodes = np.unique(np.concatenate([supports, [load], sections, np.linspace(0, supports[-1], 9)]))
    dof = 2 * nodes.size
    stiffness = np.zeros((dof, dof))
    for i, h in enumerate(np.diff(nodes)):
        k = (ei / h**3) * np.array(
            [
                [12, 6 * h, -12, 6 * h],
                [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                [-12, -6 * h, 12, -6 * h],
                [6 * h, 2 * h * h, -6 * h, 4 * h * h],
            ]
        )
        stiffness[2 * i : 2 * i + 4, 2 * i : 2 * i + 4] += k
    loads = np.zeros(dof)
    loads[2 * int(np.searchsorted(nodes, load))] = force
    fixed = [2 * int(np.searchsorted(nodes, s)) for s in supports]
    free = np.setdiff1d(np.arange(dof), fixed)
    d = np.zeros(dof)
    d[free] = np.linalg.solve(stiffness[np.ix_(free, free)], loads[free])
    reactions = -(stiffness @ d - loads)[fixed]  # upward positive
    deflection = d[2 * np.searchsorted(nodes, sections)]
    moment = np.array(
        [
            sum(r * (x - s) for r, s in zip(reactions, supports, strict=True) if s < x)
            - (force * (x - load) if x > load else 0.0)
            for x in sections
        ]
    )
    shear = np.array(  # the value just left of x; at x = 0 just right
        [
            sum(r for r, s in zip(reactions, supports, strict=True) if s < x or s == x == 0)
            - (force if x > load or x == load == 0 else 0.0)
            for x in sections
        ]
    )
    return deflection, moment, shear


@pytest.mark.parametrize(
    ("n_spans", "load"),
    [(1, a) for a in (0.0, 1.7, 6.0, 10.0)]
    + [(2, a) for a in (0.0, 1.7, 6.0, 10.0, 12.5, 17.2, 20.0)],
)
def test_statics_match_a_beam_finite_element_model(n_spans: int, load: float) -> None:
    span, ei, force = 10.0, 4e8, 3e4
    supports = [j * span for j in range(n_spans + 1)]
    sections = np.array([0.0, 1.0, 3.3, 5.0, 8.9, 10.0, 11.0, 14.2, 15.0, 19.0, 20.0])
    sections = sections[sections <= n_spans * span]
    w, m, v = _beam_fe(supports, load, sections, force, ei)
    got = cf.point_load_statics(sections, load, span, ei, n_spans, force)
    np.testing.assert_allclose(got.deflection, w, rtol=1e-9, atol=1e-12 * force * span**3 / ei)
    np.testing.assert_allclose(got.moment, m, rtol=1e-9, atol=1e-9 * force * span)
    np.testing.assert_allclose(got.shear, v, rtol=1e-9, atol=1e-9 * force)


def test_the_textbook_values() -> None:
    span, ei, force = 12.0, 5e8, 2e4
    one = cf.point_load_statics(span / 2, span / 2, span, ei, force=force)
    assert float(one.deflection) == pytest.approx(force * span**3 / (48 * ei))  # (38)
    assert float(one.moment) == pytest.approx(force * span / 4)
    assert float(one.shear) == pytest.approx(force / 2)
    two = cf.point_load_statics(span / 2, span / 2, span, ei, n_spans=2, force=force)
    assert float(two.deflection) == pytest.approx(23 * force * span**3 / (1536 * ei))  # (64)
    support = cf.point_load_statics(span, span / 2, span, ei, n_spans=2, force=force)
    assert float(support.moment) == pytest.approx(-3 * force * span / 32)
    assert float(support.deflection) == pytest.approx(0.0, abs=1e-18)
    # the unloaded span lifts
    assert float(cf.point_load_statics(1.5 * span, span / 2, span, ei, 2, force).deflection) < 0


@pytest.mark.parametrize("n_spans", [1, 2])
def test_reciprocity_and_equilibrium(n_spans: int) -> None:
    span, ei = 8.0, 1e9
    length = n_spans * span
    x = np.linspace(0.0, length, 57)
    a = x[:, None]
    grid = cf.point_load_statics(x[None, :], a, span, ei, n_spans)
    # Maxwell: the deflection at x under a load at a equals that at a under a load at x
    np.testing.assert_allclose(grid.deflection, grid.deflection.T, atol=1e-15)
    # V = dM/dx away from the load and supports; the shear jumps by P at the load
    load = 0.37 * length
    fine = np.linspace(0.0, length, 4001)
    statics = cf.point_load_statics(fine, load, span, ei, n_spans)
    slope = np.gradient(statics.moment, fine)
    kinks = [load, *[j * span for j in range(n_spans + 1)]]
    smooth = np.min(np.abs(fine[:, None] - np.array(kinks)[None, :]), axis=1) > 0.01
    np.testing.assert_allclose(slope[smooth], statics.shear[smooth], atol=1e-9)
    jump = cf.point_load_statics([load, load + 1e-9], load, span, ei, n_spans).shear
    assert jump[0] - jump[1] == pytest.approx(1.0)


def test_statics_reject_bad_input() -> None:
    with pytest.raises(ValueError, match="x=25.0 must lie on the beam, 0 to 20 m"):
        cf.point_load_statics(25.0, 5.0, 10.0, 1e9, n_spans=2)
    with pytest.raises(ValueError, match="load_position=-1.0"):
        cf.point_load_statics(5.0, -1.0, 10.0, 1e9)
    with pytest.raises(ValueError, match="n_spans=3"):
        cf.point_load_statics(5.0, 5.0, 10.0, 1e9, n_spans=3)
    with pytest.raises(ValueError, match="EI"):
        cf.point_load_statics(5.0, 5.0, 10.0, 0.0)


# ---------------------------------------------------------------------------- base excitation
@pytest.mark.parametrize(("ratio", "zeta"), [(0.5, 0.05), (1.0, 0.1), (1.3, 0.2), (3.0, 0.1)])
def test_transmissibility_matches_an_integrated_steady_state(ratio: float, zeta: float) -> None:
    """m u'' = k (y - u) + c (y' - u'), y = Y sin(w t), integrated until the transient dies."""
    m, k, amplitude = 1.0, (2 * math.pi * 1.5) ** 2, 0.01
    wn = math.sqrt(k / m)
    c, w = 2 * zeta * wn * m, ratio * wn

    def rhs(t: float, s: np.ndarray) -> np.ndarray:
        y, dy = amplitude * math.sin(w * t), amplitude * w * math.cos(w * t)
        return np.array([s[1], (k * (y - s[0]) + c * (dy - s[1])) / m])

    settle = 12.0 / (zeta * wn)  # e^-12 of the transient left
    period = 2 * math.pi / w
    times = np.linspace(settle, settle + 3 * period, 3001)
    run = solve_ivp(rhs, (0.0, times[-1]), [0.0, 0.0], "DOP853", times, rtol=1e-10, atol=1e-14)
    u, du = run.y
    y = amplitude * np.sin(w * times)
    dy = amplitude * w * np.cos(w * times)
    force = k * (y - u) + c * (dy - du)  # dynamic contact force on the mass
    assert 0.5 * np.ptp(u) / amplitude == pytest.approx(
        float(cf.displacement_transmissibility(ratio, zeta)), rel=1e-4
    )
    assert 0.5 * np.ptp(force) / (k * amplitude) == pytest.approx(
        float(cf.contact_force_transmissibility(ratio, zeta)), rel=1e-4
    )


def test_transmissibility_limits() -> None:
    zetas = np.array([0.0, 0.05, 0.3, 0.9])
    np.testing.assert_allclose(cf.displacement_transmissibility(0.0, zetas), 1.0)
    np.testing.assert_allclose(cf.displacement_transmissibility(math.sqrt(2), zetas), 1.0)
    np.testing.assert_allclose(cf.contact_force_transmissibility(0.0, zetas), 0.0)
    r = np.array([0.3, 0.7, 1.5, 4.0])
    np.testing.assert_allclose(cf.displacement_transmissibility(r, 0.0), 1 / np.abs(1 - r**2))
    assert np.isinf(cf.displacement_transmissibility(1.0, 0.0))
    assert cf.displacement_transmissibility(np.ones((2, 3)), 0.1).shape == (2, 3)
    with pytest.raises(ValueError, match="frequency_ratio=-1.0"):
        cf.displacement_transmissibility(-1.0, 0.1)
    with pytest.raises(ValueError, match="damping_ratio=-0.1"):
        cf.contact_force_transmissibility(1.0, -0.1)
