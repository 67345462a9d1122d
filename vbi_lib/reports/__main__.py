"""``python -m vbi_lib.reports PARAMS.yaml --output-dir DIR`` (see :mod:`.cli`)."""

import sys

from .cli import main

sys.exit(main())
