"""The command line: ``vbi-report PARAMS.yaml [MORE.yaml ...] --output-dir DIR``.

Exit status 0 when every report is written, 2 for input that cannot be used (a parameter, a
parameter file, the output folder; nothing has run), 1 when a report fails while running,
130 on SIGINT and 143 on SIGTERM.  Every failure prints one line and no traceback, and
leaves nothing behind (see :mod:`vbi_lib.reports.running`).
"""

from __future__ import annotations

import argparse
import sys

from .parameters import ParameterError
from .running import OutputError, ReportFailed, Terminated, signals_raise, write_reports

__all__ = ["main"]

EPILOG = """\
example parameter file (every dimensional value is one number and one unit):

  title: I-76 span 3
  bridge: {span: 140 ft, k_mid: 222278 lbf/in, first_frequency: 2.08 Hz}
  vehicle: {mass: 200 lbf*s**2/in, frequency: 2.5 Hz, damping_ratio: 0.10}
  profile: {file: deck.csv, length_unit: inch}
  speeds: [30 mph, 70 mph]

Each PARAMS.yaml gives DIR/PARAMS.html and DIR/PARAMS.pdf; several files share one kernel.
More examples: the repository's examples/ folder.
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
        except Terminated:
            return _fail("terminated (SIGTERM); nothing written", 143)
        except Exception as error:  # anything unforeseen: one line, never a traceback
            return _fail(f"failed: {type(error).__name__}: {error}; nothing written", 1)
    for report in files:
        print(report.html)
        if report.pdf is not None:
            print(report.pdf)
    return 0
