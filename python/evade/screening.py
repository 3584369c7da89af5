"""Conjunction screening (``evade screen``): many objects, or one satellite against a catalog.

Paper 002 (Wang Xiaoyu, "Space entity collision prediction algorithm and self-adaptive
simulation step design", 2006) for ``method='paper'``; the screening that cannot miss an
approach below the threshold for ``method='robust'`` and for catalogs (docs/VALIDATION.md).
"""
from __future__ import annotations

import os
from typing import Dict, Mapping, Optional, Sequence, Union

import numpy as np

from . import _evade
from ._inputs import PathOrText, is_text, overrides, param_values, scenario_path
from ._result import Record, columns
from .sgp4 import Catalog, read_catalog

_OBJECT_EVENT_KEYS = ("i", "j", "name_i", "name_j", "tca_s", "tca_utc", "miss_m",
                      "rel_speed_mps", "collision", "warning")
_CATALOG_EVENT_KEYS = ("norad_i", "norad_j", "name_i", "name_j", "tca_s", "tca_utc", "miss_m",
                       "rel_speed_mps")


class ScreenResult(Record):
    """``evade screen --json``'s document; ``events`` as columns (a dict of numpy arrays)."""

    __slots__ = ("_event_keys",)

    def __init__(self, data: Dict[str, object], catalog: bool):
        super().__init__(data)
        object.__setattr__(self, "_event_keys", _CATALOG_EVENT_KEYS if catalog else _OBJECT_EVENT_KEYS)

    @property
    def events(self) -> Dict[str, np.ndarray]:  # type: ignore[override]
        """The conjunctions by TCA as columns: ``pandas.DataFrame(result.events)``."""
        return columns(self._data["events"], self._event_keys)


def screen(scenario: Optional[str] = None, *, catalog: Union[None, PathOrText, Catalog] = None,
           objects_csv: Optional[PathOrText] = None, population: Optional[int] = None,
           seed: Optional[int] = None, method: str = "robust", primary: Optional[int] = None,
           span_s: Optional[float] = None, threshold_m: Optional[float] = None,
           step_s: Optional[float] = None, start_utc: Optional[str] = None,
           prefilter: bool = True, path_filter: bool = True, time_filter: bool = True,
           trace: bool = False, threads: int = 0,
           set: Union[None, Mapping[str, object], Sequence[str]] = None) -> ScreenResult:
    """Screens for close approaches, as ``evade screen`` does.

    Objects: ``scenario`` (a shipped name such as "seed2", the default, or a YAML path) with
    ``set`` overrides, its objects or ``objects_csv`` or a synthetic ``population`` (``seed``),
    ``method`` 'paper' or 'robust' (``trace``: the paper's every sample).
    Catalog: ``catalog`` (a path, the text, or a :class:`evade.sgp4.Catalog`) moved by SGP4,
    ``primary`` a NORAD id to screen against it (``prefilter``: set aside by perigee/apogee
    the objects that can never come within the threshold; ``path_filter``: then by the orbit
    path those whose radius near the primary's orbit plane stays far from the primary's;
    ``time_filter``: then screen each
    object only when it can be within the threshold), ``start_utc`` (default: the latest
    element epoch).
    Both: ``span_s`` [s], ``threshold_m`` [m] (robust), ``step_s`` [s] (robust grid step; 0
    automatic), ``threads`` (0: every core). The GIL is released while screening.
    Raises evade.InputError with the CLI's message for an inapplicable or invalid input."""
    params = param_values(**{"span_s": span_s, "robust.threshold_m": threshold_m,
                             "robust.step_s": step_s})
    if catalog is not None:
        _refuse("a catalog screen (catalog=)", scenario=scenario, objects_csv=objects_csv,
                population=population, seed=seed, set=set, trace=trace or None)
        if method != "robust":
            raise _evade.InputError("method: a catalog screen has only the robust method")
        source = "<catalog>" if isinstance(catalog, Catalog) or is_text(catalog) else os.fspath(catalog)
        doc = _evade.screen_catalog(read_catalog(catalog), source, -1 if primary is None else int(primary),
                                    params, start_utc or "", int(threads), bool(prefilter),
                                    bool(path_filter), bool(time_filter))
        return ScreenResult(doc, catalog=True)
    _refuse("a screen of objects (no catalog=)", primary=primary, start_utc=start_utc,
            prefilter=None if prefilter else False, path_filter=None if path_filter else False,
            time_filter=None if time_filter else False)
    if seed is not None and population is None:
        raise _evade.InputError("seed: applies only with population (the seed of the synthetic population)")
    csv = "" if objects_csv is None else os.fspath(objects_csv)
    doc = _evade.screen_objects(scenario_path(scenario or "seed2"), overrides(set), params, method,
                                int(population or 0), int(seed or 1), csv, bool(trace), int(threads))
    return ScreenResult(doc, catalog=False)


def _refuse(mode: str, **given: object) -> None:
    for name, value in given.items():
        if value is not None:
            raise _evade.InputError(f"{name}: does not apply to {mode}")
