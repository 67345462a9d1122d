"""Preview of issue 26: the study's 239 scenarios on the decks, by the tests' reference crossing.

Not the library's crossing (that plugs into the lead's modal kernel later): the independent
solve_ivp reference of ``deck_crossing.py`` on each row's deck (``assessment_inputs(...,
beam="deck")``), its N modes below 4 f1 with the mode-acceleration correction, the study's
sprung mass bonded to the road (the study's FE runs allowed no loss of contact).  The 140 ft
rows keep the exact beam (5 modes).  Run from the repository:

    .venv/bin/python tests/decks/preview_mape.py [--skew left|right] [--track 0] [--beam]

``--beam`` runs every row on the exact beam instead (the same integrator: what the deck
changes).  Prints the MAPE against the FE DAF by bridge type, span and path, and writes the
per-row DAFs to a CSV in /tmp.  ``--span`` runs one bridge length only (the others do not
change with ``--skew``), ``--barriers`` draws the decks' barriers another way.

Measured at commit ba5940e (MAPE one span / two spans; 140 ft rows on the exact beam):

=========================================  ===============  ==============
variant                                    MAPE             mean bias
=========================================  ===============  ==============
deck, square 40 ft (the default)           9.09 % / 11.50 %  -2.3 / -3.8 %
deck, 40 ft skewed 16 deg left-forward     9.04 % / 11.55 %  -2.3 / -3.8 %
deck, 40 ft skewed 16 deg right-forward    9.29 % / 11.46 %  -2.4 / -3.9 %
deck, one wheel on the path (track 0)      9.27 % / 12.08 %  -4.2 / -6.0 %
deck, 40 ft barriers their own section     8.32 % / 10.76 %  -2.7 / -4.0 %
deck, 100 ft barriers composite            10.09 % / 10.09 % -4.1 / -1.8 %
exact beam, 5 modes, this integrator       9.98 % / 11.95 %  +0.8 / +2.2 %
=========================================  ===============  ==============
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import deck_crossing as dc  # noqa: E402

import vbi_lib as vbi  # noqa: E402
from vbi_lib import study_data as sd  # noqa: E402
from vbi_lib import units as u  # noqa: E402
from vbi_lib.decks import WheelPath  # noqa: E402
from vbi_lib.decks.study import assessment_site  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--skew", default=None, choices=["left", "right"])
    parser.add_argument("--track", type=float, default=6.0, help="ft between the wheels")
    parser.add_argument("--beam", action="store_true")
    parser.add_argument("--rows", type=int, default=None)
    parser.add_argument("--span", type=float, default=None, help="only the rows of this span")
    parser.add_argument("--barriers", default=None, choices=["composite", "own"])
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    data = HERE.parents[2] / "shared" / "data" / "seed-study"
    table, profiles = sd.read_assessment_set(data)
    if args.span is not None:
        table = table[table.span_ft == args.span]
    if args.rows:
        table = table.iloc[: args.rows]
    warnings.simplefilter("ignore", vbi.VbiWarning)
    sites, trucks, roads = sd.assessment_inputs(table, profiles, beam="deck", skew_hand=args.skew)
    if args.barriers is not None:  # the barriers' action, which the seed leaves open
        sites = [
            assessment_site(row, args.skew, barriers=args.barriers) for row in table.itertuples()
        ]
    exact, _, _ = sd.assessment_inputs(table, profiles, beam="exact")
    cache: dict[object, dc.BridgeData] = {}
    predicted = []
    start = time.time()
    for i, (site, beam, truck, road) in enumerate(zip(sites, exact, trucks, roads, strict=True)):
        if site.deck is None or args.beam:
            key = ("beam", beam)
            if key not in cache:
                cache[key] = dc.beam_data(beam, 5, list(beam.midspans))
        else:
            path = site.path
            if args.track != 6.0:
                path = WheelPath(path.offset, args.track * u.ft, path.direction)
            key = ("deck", site.deck, path, site.girder)
            if key not in cache:
                modes = site.deck.modes()
                tables = modes.path_tables(path, list(site.responses))
                cache[key] = dc.BridgeData.from_tables(tables)
        out = dc.crossing(cache[key], (truck.mass, truck.stiffness, truck.damping),
                          (road.x, road.elevation), sd.ASSESSMENT_SPEED,
                          sd.ASSESSMENT_BRIDGE_START, rtol=1e-7)  # fmt: skip
        predicted.append(float(np.max(out["daf"])))
        if i % 20 == 0:
            print(f"{i:4d} {time.time() - start:7.1f} s  DAF {predicted[-1]:.3f} FE "
                  f"{table.fe_daf.iloc[i]:.3f}", flush=True)  # fmt: skip
    table = table.assign(predicted=predicted)
    table["error"] = (table.predicted - table.fe_daf).abs() / table.fe_daf
    label = "beam" if args.beam else f"deck skew={args.skew} track={args.track:g}ft"
    if args.barriers:
        label += f" barriers={args.barriers}"
    print(f"\n{label}: MAPE against the FE DAF")
    print(table.groupby("n_spans").error.mean().round(4).to_string())
    print(table.groupby(["n_spans", "span_ft"]).error.mean().round(4).to_string())
    print(table.groupby(["n_spans", "span_ft", "path"]).error.mean().round(4).to_string())
    bias = (table.predicted / table.fe_daf - 1).groupby(table.n_spans).mean()
    print("bias\n" + bias.round(4).to_string())
    out = args.out or f"/tmp/h26-preview-{label.replace(' ', '_').replace('=', '-')}.csv"
    table.to_csv(out, index=False)
    print(f"rows written to {out}; {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()
