"""Responses at sections in a study: the per-crossing columns and their envelopes.

``run(..., sections=[x_1, x_2, ...])`` adds, for each section ``k`` (stations from the bridge
start [m], the same on every bridge of the table), the extremes of the displacement [m, up
positive], bending moment [N m, sagging positive] and shear [N] over each crossing, their
static counterparts (the vehicle's weight crawling across, exact statics) and the DAF of each
effect (:meth:`vbi_lib.models.results.Crossing.sections`, mode-acceleration method):

* ``section_k``: the station;
* ``{effect}_max_k``, ``{effect}_min_k``: the dynamic extremes;
* ``{effect}_static_max_k``, ``{effect}_static_min_k``: the static extremes;
* ``{effect}_daf_k``: the DAF in the governing sense (NaN where the static extreme is 0);
* ``shear_at_moment_max_k``, ``shear_at_moment_min_k``: the shear at the instant of the
  largest and smallest moment (the coincident shear).

:func:`envelope` then takes the extremes over the crossings of a table (or of groups of it),
leaving out by default the crossings that lost contact (outside the model's validity).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

import numpy as np
import pandas as pd

from ..beam_statics import EFFECTS

__all__ = ["SECTION_FIELDS", "check_sections", "envelope", "section_columns"]

#: The per-section result columns, before the ``_k`` suffix.
SECTION_FIELDS = (
    *(f"{e}_{f}" for e in EFFECTS for f in ("max", "min", "static_max", "static_min", "daf")),
    "shear_at_moment_max",
    "shear_at_moment_min",
)


def check_sections(sections: object, bridges: Sequence[Any], index: pd.Index, codes: Any) -> Any:
    """Sections as a 1-D float array that lies on every bridge of the table, or ``None``.

    Raises ``ValueError`` naming the rows whose bridge is shorter than a section.
    """
    if sections is None:
        return None
    try:
        x = np.atleast_1d(np.asarray(sections, dtype=float)).ravel()
    except (TypeError, ValueError):
        raise ValueError(
            f"sections={sections!r} must be stations [m] from the bridge start"
        ) from None
    if x.size == 0 or not np.isfinite(x).all() or (x < 0).any():
        raise ValueError(
            f"sections={sections!r} must be one or more finite stations >= 0 [m] from the "
            "bridge start"
        )
    lengths = np.array([b.length for b in bridges])[codes]
    short = lengths < x.max() * (1 - 1e-12)
    if short.any():
        bad = list(index[short])
        shown = ", ".join(repr(r) for r in bad[:8]) + (" and more" if len(bad) > 8 else "")
        raise ValueError(
            f"sections={sections!r}: station {x.max():g} m lies beyond the end of the bridge "
            f"(as short as {lengths[short].min():g} m) in rows {shown}; give stations on "
            "every bridge of the study, or run the bridges in separate studies"
        )
    return x


def section_columns(result: Any) -> dict[str, np.ndarray]:
    """The per-section values of one crossing's :class:`SectionResponse`, by column name."""
    out: dict[str, np.ndarray] = {}
    daf = result.daf
    for e, effect in enumerate(EFFECTS):
        out[f"{effect}_max"] = result.maximum[e]
        out[f"{effect}_min"] = result.minimum[e]
        out[f"{effect}_static_max"] = result.static.maximum[e]
        out[f"{effect}_static_min"] = result.static.minimum[e]
        out[f"{effect}_daf"] = daf[e]
    out["shear_at_moment_max"] = result.coincident("moment", "max", "shear")
    out["shear_at_moment_min"] = result.coincident("moment", "min", "shear")
    return out


def envelope(
    results: pd.DataFrame,
    by: str | Sequence[str] | None = None,
    include_lost_contact: bool = False,
) -> pd.DataFrame:
    """Envelope over the crossings of a study run with ``sections``: one row per section.

    Parameters
    ----------
    results
        A table from :func:`vbi_lib.studies.run` called with ``sections=...``.
    by
        Columns to group by (e.g. ``"bridge_name"``: the sections are stations on each
        bridge, so an envelope normally belongs to one bridge); ``None``: the whole table.
    include_lost_contact
        Whether crossings that lost contact count.  By default they are left out (their
        responses are outside the model's validity) and counted in ``excluded_lost_contact``.

    Returns
    -------
    pandas.DataFrame
        Per group, section and effect (SI units: m, N m, N): ``section``, ``effect``,
        ``maximum`` and ``minimum`` over the crossings and the index of the crossing where each
        occurred, the static extremes, the largest DAF and its crossing, ``crossings`` (how
        many counted) and ``excluded_lost_contact``.

    Raises
    ------
    ValueError
        A table without section columns, or ``by`` naming a missing column.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib import studies
    >>> bridge = vbi.Bridge.continuous([12.0, 15.0], EI=4e9, mass_per_length=6000.0)
    >>> table = studies.grid(bridge, vbi.Vehicle.from_frequency(2e4, 3.0),
    ...                      studies.FlatProfile(40.0, 0.05), [10.0, 20.0], 10.0,
    ...                      model="modal", modes=4)
    >>> env = envelope(studies.run(table, "serial", sections=[6.0, 12.0]))
    >>> env[["section", "effect", "crossings"]].head(2).to_records(index=False).tolist()
    [(6.0, 'displacement', 2), (6.0, 'moment', 2)]
    """
    if not isinstance(results, pd.DataFrame):
        raise TypeError(f"results must be a pandas.DataFrame, got {type(results).__name__}")
    numbers = sorted(
        {int(m.group(1)) for c in results.columns if (m := re.fullmatch(r"section_(\d+)", str(c)))}
    )
    if not numbers:
        raise ValueError(
            "results has no section columns (section_1, moment_max_1, ...); run the study "
            "with studies.run(..., sections=[...])"
        )
    keys = [] if by is None else [by] if isinstance(by, str) else list(by)
    missing = [k for k in keys if k not in results.columns]
    if missing:
        raise ValueError(f"by={by!r}: the table has no columns {missing}")
    lost = (
        results["lost_contact"].to_numpy(bool)
        if "lost_contact" in results.columns
        else np.zeros(len(results), bool)
    )
    groups = [((), results)] if not keys else list(results.groupby(keys, sort=True))
    rows = []
    for key, group in groups:
        key = key if isinstance(key, tuple) else (key,)
        excluded = lost[results.index.get_indexer(group.index)]
        used = group if include_lost_contact else group[~excluded]
        for k in numbers:
            for effect in EFFECTS:
                row: dict[str, Any] = dict(zip(keys, key, strict=True))
                row["section"] = float(group[f"section_{k}"].iloc[0])
                row["effect"] = effect
                for name, pick in (("maximum", "idxmax"), ("minimum", "idxmin")):
                    column = used[f"{effect}_{name[:3]}_{k}"]
                    valid = column.dropna()
                    row[name] = getattr(valid, name[:3])() if len(valid) else np.nan
                    row[f"crossing_of_{name}"] = getattr(valid, pick)() if len(valid) else None
                row["static_maximum"] = used[f"{effect}_static_max_{k}"].max()
                row["static_minimum"] = used[f"{effect}_static_min_{k}"].min()
                daf = used[f"{effect}_daf_{k}"].dropna()
                row["daf"] = daf.max() if len(daf) else np.nan
                row["crossing_of_daf"] = daf.idxmax() if len(daf) else None
                row["crossings"] = len(used)
                row["excluded_lost_contact"] = 0 if include_lost_contact else int(excluded.sum())
                rows.append(row)
    return pd.DataFrame(rows)
