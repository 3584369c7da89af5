"""Argument handling shared by the evade calls: scenarios by name or path, --set overrides,
files given as a path or as their text, parameter keywords as the CLI's parameter flags."""
from __future__ import annotations

import numbers
import os
from typing import Dict, Iterable, List, Mapping, Sequence, Union

from ._evade import InputError

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


def param_values(**values: object) -> Dict[str, float]:
    """Parameter keywords given (not None), keys as declared in C++, each as the float given:
    they reach the C++ reader as doubles, as the CLI's parameter flags do (no text on the way).
    A value that is not a real number is refused naming its key."""
    out: Dict[str, float] = {}
    for k, v in values.items():
        if v is None:
            continue
        if isinstance(v, bool) or not isinstance(v, numbers.Real):
            raise InputError(f"key '{k}' = '{v}' is invalid: expected a number")
        out[k] = float(v)
    return out


def is_text(value: PathOrText) -> bool:
    """A str holding a line break is a file's text; anything else names a file."""
    return isinstance(value, str) and ("\n" in value or "\r" in value)


def iter_nonempty(values: Iterable[str]) -> List[str]:
    return [v for v in values if v]
