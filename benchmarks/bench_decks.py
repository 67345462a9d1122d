"""Speed and convergence of the decks (issue 26): modes, fitting, path tables.

Run: ``.venv/bin/python benchmarks/bench_decks.py``.  Prints the median of repeated runs
after a warm-up and the machine's load; the modes are memoised per deck, so their timing
clears the caches on every call.  Then the convergence of the 40 ft deck (16 degrees,
left-forward) as its Ritz basis grows: first frequencies and the study's twin-load
deflection on path 2, against the default (12 beam modes per span along, 30 polynomials
across).  Not in ``run_all.py`` (its rows feed the README, which this issue leaves alone).
"""

from __future__ import annotations

from dataclasses import replace

from _timing import load, median_time, report

from vbi_lib import units as u
from vbi_lib.decks import WheelPath, axle_deflection
from vbi_lib.decks import modes as deck_modes_module
from vbi_lib.decks.basis import ritz_basis
from vbi_lib.decks.study import study_deck, study_site


def clear() -> None:
    deck_modes_module._solve.cache_clear()
    ritz_basis.cache_clear()


def modes_of(span_ft: int, n_spans: int) -> float:
    deck = study_deck(span_ft, n_spans)

    def compute() -> None:
        clear()
        deck.modes(10)

    return median_time(compute, 3)


if __name__ == "__main__":
    print(load())
    times = {(s, n): modes_of(s, n) for s in (40, 100) for n in (1, 2)}
    report(
        "deck modes (Rayleigh-Ritz, default basis), 40 ft 1 / 2 spans, 100 ft 1 / 2 spans",
        "",
        " / ".join(f"{t * 1e3:.0f}" for t in times.values()) + " ms",
    )
    deck = study_deck(40, 1, "left")
    path = WheelPath.from_girder(deck, 16 * u.ft)
    responses = [(deck.midspans[0], deck.girder_y(3))]
    modes = deck.modes()
    tables = median_time(lambda: modes.path_tables(path, responses), 5)
    report(
        f"path tables of the skewed 40 ft deck ({modes.count} modes, one response point)",
        "",
        f"{tables * 1e3:.0f} ms",
    )
    fit = median_time(
        lambda: study_site(40, 2, 2, 661235 * u.lbf / u.inch, 9.98, skew_hand="right"), 3
    )
    report("one row's deck fitted to K_mid and f1 (drawn deck's modes cached)", "",
           f"{fit * 1e3:.0f} ms")  # fmt: skip

    print("\nconvergence, 40 ft deck skewed 16 degrees left-forward, path 2 (girder 3)")
    print("functions (along per span, across)   f1..f6 [Hz]   twin-load deflection [m/N]")
    for resolution in [(6, 12), (8, 18), (12, 24), (12, 30), (16, 36), (24, 44)]:
        trial = replace(deck, resolution=resolution)
        f = trial.frequencies_hz(6)
        d = axle_deflection(trial, path, trial.midspans[0], responses)[0]
        shown = " ".join(f"{v:7.3f}" for v in f)
        print(f"  {resolution!s:12s} {shown}   {d:.6e}")
