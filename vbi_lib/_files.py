"""Reading a file the user names, safely: a regular file, of bounded size, in a known encoding.

Every reader of the library that opens a path it was given goes through :func:`read_bytes`
or :func:`read_text`, so that no path can hang it or exhaust the memory:

* **only regular files** are opened.  A directory, a character or block device
  (``/dev/zero`` never ends), a named pipe (FIFO: reading it waits for a writer, forever) or
  a socket is refused, by what it is, before it is opened; the file is opened without
  blocking and checked again after opening (the path may have changed in between);
* **a size cap** (:data:`MAX_FILE_BYTES` by default, ``max_bytes`` to change it) is checked
  on the file's size before anything is read, and no more than ``max_bytes + 1`` bytes are
  ever read (a file that grows while it is read is refused as well);
* **text** is UTF-8 (with or without a byte-order mark) or UTF-16 (with a byte-order mark,
  or without one when every other byte of the file is a zero, as in text written by
  Windows tools).  Anything else is refused by name: UTF-32, an 8-bit encoding such as
  Latin-1 or Windows-1252, or binary data (zero bytes in text that is not UTF-16).

Every refusal is a :class:`FileReadError` (a ``ValueError``) whose message starts with
``name=<path>`` and says what was found and what to do.
"""

from __future__ import annotations

import codecs
import os
import stat
from pathlib import Path

__all__ = ["MAX_FILE_BYTES", "FileReadError", "decode_text", "read_bytes", "read_text"]

#: Default size cap of a file a reader opens [bytes]: 100 MiB, about four million samples of
#: a two-column profile written with ten digits a number.  Pass ``max_bytes`` to raise it.
MAX_FILE_BYTES = 100 * 2**20

#: What :func:`os.stat` may say a path is, other than a regular file.
_KINDS = (
    (stat.S_ISDIR, "a directory"),
    (stat.S_ISCHR, "a character device (it may never end, as /dev/zero does)"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISFIFO, "a named pipe (FIFO: reading it waits for a writer)"),
    (stat.S_ISSOCK, "a socket"),
)


class FileReadError(ValueError):
    """A path that names no readable regular text file; the message says what it is instead.

    Attributes
    ----------
    name
        The parameter that gave the path.
    path
        The path, as text.
    problem
        What is wrong, without the ``name=path`` prefix (for readers that put the file's name
        first in their own messages).
    size
        The file's size [bytes] when it was refused for being larger than ``max_bytes``
        (for readers that state their own cap), else ``None``.
    """

    def __init__(self, name: str, path: str | Path, problem: str, size: int | None = None) -> None:
        super().__init__(f"{name}={str(path)!r} {problem}")
        self.name = name
        self.path = str(path)
        self.problem = problem
        self.size = size


def _as_path(name: str, path: object) -> Path:
    if isinstance(path, bytes) or not (isinstance(path, str) or hasattr(path, "__fspath__")):
        raise TypeError(f"{name}={path!r} must be a file path (text or pathlib.Path)")
    return Path(path)


def _size_text(size: int) -> str:
    for unit, factor in (("GiB", 2**30), ("MiB", 2**20), ("KiB", 2**10)):
        if size >= factor:
            return f"{size / factor:.3g} {unit}"
    return f"{size} bytes"


def _max_bytes(max_bytes: object) -> int:
    if isinstance(max_bytes, bool) or not isinstance(max_bytes, int):
        raise TypeError(
            f"max_bytes={max_bytes!r} must be a whole number of bytes (an int), not "
            f"{type(max_bytes).__name__}"
        )
    if max_bytes < 1:
        raise ValueError(f"max_bytes={max_bytes!r} must be a whole number of bytes >= 1")
    return max_bytes


def _kind(mode: int) -> str | None:
    """What a file of this ``st_mode`` is, when it is not a regular file."""
    if stat.S_ISREG(mode):
        return None
    for test, words in _KINDS:
        if test(mode):
            return words
    return "not a regular file"


def _too_big(name: str, path: Path, size: int, max_bytes: int) -> FileReadError:
    return FileReadError(
        name,
        path,
        f"holds {_size_text(size)}, more than max_bytes={max_bytes} ({_size_text(max_bytes)}) "
        "that a reader opens by default; pass a larger max_bytes to read it",
        size,
    )


