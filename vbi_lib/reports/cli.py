"""The command line: ``vbi-report PARAMS.yaml [MORE.yaml ...] --output-dir DIR``.

Exit status 0 when every report is written, 2 for input that cannot be used (a parameter, a
parameter file, the output folder; nothing has run), 1 when a report fails while running,
130 on SIGINT, 143 on SIGTERM and 129 on SIGHUP (the terminal or ssh session closed).  Every
failure prints one line and no traceback, and leaves nothing behind (see
:mod:`vbi_lib.reports.running`).  A report whose inputs look like a slip (a unit) is written,
and each such warning printed on stderr as ``vbi-report: warning: NAME: ...``.
"""

from __future__ import annotations

import argparse
import contextlib
import sys

from .parameters import ParameterError
from .running import OutputError, ReportFailed, Terminated, signals_raise, write_reports

__all__ = ["main"]

EPILOG = """\
example parameter files (every dimensional value is one number and one unit):

  title: I-76 span 3
  bridge: {span: 140 ft, k_mid: 222278 lbf/in, first_frequency: 2.08 Hz}
  vehicle: {mass: 200 lbf*s**2/in, frequency: 2.5 Hz, damping_ratio: 0.10}
  profile: {file: deck.csv, length_unit: inch}
  speeds: [30 mph, 70 mph]

  title: Three spans under the HS20
  bridge: {spans: [90 ft, 120 ft, 90 ft], EI: 5.3e11 kip*in**2, mass_per_length: 11 kip/ft}
  vehicle: {type: hs20, rear_axle_spacing: [14 ft, 30 ft]}
  profile: {iso_class: B, seed: 7}
  speeds: [35 mph, 55 mph, 70 mph]

Each PARAMS.yaml gives DIR/PARAMS.html, DIR/PARAMS.pdf and the results as data,
DIR/PARAMS.json and DIR/PARAMS.csv; several files share one kernel.  Vehicle types:
sprung-mass (default), quarter-car, hs20, hl93-truck, hl93-tandem, axles.  More examples and
every key: the repository's examples/ folder.
"""


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="vbi-report",
        description="Reports of the dynamic amplification of a bridge under a truck.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("parameters", nargs="+", metavar="PARAMS.yaml", help="parameter files")
    parser.add_argument("-o", "--output-dir", required=True, metavar="DIR", help="output folder")
    parser.add_argument("--no-pdf", action="store_true", help="write the HTML only")
    parser.add_argument(
        "--timeout", type=float, default=600.0, metavar="S", help="seconds a cell may run"
    )
    return parser


def _fail(message: str, status: int) -> int:
    with contextlib.suppress(OSError):  # after SIGHUP the terminal may be gone
        print(f"vbi-report: {message}", file=sys.stderr)
    return status


def main(argv: list[str] | None = None) -> int:
    """Run the command line with ``argv`` (``sys.argv[1:]`` by default); return the status."""
    args = _parser().parse_args(argv)
    pairs = [a for a in args.parameters if "=" in a]
    if pairs:
        return _fail(
            f"error: {pairs[0]!r}: name=value parameters are replaced by a parameter file "
            "(YAML); see vbi-report --help",
            2,
        )
    if args.timeout <= 0:
        return _fail(f"error: --timeout={args.timeout:g} must be a number of seconds > 0", 2)
    with signals_raise():
        try:
            files = write_reports(
                args.parameters, args.output_dir, pdf=not args.no_pdf, timeout=args.timeout
            )
        except (ParameterError, OutputError) as error:
            return _fail(f"error: {error}", 2)
        except ReportFailed as error:
            return _fail(f"failed: {error}; nothing written", 1)
        except KeyboardInterrupt:
            return _fail("interrupted (SIGINT); nothing written", 130)
        except Terminated as stop:
            if stop.signal_name == "SIGHUP":
                return _fail("hung up (SIGHUP); nothing written", 129)
            return _fail("terminated (SIGTERM); nothing written", 143)
        except Exception as error:  # anything unforeseen: one line, never a traceback
            return _fail(f"failed: {type(error).__name__}: {error}; nothing written", 1)
    for report in files:
        for warning in report.warnings:
            _fail(f"warning: {report.html.stem}: {warning}", 0)
        for path in (report.html, report.pdf, report.json, report.csv):
            if path is not None:
                print(path)
    return 0
