"""Reading a parameter file: a regular file, small, UTF-8 YAML, its aliases expanded under a cap.

:func:`read_parameter_file` is the one place a parameter file's bytes are read and parsed; the
bytes are read by the library's safe reader (:func:`vbi_lib._files.read_bytes`, which every
reader of a path uses).  It refuses, with a
:class:`~vbi_lib.reports.parameters.ParameterError` naming the file and within a fraction of
a second:

* anything but a regular file (a folder, a FIFO, ``/dev/zero``, a socket): it is opened
  without blocking and checked on the open descriptor, so nothing can hang or be swapped in
  between;
* more than :data:`MAX_BYTES` (a parameter file holds a few hundred bytes);
* text that is not UTF-8, not YAML, or a mapping that gives a key twice;
* YAML nested more than :data:`MAX_DEPTH` deep, checked on its stream of events before
  anything is built (a deep nesting would otherwise exhaust the parser's recursion slowly);
* YAML whose aliases (``&anchor`` and ``*alias``) would expand to more than
  :data:`MAX_VALUES` values (the "billion laughs": 500 bytes that expand to 10^9 values).
  The expansion is counted on the parsed node graph, each shared node once, before any
  Python object is built.

Booleans are YAML 1.2's ``true`` and ``false`` only: YAML 1.1's ``yes``, ``no``, ``on`` and
``off`` stay text, which a boolean parameter then refuses by name.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import yaml

from .._files import FileReadError, read_bytes
from .parameters import ParameterError

__all__ = ["MAX_BYTES", "MAX_DEPTH", "MAX_VALUES", "read_parameter_file"]

#: Largest parameter file read [bytes].
MAX_BYTES = 256 * 1024
#: Most YAML values (scalars, lists, mappings) a parameter file may expand to.
MAX_VALUES = 10_000
#: Deepest nesting of lists and mappings.
MAX_DEPTH = 20


class _Loader(yaml.SafeLoader):
    """YAML's safe loader that refuses a key given twice in one mapping, and reads only
    ``true`` and ``false`` as booleans (YAML 1.2)."""


# YAML 1.1 resolves yes/no/on/off to booleans; keep every other implicit type of the safe
# loader and give booleans YAML 1.2's spelling only
_Loader.yaml_implicit_resolvers = {
    first: [(tag, regexp) for tag, regexp in resolvers if tag != "tag:yaml.org,2002:bool"]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
_Loader.add_implicit_resolver(
    "tag:yaml.org,2002:bool", re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$"), list("tTfF")
)


def _mapping(loader: _Loader, node: yaml.MappingNode) -> dict:
    seen: set[object] = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node)
        try:
            twice = key in seen
        except TypeError:  # a list or mapping as a key: unhashable, refused as such
            raise yaml.constructor.ConstructorError(
                None, None, "a key must be a name, not a list or mapping", key_node.start_mark
            ) from None
        if twice:
            raise yaml.constructor.ConstructorError(
                None, None, f"key {key!r} is given twice", key_node.start_mark
            )
        seen.add(key)
    return loader.construct_mapping(node)


_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _mapping)


class _TooLarge(Exception):
    def __init__(self, what: str) -> None:
        self.what = what


def _expanded_size(root: yaml.Node) -> int:
    """Number of values ``root`` stands for with every alias expanded (shared nodes counted
    each time they are used, computed once each); :class:`_TooLarge` past the caps."""
    sizes: dict[int, int] = {}

    def size(node: yaml.Node, depth: int, path: tuple[int, ...]) -> int:
        key = id(node)
        if key in path:
            raise _TooLarge("refers to itself through an alias")
        if key in sizes:
            return sizes[key]
        if depth > MAX_DEPTH:
            raise _TooLarge(f"nests lists and mappings more than {MAX_DEPTH} deep")
        total = 1
        if isinstance(node, yaml.SequenceNode):
            for child in node.value:
                total += size(child, depth + 1, (*path, key))
        elif isinstance(node, yaml.MappingNode):
            for k, v in node.value:
                total += size(k, depth + 1, (*path, key)) + size(v, depth + 1, (*path, key))
        if total > MAX_VALUES:
            raise _TooLarge(
                f"expands to more than {MAX_VALUES:,} values through its aliases (&name and "
                "*name); a parameter file needs a few dozen: write the values out"
            )
        sizes[key] = total
        return total

    return size(root, 0, ())


def _shallow(text: str) -> None:
    """Walk the YAML's events (no recursion) and stop early past :data:`MAX_DEPTH` or past
    :data:`MAX_VALUES` values, before anything is composed."""
    depth = count = 0
    opening = (yaml.SequenceStartEvent, yaml.MappingStartEvent)
    closing = (yaml.SequenceEndEvent, yaml.MappingEndEvent)
    for event in yaml.parse(text, Loader=_Loader):
        if isinstance(event, opening):
            depth += 1
            if depth > MAX_DEPTH:
                raise _TooLarge(f"nests lists and mappings more than {MAX_DEPTH} deep")
        elif isinstance(event, closing):
            depth -= 1
        count += 1
        if count > 2 * MAX_VALUES:
            raise _TooLarge(f"holds more than {MAX_VALUES:,} values")


def _read_bytes(path: Path) -> bytes:
    """The file's bytes, read by the library's safe reader (:func:`vbi_lib._files.read_bytes`:
    a regular file of at most :data:`MAX_BYTES`, opened without blocking, so a FIFO or a
    device is refused, not waited on); its refusal as a :class:`ParameterError` that starts
    with the path."""
    try:
        return read_bytes(path, "parameter file", max_bytes=MAX_BYTES)
    except FileReadError as error:
        if error.size is not None:
            raise ParameterError("", path, _size_rule(path, error.size)) from None
        raise ParameterError("", path, f"{path}: {error.problem}") from None


def _size_rule(path: Path, size: int) -> str:
    return (
        f"{path}: is {size:,} bytes, more than the {MAX_BYTES // 1024} KiB a parameter file "
        "may have (one holds a few hundred bytes); is it the right file?"
    )


def read_parameter_file(path: str | Path) -> tuple[Any, bytes]:
    """The parameters of a YAML file, and its bytes (for its SHA-256).

    Returns
    -------
    values, data
        What the YAML holds (``{}`` for an empty file; :func:`read_parameters
        <vbi_lib.reports.parameters.read_parameters>` checks it) and the file's bytes.

    Raises
    ------
    ParameterError
        The file cannot be read, is not a regular file, is too large, is not UTF-8 YAML,
        gives a key twice or expands past the caps; the message starts with the path.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as f:
    ...     _ = f.write("a: &x [1, 1]\\nb: [*x, *x]\\n")
    >>> read_parameter_file(f.name)[0]
    {'a': [1, 1], 'b': [[1, 1], [1, 1]]}
    >>> read_parameter_file("/dev/zero")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vbi_lib.reports.ParameterError: /dev/zero: is a character device (...), not a regular file...
    """
    path = Path(path)
    data = _read_bytes(path)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise ParameterError("", path, f"{path}: is not a UTF-8 text file") from None
    loader = _Loader(text)
    try:
        _shallow(text)
        node = loader.get_single_node()
        if node is None:
            return {}, data
        _expanded_size(node)
        return loader.construct_document(node), data
    except _TooLarge as error:
        raise ParameterError("", path, f"{path}: {error.what}") from None
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        where = f", line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(error, "problem", None) or str(error)
        raise ParameterError("", path, f"{path}{where}: not valid YAML ({problem})") from None
    except RecursionError:
        raise ParameterError(
            "", path, f"{path}: nests lists and mappings too deeply to be a parameter file"
        ) from None
    finally:
        loader.dispose()
