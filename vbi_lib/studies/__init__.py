r"""Parametric studies and Monte Carlo: many crossings described as a table, run in batches.

A *study* is a table of scenarios, one row per crossing: a bridge, a vehicle, a road profile
(a :class:`~vbi_lib.Profile` or a small *recipe* that builds one), a speed, where the bridge
starts on the road, how far the road is slid under the bridge, whether the model is coupled
and which crossing model runs it (with how many modes).  :func:`grid` builds the full
factorial of some axes;
:func:`run` simulates every row and returns one tidy row per crossing: every input as plain
columns, the DAF of each span (88)-(91), the peak contact-force amplification
:math:`\max R / (m_v g)` on the bridge and where and when it occurred, and whether the
contact force stayed compressive (the model's validity).

The package is split by job: :mod:`~vbi_lib.studies.recipes` (roads a worker builds),
:mod:`~vbi_lib.studies.scenarios` (tables: grids, Monte Carlo draws),
:mod:`~vbi_lib.studies.checks` (a table checked before any work),
:mod:`~vbi_lib.studies.runner` (the runner and its executors), :mod:`~vbi_lib.studies.chunks`
(what a worker runs), :mod:`~vbi_lib.studies.workers` (a worker that died),
:mod:`~vbi_lib.studies.files` (saving results),
:mod:`~vbi_lib.studies.statistics` (characteristic values, agreement with a reference, how
many crossings lost contact) and
:mod:`~vbi_lib.studies.envelopes` (responses at sections: their columns and envelopes,
``run(..., sections=[...])`` and :func:`envelope`).

How it runs
-----------
Rows are cut into chunks; each chunk is one call of :func:`~vbi_lib.simulate_many`
(compiled, no time histories kept) inside a worker of a :class:`concurrent.futures.Executor`:
a local process pool by default, or any executor you pass, such as
``dask.distributed.Client(...).get_executor()``.  Profiles are built from their recipes in the
worker and cached there (a profile shared by many rows is generated once per worker).  Every
crossing depends only on its own row, so the table is the same, bit for bit, whatever the
executor and the chunk size; random studies draw all their random numbers in
:func:`monte_carlo`, before any work, from one seed.  So are the validity columns (contact
flags and fractions, and the inputs outside their intended ranges: ``bridge_notes``,
``vehicle_notes``, ``profile_notes``), with or without ``sections``.  When a worker of a
process pool dies (killed, perhaps out of memory), the chunks it held run again once, alone,
in a new pool; a chunk whose worker dies again keeps NaN and the reason in ``error``, and
every finished row is kept.

Sliding the road: with ``profile_offset = d >= 0`` the wheel meets, at station ``x``, the
elevation the profile has at ``x + d``; the truck still starts at the profile's first
station, so the approach length stays ``bridge_start - profile.start`` while the features on
the bridge move back by ``d`` (the study's Figure 2.15.16 slides the road in 5 ft steps).
"""

from .envelopes import envelope
from .files import load, save
from .recipes import FlatProfile, HarmonicProfile, ISOProfile
from .runner import (
    DEFAULT_CHUNK_SIZE,
    SERIAL_BELOW,
    default_executor,
    run,
    shutdown_default_executor,
)
from .scenarios import (
    OPTIONAL_COLUMNS,
    REQUIRED_COLUMNS,
    TAG_PREFIX,
    grid,
    monte_carlo,
    parametric_bridges,
    parametric_trucks,
    validate,
)
from .statistics import agreement, characteristic_values, contact_summary

__all__ = [
    "DEFAULT_CHUNK_SIZE",
    "OPTIONAL_COLUMNS",
    "REQUIRED_COLUMNS",
    "SERIAL_BELOW",
    "TAG_PREFIX",
    "FlatProfile",
    "HarmonicProfile",
    "ISOProfile",
    "agreement",
    "characteristic_values",
    "contact_summary",
    "default_executor",
    "envelope",
    "grid",
    "load",
    "monte_carlo",
    "parametric_bridges",
    "parametric_trucks",
    "run",
    "save",
    "shutdown_default_executor",
    "validate",
]
