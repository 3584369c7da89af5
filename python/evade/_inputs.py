"""Argument handling shared by the evade calls: scenarios by name or path, --set overrides,
files given as a path or as their text, parameter keywords as the CLI's key=value flags."""
from __future__ import annotations

import os
from typing import Iterable, List, Mapping, Optional, Sequence, Union

PathOrText = Union[str, "os.PathLike[str]"]

def scenario_path(name_or_path: Union[str, "os.PathLike[str]"]) -> str:
    """A shipped scenario's name ("seed0") or a YAML file's path, as ``--scenario`` takes it
    (names are found in the installed package first, then where the C++ library looks)."""
    return os.fspath(name_or_path)


def overrides(sets: Union[None, Mapping[str, object], Sequence[str]]) -> List[str]:
    """``set={"key": value}`` or ``set=["key=value"]`` as the CLI's repeated ``--set key=value``."""
    if sets is None:
        return []
    if isinstance(sets, Mapping):
        return [f"{k}={_value_text(v)}" for k, v in sets.items()]
    if isinstance(sets, str):
        return [sets]
    return [str(s) for s in sets]


def _value_text(v: object) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        # The shortest text that reads back to the same double, an integral value without its
        # ".0" (as a user types it on the command line, and as the messages echo it).
        text = repr(v)
        return text[:-2] if text.endswith(".0") else text
    return str(v)


def param_flags(**values: Optional[float]) -> List[str]:
    """Parameter keywords given (not None) as ``key=value`` overrides, keys as declared in C++."""
    return [f"{k}={_value_text(v)}" for k, v in values.items() if v is not None]


def is_text(value: PathOrText) -> bool:
    """A str holding a line break is a file's text; anything else names a file."""
    return isinstance(value, str) and ("\n" in value or "\r" in value)


def iter_nonempty(values: Iterable[str]) -> List[str]:
    return [v for v in values if v]
