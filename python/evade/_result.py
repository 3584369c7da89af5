"""Result objects of the evade calls: the command's JSON document with attribute access.

Every call that has a CLI command returns the same document the command prints with
``--json`` (same keys, same numbers: the C++ result's JSON read back exactly), wrapped so that
``r.miss_m`` and ``r["miss_m"]`` both work; lists of rows are also offered as columns of numpy
arrays (:func:`columns`) that ``pandas.DataFrame`` takes as they are.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Dict, Iterator, List, Sequence

import numpy as np


def _wrap(value: Any) -> Any:
    if isinstance(value, dict):
        return Record(value)
    if isinstance(value, list):
        return [_wrap(v) for v in value]
    return value


class Record(Mapping):
    """A JSON object with attribute access (read-only). ``to_dict()`` gives the plain dict."""

    __slots__ = ("_data",)

    def __init__(self, data: Dict[str, Any]):
        object.__setattr__(self, "_data", data)

    def __getattr__(self, name: str) -> Any:
        try:
            return _wrap(self._data[name])
        except KeyError:
            raise AttributeError(
                f"{type(self).__name__} has no field '{name}' (fields: {', '.join(self._data)})"
            ) from None

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __getitem__(self, key: str) -> Any:
        return _wrap(self._data[key])

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def __dir__(self) -> List[str]:
        return sorted(set(super().__dir__()) | set(self._data))

    def __repr__(self) -> str:
        keys = ", ".join(list(self._data)[:8])
        more = ", ..." if len(self._data) > 8 else ""
        return f"{type(self).__name__}({keys}{more})"

    def to_dict(self) -> Dict[str, Any]:
        """The document as the CLI prints it with --json (plain dicts, lists and numbers)."""
        return self._data


def columns(rows: Sequence[Dict[str, Any]], keys: Sequence[str]) -> Dict[str, np.ndarray]:
    """Rows of a JSON list as one numpy array per key (float64, int64, bool or str)."""
    out: Dict[str, np.ndarray] = {}
    for k in keys:
        values = [r[k] for r in rows]
        sample = values[0] if values else None
        if isinstance(sample, bool):
            out[k] = np.array(values, dtype=bool)
        elif isinstance(sample, int):
            out[k] = np.array(values, dtype=np.int64)
        elif isinstance(sample, str):
            out[k] = np.array(values, dtype=str)
        else:
            out[k] = np.array([np.nan if v is None else v for v in values], dtype=np.float64)
    return out
