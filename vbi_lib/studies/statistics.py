"""Statistics of study results: characteristic values, agreement with a reference, and how
many crossings left the model's validity."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import pandas as pd

from .. import _validation as check


def characteristic_values(
    values: Any,
    quantiles: Sequence[float] = (0.95, 0.99),
    confidence: float = 0.95,
    allowance: float | None = None,
) -> pd.DataFrame:
    """Mean and upper percentiles of a DAF sample with confidence intervals.

    * mean: Student-t interval ``mean +/- t s / sqrt(n)``;
    * percentiles: the distribution-free order-statistic interval ``[x_(l), x_(u)]`` with
      ``l, u`` the binomial ``(n, q)`` quantiles at ``(1 -/+ confidence) / 2`` (an upper bound
      beyond the largest sample is ``inf``: too few crossings to bound it);
    * ``P(DAF > 1 + allowance)``: the fraction of crossings above the code's allowance with a
      Wilson score interval (default allowance AASHTO LRFD's 33 %, Table 3.6.2.1-1).

    Parameters
    ----------
    values
        DAF of each crossing (a column of :func:`run`'s table); NaN is an error.
    quantiles
        Probabilities of the percentiles reported.
    confidence
        Confidence level of the intervals.
    allowance
        Code allowance ``IM``; ``None`` uses AASHTO LRFD's 0.33.

    Returns
    -------
    pandas.DataFrame
        Rows ``mean``, ``p95``, ``p99`` (one per quantile), ``P(DAF > 1.33)``; columns
        ``estimate``, ``lower``, ``upper``.

    Examples
    --------
    >>> c = characteristic_values([1.0, 1.1, 1.2, 1.3, 1.4], quantiles=(0.5,))
    >>> c.loc["mean"].round(3).tolist()
    [1.2, 1.004, 1.396]
    """
    from scipy import stats

    from ..amplification import aashto_lrfd_allowance

    x = np.sort(np.asarray(values, dtype=float).ravel())
    if x.size < 2:
        raise ValueError(f"characteristic_values needs at least two values; got {x.size}")
    if not np.isfinite(x).all():
        raise ValueError("values contain NaN or infinity; drop failed or missing crossings first")
    if not 0.0 < confidence < 1.0:
        raise ValueError(f"confidence={confidence!r} must be in (0, 1)")
    allowance = (
        aashto_lrfd_allowance() if allowance is None else check.non_negative("allowance", allowance)
    )
    n = x.size
    alpha = 1.0 - confidence
    rows: dict[str, tuple[float, float, float]] = {}
    mean = float(x.mean())
    half = float(stats.t.ppf(1 - alpha / 2, n - 1) * x.std(ddof=1) / math.sqrt(n))
    rows["mean"] = (mean, mean - half, mean + half)
    for q in quantiles:
        if not 0.0 < q < 1.0:
            raise ValueError(f"quantile {q!r} must be in (0, 1)")
        low = int(stats.binom.ppf(alpha / 2, n, q))  # order statistic x_(low), 1-based
        high = int(stats.binom.ppf(1 - alpha / 2, n, q)) + 1
        lower = float(x[low - 1]) if low >= 1 else -np.inf
        upper = float(x[high - 1]) if high <= n else np.inf
        rows[f"p{100 * q:g}"] = (float(np.quantile(x, q)), lower, upper)
    exceed = int((x > 1.0 + allowance).sum())
    p = exceed / n
    z = float(stats.norm.ppf(1 - alpha / 2))
    centre = (p + z**2 / (2 * n)) / (1 + z**2 / n)
    spread = z * math.sqrt(p * (1 - p) / n + z**2 / (4 * n**2)) / (1 + z**2 / n)
    rows[f"P(DAF > {1 + allowance:g})"] = (p, max(0.0, centre - spread), min(1.0, centre + spread))
    return pd.DataFrame.from_dict(rows, orient="index", columns=["estimate", "lower", "upper"])


def agreement(predicted: object, reference: object) -> dict[str, float]:
    """How well a model's DAFs match reference DAFs (for example a finite-element model's).

    Returns ``n``; ``r2``, the squared correlation coefficient; ``bias``, the mean relative
    error ``mean(predicted / reference - 1)``; ``mape``, the mean absolute relative error;
    and ``max_ape``, the largest absolute relative error.

    Examples
    --------
    >>> scores = agreement([1.1, 2.2, 2.7], [1.0, 2.0, 3.0])
    >>> {k: round(v, 4) for k, v in scores.items()}
    {'n': 3, 'r2': 0.9552, 'bias': 0.0333, 'mape': 0.1, 'max_ape': 0.1}
    """
    p = check.finite_array("predicted", predicted)
    f = check.finite_array("reference", reference)
    if p.shape != f.shape or p.size < 2:
        raise ValueError(
            f"predicted ({p.size}) and reference ({f.size}) need the same length, at least 2"
        )
    if (f <= 0).any():
        raise ValueError("reference DAFs must be positive")
    error = p / f - 1.0
    return {
        "n": int(p.size),
        "r2": float(np.corrcoef(p, f)[0, 1] ** 2),
        "bias": float(error.mean()),
        "mape": float(np.abs(error).mean()),
        "max_ape": float(np.abs(error).max()),
    }


#: Columns of a results table that :func:`contact_summary` reads.
CONTACT_COLUMNS = ("daf", "lost_contact", "min_contact_force_ratio")


def contact_summary(results: pd.DataFrame, by: Any = None, daf_above: float = 2.0) -> pd.DataFrame:
    """How many crossings of a study lost contact, and which large DAFs they explain.

    A crossing whose contact force became tensile (``lost_contact``) is outside the
    one-coordinate and modal models' validity: the sprung mass is tied to the road, so its
    DAF is not a prediction of a real truck's.  This counts them, and the crossings whose
    DAF exceeds ``daf_above``, per group of a :func:`run` table.

    Parameters
    ----------
    results
        A table from :func:`run` (columns ``daf``, ``lost_contact``,
        ``min_contact_force_ratio``).
    by
        A column name, or a list of them, to group by; ``None``: one row ``"all"``.
    daf_above
        The DAF above which crossings are counted (default 2).

    Returns
    -------
    pandas.DataFrame
        One row per group, columns: ``crossings``; ``lost contact`` (how many) and
        ``lost contact [%]``; ``smallest contact force / weight [-]``; ``largest DAF [-]``;
        ``largest DAF in contact [-]`` (NaN when every crossing lost contact);
        ``DAF > x`` (how many) and ``DAF > x, lost contact`` (how many of those lost
        contact), ``x`` being ``daf_above``.

    Raises
    ------
    ValueError
        A column missing, NaN among the DAFs or contact ratios, or ``daf_above`` not a
        positive number.

    Examples
    --------
    >>> import pandas as pd
    >>> t = pd.DataFrame({"daf": [1.2, 2.5, 3.1], "lost_contact": [False, False, True],
    ...                   "min_contact_force_ratio": [0.6, 0.1, -0.4]})
    >>> s = contact_summary(t).loc["all"]
    >>> int(s["lost contact"]), int(s["DAF > 2"]), float(s["largest DAF in contact [-]"])
    (1, 2, 2.5)
    """
    if not isinstance(results, pd.DataFrame):
        raise TypeError(f"results must be a pandas.DataFrame from run(), got {type(results)}")
    missing = [c for c in CONTACT_COLUMNS if c not in results.columns]
    if missing:
        raise ValueError(
            f"results lacks the column(s) {missing}; give a table from vbi_lib.studies.run"
        )
    daf_above = check.positive("daf_above", daf_above)
    numbers = results[["daf", "min_contact_force_ratio"]].to_numpy(float)
    if not np.isfinite(numbers).all():
        raise ValueError(
            "results hold NaN DAFs or contact ratios; drop failed or missing crossings first"
        )
    table = pd.DataFrame(
        {
            "daf": results["daf"].to_numpy(float),
            "lost": results["lost_contact"].to_numpy(bool),
            "ratio": results["min_contact_force_ratio"].to_numpy(float),
        },
        index=results.index,
    )
    if by is None:
        keys: Any = pd.Series("all", index=table.index)
    else:
        keys = [results[c] for c in np.atleast_1d(by)]
    above = f"DAF > {daf_above:g}"
    rows = {}
    for key, part in table.groupby(keys, sort=False):
        large = part["daf"] > daf_above
        kept = part.loc[~part["lost"], "daf"]
        rows[key[0] if isinstance(key, tuple) and len(key) == 1 else key] = {
            "crossings": len(part),
            "lost contact": int(part["lost"].sum()),
            "lost contact [%]": 100.0 * part["lost"].mean(),
            "smallest contact force / weight [-]": part["ratio"].min(),
            "largest DAF [-]": part["daf"].max(),
            "largest DAF in contact [-]": kept.max() if len(kept) else np.nan,
            above: int(large.sum()),
            f"{above}, lost contact": int((large & part["lost"]).sum()),
        }
    out = pd.DataFrame.from_dict(rows, orient="index")
    counts = ["crossings", "lost contact", above, f"{above}, lost contact"]
    out = out.astype(dict.fromkeys(counts, "int64"))
    if by is not None:
        names = list(np.atleast_1d(by))
        if len(names) > 1:
            out.index = pd.MultiIndex.from_tuples(out.index, names=names)
        else:
            out.index.name = names[0]
    return out