def read_bytes(path: object, name: str = "path", max_bytes: int = MAX_FILE_BYTES) -> bytes:
    """The bytes of the regular file ``path``, at most ``max_bytes`` of them.

    Parameters
    ----------
    path
        The file (text or a path-like).
    name
        The parameter that gave it, for messages.
    max_bytes
        The largest file read [bytes] (:data:`MAX_FILE_BYTES` by default).

    Raises
    ------
    TypeError
        ``path`` that is not a path, ``max_bytes`` that is not an int.
    FileReadError
        (a ``ValueError``) A path that does not exist or cannot be opened, one that names a
        directory, device, named pipe or socket, or a file larger than ``max_bytes``.

    Examples
    --------
    >>> read_bytes("/dev/zero")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vbi_lib._files.FileReadError: path='/dev/zero' is a character device (...), not a regular ...
    """
    file = _as_path(name, path)
    limit = _max_bytes(max_bytes)
    try:
        info = os.stat(file)
    except OSError as exc:
        raise FileReadError(name, file, f"cannot be read ({exc.strerror or exc})") from None
    except ValueError:  # a zero character in the path
        raise FileReadError(
            name, file, "cannot be a file name: it holds a zero character"
        ) from None
    kind = _kind(info.st_mode)
    if kind is not None:
        raise FileReadError(name, file, f"is {kind}, not a regular file; give the path of a file")
    if info.st_size > limit:
        raise _too_big(name, file, info.st_size, limit)
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
    try:
        handle = os.open(file, flags | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        raise FileReadError(name, file, f"cannot be read ({exc.strerror or exc})") from None
    try:
        kind = _kind(os.fstat(handle).st_mode)  # the path may name another file by now
        if kind is not None:
            raise FileReadError(name, file, f"is {kind}, not a regular file; give a file")
        chunks, count = [], 0
        while count <= limit:
            chunk = os.read(handle, min(1 << 20, limit + 1 - count))
            if not chunk:
                break
            chunks.append(chunk)
            count += len(chunk)
    except OSError as exc:
        raise FileReadError(name, file, f"cannot be read ({exc.strerror or exc})") from None
    finally:
        os.close(handle)
    if count > limit:
        raise _too_big(name, file, count, limit)
    return b"".join(chunks)


def _line_of(data: bytes, offset: int) -> int:
    return data.count(b"\n", 0, offset) + 1


def _utf16_without_bom(data: bytes) -> str | None:
    """``"utf-16-le"`` or ``"utf-16-be"`` when every other byte is zero (text of the Latin
    range written as UTF-16 without a byte-order mark), else ``None``."""
    if len(data) < 2 or len(data) % 2:
        return None
    even, odd = data[0::2], data[1::2]
    if odd.count(0) == len(odd) and even.count(0) == 0:
        return "utf-16-le"
    if even.count(0) == len(even) and odd.count(0) == 0:
        return "utf-16-be"
    return None


def decode_text(data: bytes, name: str = "path", path: object = "") -> str:
    """``data`` as text: UTF-8 (a byte-order mark allowed) or UTF-16; others refused by name.

    Raises
    ------
    FileReadError
        UTF-32, an 8-bit encoding (Latin-1, Windows-1252, ...), or binary data.
    """
    if data.startswith((codecs.BOM_UTF32_LE, codecs.BOM_UTF32_BE)):
        raise FileReadError(
            name, path, "is UTF-32 text, which the readers do not take; save it as UTF-8"
        )
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        encoding = "utf-16"
    elif data.startswith(codecs.BOM_UTF8):
        encoding = "utf-8-sig"
    elif b"\0" in data:
        encoding = _utf16_without_bom(data)
        if encoding is None:
            at = data.index(b"\0")
            raise FileReadError(
                name,
                path,
                f"is not a text file: it holds zero bytes (the first at byte {at}, line "
                f"{_line_of(data, at)}) and is not UTF-16 text; give a UTF-8 text file",
            )
    else:
        encoding = "utf-8"
    try:
        text = data.decode(encoding)
    except UnicodeDecodeError as exc:
        if encoding == "utf-8":
            byte = data[exc.start]
            raise FileReadError(
                name,
                path,
                f"is not UTF-8 text: byte 0x{byte:02X} at line {_line_of(data, exc.start)} "
                "is not valid UTF-8, as in an 8-bit encoding such as Latin-1 or Windows-1252; "
                "save the file as UTF-8 (or UTF-16)",
            ) from None
        raise FileReadError(
            name, path, f"is not valid {encoding.upper().replace('-SIG', '')} text ({exc.reason})"
        ) from None
    if "\0" in text:
        line = text.count("\n", 0, text.index("\0")) + 1
        raise FileReadError(
            name, path, f"is not a text file: it holds a zero character at line {line}"
        )
    return text


def read_text(path: object, name: str = "path", max_bytes: int = MAX_FILE_BYTES) -> str:
    """The text of the regular file ``path``: UTF-8 (with or without a byte-order mark) or
    UTF-16; at most ``max_bytes`` bytes.

    The safe reader of every text file the library opens (profiles, ERD files, parameter
    files): see the module docstring for what is refused and why.

    Parameters
    ----------
    path
        The file (text or a path-like).
    name
        The parameter that gave it, for messages (``"profile.file"``, ``"path"``).
    max_bytes
        The largest file read [bytes] (:data:`MAX_FILE_BYTES` by default).

    Returns
    -------
    str
        The text, byte-order mark removed, line ends as in the file.

    Raises
    ------
    TypeError
        ``path`` that is not a path, ``max_bytes`` that is not an int.
    FileReadError
        (a ``ValueError``) As :func:`read_bytes`, or text in another encoding (UTF-32, an
        8-bit encoding) or binary data, named in the message.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> _ = f.write_bytes("0 1\\n".encode("utf-16"))
    >>> read_text(f)
    '0 1\\n'
    """
    return decode_text(read_bytes(path, name, max_bytes), name, path)
