"""Saving a study's results: Parquet or CSV, never a half-written file; reading them back
from regular files only."""

from __future__ import annotations

import io
import os
import tempfile
from pathlib import Path

import pandas as pd

from .._files import read_bytes, read_text

__all__ = ["load", "save"]


def save(results: pd.DataFrame, path: str | os.PathLike[str]) -> Path:
    """Write a results table to ``.parquet`` or ``.csv`` (never a half-written file).

    The table is written to a temporary file beside ``path`` and moved into place.

    Raises
    ------
    TypeError
        ``path`` that is not a path, ``results`` that is not a DataFrame.
    ValueError
        A suffix other than ``.parquet``, ``.pq`` or ``.csv``.
    FileNotFoundError, NotADirectoryError, IsADirectoryError
        The folder of ``path`` does not exist or is not a folder, or ``path`` is a folder
        (checked before anything is written).

    Examples
    --------
    >>> import pandas as pd, tempfile, os
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = save(pd.DataFrame({"daf": [1.1, 1.2]}), os.path.join(d, "s.csv"))
    ...     load(p)["daf"].tolist()
    [1.1, 1.2]
    """
    if isinstance(path, bytes) or not (isinstance(path, str) or hasattr(path, "__fspath__")):
        raise TypeError(f"path={path!r} must be a file path (text or pathlib.Path)")
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".parquet", ".pq", ".csv"):
        raise ValueError(f"path={str(path)!r}: save to a '.parquet' or '.csv' file")
    if not isinstance(results, pd.DataFrame):
        raise TypeError(f"results must be a pandas.DataFrame, got {type(results).__name__}")
    folder = path.parent
    if not folder.exists():
        raise FileNotFoundError(
            f"path={str(path)!r}: the folder {str(folder)!r} does not exist; create it "
            "(os.makedirs) or save elsewhere"
        )
    if not folder.is_dir():
        raise NotADirectoryError(f"path={str(path)!r}: {str(folder)!r} is not a folder")
    if path.is_dir():
        raise IsADirectoryError(f"path={str(path)!r} is a folder; give a file name in it")
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(handle)
    try:
        if suffix == ".csv":
            results.to_csv(temporary, index=False)
        else:
            results.to_parquet(temporary, index=False)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return path


#: Largest results file :func:`load` reads by default [bytes] (2 GiB); ``max_bytes`` raises it.
MAX_RESULTS_BYTES = 2 * 2**30


def load(path: str | os.PathLike[str], *, max_bytes: int = MAX_RESULTS_BYTES) -> pd.DataFrame:
    """Read a table written by :func:`save` (``.parquet`` or ``.csv``).

    Only a regular file of at most ``max_bytes`` is read (:mod:`vbi_lib._files`); a CSV
    file in UTF-8 or UTF-16.

    Raises
    ------
    TypeError
        ``path`` that is not a path.
    ValueError
        Another suffix; a path that is missing, a folder, a device, a pipe or a socket, or a
        file larger than ``max_bytes`` (:class:`vbi_lib._files.FileReadError`).
    """
    if isinstance(path, bytes) or not (isinstance(path, str) or hasattr(path, "__fspath__")):
        raise TypeError(f"path={path!r} must be a file path (text or pathlib.Path)")
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".csv":
        return pd.read_csv(io.StringIO(read_text(path, "path", max_bytes)))
    if suffix in (".parquet", ".pq"):
        return pd.read_parquet(io.BytesIO(read_bytes(path, "path", max_bytes)))
    raise ValueError(f"path={str(path)!r}: load a '.parquet' or '.csv' file")
