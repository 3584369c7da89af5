"""SGP4 catalogs: read element sets and propagate many objects at many instants.

SGP4 is Vallado, Crawford, Hujsak and Kelso, "Revisiting Spacetrack Report #3" (2006),
improved mode, WGS-72, the theory of ``evade propagate --tle/--omm`` (here four element sets
at a time where the processor has AVX2 and FMA, within 1e-12 |r| of it). States are in TEME
(``frame='teme'``) or J2000 (``frame='eci'``), SI units: metres and metres per second.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import List, Optional, Sequence, Union

import numpy as np

from . import _evade
from ._inputs import PathOrText, is_text

Catalog = _evade.Catalog

def error_text(code: int) -> str:
    """What an SGP4 error code of :attr:`Propagation.error` means (0: none)."""
    return _evade.sgp4_error_text(int(code))


def read_catalog(catalog: Union[PathOrText, Catalog]) -> Catalog:
    """Reads a catalog: a path, or the file's text (a str holding a line break).

    Formats (guessed from the text): TLE/3LE, CCSDS OMM KVN or XML, GP JSON or CSV. Entries
    that fail a check are not in the result; ``catalog.issues`` names each with its line and
    column, ``catalog.bad_entries`` counts them."""
    if isinstance(catalog, Catalog):
        return catalog
    if is_text(catalog):
        return _evade.read_catalog_text(catalog, "<text>")
    return _evade.read_catalog_file(os.fspath(catalog))


@dataclass(frozen=True)
class Propagation:
    """States of N objects at T instants (catalog order, instants as given)."""

    r_m: np.ndarray          #: (N, T, 3) position [m], NaN where SGP4 failed (not for decay)
    v_mps: Optional[np.ndarray]  #: (N, T, 3) velocity [m/s], likewise; None when not asked for
    error: np.ndarray        #: (N, T) SGP4 error codes (int32; 0 computed, see error_text)
    ids: np.ndarray          #: (N,) NORAD catalog numbers (int64)
    names: List[str]         #: N object names
    t_s: np.ndarray          #: (T,) the instants, seconds after start_utc
    start_utc: str           #: t = 0, "YYYY-MM-DD hh:mm:ss.fffffffff" UTC
    start_j2000_s: float     #: t = 0, UTC seconds since J2000 (86 400 s days)
    frame: str               #: "teme" or "eci" (J2000)
    issues: List[str] = field(default_factory=list)  #: rejected catalog entries


def propagate(catalog: Union[PathOrText, Catalog], start_utc: Optional[str],
              t_s: Union[Sequence[float], np.ndarray], frame: str = "teme",
              threads: int = 0, velocities: bool = True) -> Propagation:
    """SGP4 of every valid object of ``catalog`` at ``start_utc + t_s``.

    catalog: a path or the file's text (TLE/3LE, OMM, GP JSON/CSV), or a :class:`Catalog`.
    start_utc: ISO 8601 UTC ("2024-03-01T12:00:00Z"); None: the latest element epoch.
    t_s: 1-D seconds after start_utc (any order). frame: 'teme' or 'eci' (J2000).
    threads: worker threads (0: every core). The GIL is released while SGP4 runs.
    velocities: False leaves ``v_mps`` None (positions only: less memory to fill).
    States come from SGP4's four-lane path where the processor has it (AVX2 and FMA), within
    1e-13 |r| (near Earth) and 1e-12 |r| (deep space) of the scalar theory's, whose error
    codes they keep.
    Every (object, instant) is computed on its own: an SGP4 error at one instant gives its
    code in ``error`` and NaN states there, and the other instants are still computed.
    Raises evade.InputError for an unreadable start, a non-finite time, an unknown frame or a
    catalog with no valid entry."""
    cat = read_catalog(catalog)
    times = np.ascontiguousarray(t_s, dtype=np.float64)
    if times.ndim != 1:
        raise _evade.InputError(f"t_s must be 1-D seconds after start_utc, not of shape {times.shape}")
    n, t = len(cat), times.shape[0]
    # numpy's own arrays: it advises huge pages for large ones, so the first touch is cheap
    r = np.empty((n, t, 3))
    v = np.empty((n, t, 3)) if velocities else None
    err = np.empty((n, t), dtype=np.int32)
    start = _evade.sgp4_propagate_into(cat, start_utc or "", times, frame, int(threads), r, v, err)
    return Propagation(r_m=r, v_mps=v, error=err, ids=cat.ids, names=list(cat.names), t_s=times,
                       start_utc=_evade.utc_text(start), start_j2000_s=start, frame=frame,
                       issues=list(cat.issues))
