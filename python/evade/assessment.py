"""Collision probability of one conjunction (``evade assess``), the collision-avoidance burn
(``evade plan cam``) and CCSDS Conjunction Data Messages (CCSDS 508.0-B-1, KVN or XML).

Pc methods: the 2D Pc of the short-term encounter model (Foster & Estes 1992, NASA
JSC-25898), Chan's series (Chan 2008, "Spacecraft Collision Probability", eq. 5.33), Alfano's
maximum Pc (Alfano 2005), the 3-D Nc over a window about TCA when the 2D usage checks fail,
and on request the Monte Carlo Pc (Alfano 2009, "Satellite Conjunction Monte Carlo
Analysis"); the recommended Pc names its method. Units are SI: m, m/s, s.
"""
from __future__ import annotations

import os
import warnings
from typing import Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _evade
from ._inputs import PathOrText, is_text, overrides, param_values, scenario_path
from ._result import Record

__all__ = ["assess", "AssessResult", "read_cdm", "write_cdm", "Cdm", "CdmObject", "plan_cam",
           "PlanResult", "burn_plan_columns"]

Sets = Union[None, Mapping[str, object], Sequence[str]]
_CDM_OBJECT_SECTIONS = ("metadata", "od_parameters", "additional_parameters", "state_vector",
                        "covariance")
_COV_ROW_NAMES = ("R", "T", "N", "RDOT", "TDOT", "NDOT", "DRG", "SRP", "THR")


def _keywords(native: object, section: str, obj: int) -> Dict[str, str]:
    return {k: v for k, v, _ in native.items(section, obj) if k != "COMMENT"}


class CdmObject:
    """One object of a CDM (OBJECT1 or OBJECT2): its keywords and typed state/covariance."""

    def __init__(self, native: object, index: int):
        self._native, self._index = native, index
        for section in _CDM_OBJECT_SECTIONS:
            setattr(self, section, _keywords(native, section, index))

    metadata: Dict[str, str]               #: metadata keywords (OBJECT, OBJECT_NAME, REF_FRAME, ...)
    od_parameters: Dict[str, str]          #: OD parameter keywords, as written
    additional_parameters: Dict[str, str]  #: AREA_PC, MASS, ... as written
    state_vector: Dict[str, str]           #: X, Y, Z [km], X_DOT ... [km/s] as written
    covariance: Dict[str, str]             #: CR_R, CT_R, ... as written

    @property
    def name(self) -> str:
        """OBJECT_NAME."""
        return self.metadata.get("OBJECT_NAME", "")

    @property
    def designator(self) -> str:
        """OBJECT_DESIGNATOR (the catalog number)."""
        return self.metadata.get("OBJECT_DESIGNATOR", "")

    @property
    def ref_frame(self) -> str:
        """REF_FRAME of the state (EME2000, GCRF or ITRF)."""
        return self.metadata.get("REF_FRAME", "")

    @property
    def r_ref_frame_m(self) -> np.ndarray:
        """Position at TCA in the object's REF_FRAME [m] (the message's km converted)."""
        return self._native.r_m(self._index)

    @property
    def v_ref_frame_mps(self) -> np.ndarray:
        """Velocity at TCA in the object's REF_FRAME [m/s]."""
        return self._native.v_mps(self._index)

    @property
    def cov_rtn_m2(self) -> np.ndarray:
        """6x6 position-velocity covariance in the object's RTN frame, SI: m^2, m^2/s, m^2/s^2."""
        return self._native.cov_rtn(self._index)

    @property
    def cov_rtn_full_si(self) -> np.ndarray:
        """The whole covariance (6x6 up to 9x9 with DRG, SRP, THR rows) in RTN, SI units;
        its rows are named by :attr:`cov_rows`."""
        return self._native.cov_rtn_full(self._index)

    @property
    def cov_rows(self) -> List[str]:
        """Names of the rows of :attr:`cov_rtn_full_si` (R, T, N, RDOT, TDOT, NDOT, DRG, SRP, THR)."""
        return [_COV_ROW_NAMES[i] for i in self._native.cov_rows(self._index)]

    def __repr__(self) -> str:
        return f"CdmObject({self.name or self.designator}, {self.ref_frame})"


class Cdm:
    """A CCSDS Conjunction Data Message (508.0-B-1), validated when read. Every keyword is kept
    as written (``header``, ``relative`` and each object's sections: dicts of text), with typed
    fields in SI units; ``to_kvn()`` / ``to_xml()`` give the message's text."""

    def __init__(self, native: object, source: str):
        self._native = native
        self.source = source  #: the file's path, or "<text>"
        self.header: Dict[str, str] = _keywords(native, "header", -1)
        self.relative: Dict[str, str] = _keywords(native, "relative", -1)
        self.object1 = CdmObject(native, 0)
        self.object2 = CdmObject(native, 1)

    def _number(self, key: str) -> Optional[float]:
        text = self.relative.get(key, "")
        return float(text) if text else None

    @property
    def message_id(self) -> str:
        return self.header.get("MESSAGE_ID", "")

    @property
    def creation_date(self) -> str:
        """CREATION_DATE as written (UTC)."""
        return self.header.get("CREATION_DATE", "")

    @property
    def originator(self) -> str:
        return self.header.get("ORIGINATOR", "")

    @property
    def tca_utc(self) -> str:
        """TCA as the message writes it (UTC)."""
        return self.relative.get("TCA", "")

    @property
    def tca_j2000_s(self) -> float:
        """TCA, UTC seconds since J2000 (86 400 s days)."""
        return self._native.tca_j2000_s()

    @property
    def miss_distance_m(self) -> Optional[float]:
        """MISS_DISTANCE [m]."""
        return self._number("MISS_DISTANCE")

    @property
    def relative_speed_mps(self) -> Optional[float]:
        """RELATIVE_SPEED [m/s] (None when absent)."""
        return self._number("RELATIVE_SPEED")

    @property
    def relative_position_rtn_m(self) -> Optional[np.ndarray]:
        """RELATIVE_POSITION_R/T/N: object 2 minus object 1 in object 1's RTN frame [m]."""
        return self._vector("RELATIVE_POSITION_")

    @property
    def relative_velocity_rtn_mps(self) -> Optional[np.ndarray]:
        """RELATIVE_VELOCITY_R/T/N in object 1's RTN frame [m/s]."""
        return self._vector("RELATIVE_VELOCITY_")

    def _vector(self, prefix: str) -> Optional[np.ndarray]:
        values = [self._number(prefix + axis) for axis in "RTN"]
        return None if any(v is None for v in values) else np.array(values, dtype=np.float64)

    @property
    def collision_probability(self) -> Optional[float]:
        """COLLISION_PROBABILITY [-] (None when absent)."""
        return self._number("COLLISION_PROBABILITY")

    @property
    def collision_probability_method(self) -> Optional[str]:
        return self.relative.get("COLLISION_PROBABILITY_METHOD") or None

    @property
    def notes(self) -> List[str]:
        """Units read as the standard's equivalent spelling; 7x7..9x9 covariances not positive definite."""
        return list(self._native.notes())

    def to_kvn(self) -> str:
        """The message as KVN text (keyword = value [unit])."""
        return self._native.to_kvn()

    def to_xml(self) -> str:
        """The message as XML text (CCSDS 505.0-B-1 NDM/XML)."""
        return self._native.to_xml()

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Cdm) and self._native == other._native

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"Cdm({self.message_id}, TCA {self.tca_utc}, {self.object1.name} / {self.object2.name})"


def read_cdm(cdm: PathOrText) -> Cdm:
    """Reads a CDM: a path, or the message's text (a str holding a line break); KVN, or XML
    when the text starts with '<'. Raises evade.InputError naming the line and keyword of the
    first problem (every mandatory keyword, number, epoch, unit and enumerated value checked)."""
    if is_text(cdm):
        return Cdm(_evade.cdm_read_text(cdm), "<text>")
    path = os.fspath(cdm)
    return Cdm(_evade.cdm_read_file(path), path)


def write_cdm(cdm: Cdm, path: Union[str, "os.PathLike[str]"], format: str = "kvn") -> None:
    """Writes ``cdm`` to ``path`` as ``format`` 'kvn' or 'xml'."""
    if format not in ("kvn", "xml"):
        raise _evade.InputError(f"format '{format}' is unknown; allowed: kvn, xml")
    text = cdm.to_kvn() if format == "kvn" else cdm.to_xml()
    with open(os.fspath(path), "w", encoding="utf-8") as out:
        out.write(text)


def _cdm_args(cdm: Union[None, PathOrText, Cdm]) -> Tuple[str, str, str]:
    """(path, text, name) of a CDM argument, as the binding takes it."""
    if cdm is None:
        return "", "", ""
    if isinstance(cdm, Cdm):
        return "", cdm.to_kvn(), cdm.source
    if is_text(cdm):
        return "", cdm, "<text>"
    return os.fspath(cdm), "", ""


def _hbr(hbr_m: Optional[float], cdm: object) -> float:
    if hbr_m is None:
        return 0.0  # from AREA_PC of both objects
    if cdm is None:
        raise _evade.InputError("hbr_m: applies only with cdm (a scenario gives conjunction.hbr_m)")
    if float(hbr_m) <= 0.0:
        raise _evade.InputError(f"hbr_m = {hbr_m!r}: the hard-body radius must be > 0 [m]")
    return float(hbr_m)


def _plane_text(plane: Union[None, str, Sequence[float]], hbr_m: Optional[float]) -> str:
    if plane is None:
        return ""
    if isinstance(plane, str):
        return plane
    values = [_number_text(v) for v in plane]
    if hbr_m is not None:
        values.append(_number_text(hbr_m))
    return ",".join(values)


def _number_text(v: object) -> str:
    """An int as written, a float in its shortest exact text (the CLI reads both back)."""
    return str(v) if isinstance(v, (int, np.integer)) else repr(float(v))  # type: ignore[arg-type]


class AssessResult(Record):
    """``evade assess --json``'s document; ``warnings``: what the CLI also prints on stderr."""

    __slots__ = ("_warnings",)

    def __init__(self, data: Dict[str, object], warnings_: List[str]):
        super().__init__(data)
        object.__setattr__(self, "_warnings", list(warnings_))

    @property
    def warnings(self) -> List[str]:  # type: ignore[override]
        """Each covariance repaired before the Pc and each CDM reading note."""
        return self._warnings


def assess(scenario: Optional[str] = None, *, cdm: Union[None, PathOrText, Cdm] = None,
           encounter_plane: Union[None, str, Sequence[float]] = None,
           hbr_m: Optional[float] = None, mc: int = 0, seed: int = 1, threads: int = 0,
           window_s: Optional[float] = None, set: Sets = None) -> AssessResult:
    """The collision probability of one conjunction, as ``evade assess`` computes it.

    The encounter, exactly one of: ``scenario`` (a name or a YAML path with a
    ``conjunction:`` block; ``set`` overrides its keys); ``cdm`` (a CDM's path, its text, or a
    :class:`Cdm`; ``set`` gives assessment.* and earth.* keys; ``hbr_m`` the hard-body radius
    [m], default from AREA_PC of both objects); ``encounter_plane`` (MISS_X_M, MISS_Y_M,
    SIGMA_X_M, SIGMA_Y_M, HBR_M [m] along the plane's principal axes: five numbers, the CLI's
    "a,b,c,d,e" text, or four numbers with ``hbr_m``; the 2D Pc only).
    ``mc``: Monte Carlo samples (0: none; from states only) with ``seed``; ``threads``: its
    worker threads (0: every core; the result does not depend on it). ``window_s``: the
    assessment window's half-width about TCA [s] (assessment.window_s; 0: automatic).
    Returns the JSON document: pc_2d, pc_chan, pc_max, pc (recommended) and method, pc_mc...
    The GIL is released while it runs. Raises evade.InputError with the CLI's message."""
    if not 0 <= int(mc) <= 100_000_000:
        raise _evade.InputError(f"mc = {mc}: expected 0 (no Monte Carlo) or samples in [1, 100000000]")
    if not 0 <= int(threads) <= 256:
        raise _evade.InputError(f"threads = {threads}: expected 0 (every core) or [1, 256]")
    if int(seed) < 0:
        raise _evade.InputError(f"seed = {seed}: expected an integer >= 0")
    plane = _plane_text(encounter_plane, hbr_m)
    hbr = _hbr(hbr_m, cdm) if encounter_plane is None else 0.0
    path, text, name = _cdm_args(cdm)
    params = param_values(**{"assessment.window_s": window_s})
    doc, notes = _evade.assess(scenario_path(scenario) if scenario else "", overrides(set), params,
                               path, text, name,
                               hbr, plane, int(mc), int(seed), int(threads))
    for w in notes:
        warnings.warn(f"evade assess: {w}", RuntimeWarning, stacklevel=2)
    return AssessResult(doc, notes)


def burn_plan_columns(native: object) -> Optional[Dict[str, object]]:
    """A plan of the binding as a dict of numpy columns (None stays None): plan_id, source,
    t_s [s after the plan's epoch] (N,), dv_rsw_mps [m/s] (N, 3), dv_eci_mps [m/s] (N, 3, NaN
    rows where the planner knows no inertial state), dv_eci_valid (N,) and, from the
    observability planner, observability (eps_rad, theta_rad, objective, objective_value,
    evaluations)."""
    if native is None:
        return None
    plan: Dict[str, object] = {"plan_id": native.plan_id, "source": native.source,
                               "t_s": native.t_s, "dv_rsw_mps": native.dv_rsw_mps,
                               "dv_eci_mps": native.dv_eci_mps, "dv_eci_valid": native.dv_eci_valid}
    if native.observability is not None:
        plan["observability"] = dict(native.observability)
    return plan


class PlanResult(Record):
    """A planner command's JSON document, with ``burn_plan``: the plan the command publishes
    (:func:`burn_plan_columns`), or None when there is nothing to fly."""

    __slots__ = ("_burn_plan",)

    def __init__(self, data: Dict[str, object], plan: object):
        super().__init__(data)
        object.__setattr__(self, "_burn_plan", burn_plan_columns(plan))

    @property
    def burn_plan(self) -> Optional[Dict[str, object]]:  # type: ignore[override]
        return self._burn_plan


def plan_cam(scenario: Optional[str] = None, *, cdm: Union[None, PathOrText, Cdm] = None,
             hbr_m: Optional[float] = None, lead_s: float = 0.0, pc_max: float = 1e-4,
             min_miss_m: float = 0.0, along_track_only: bool = False,
             sweep_lead_s: Union[None, str, Sequence[float]] = None, plan_id: int = 0,
             set: Sets = None) -> PlanResult:
    """The minimum-Δv collision-avoidance burn of object 1, as ``evade plan cam`` plans it:
    made ``lead_s`` [s] before TCA, after which Pc < ``pc_max`` and the miss > ``min_miss_m``
    [m] (``along_track_only``: along track only), verified by two-body + J2 propagation.

    The conjunction: ``scenario`` (``conjunction:`` block, ``set`` overrides) or ``cdm`` (path,
    text or :class:`Cdm`; ``hbr_m`` [m], default from AREA_PC). ``sweep_lead_s``: (A, B, N) or
    "A:B:N": the trade space at N lead times from A to B [s] instead of one plan.
    Returns the JSON document and ``burn_plan`` (Δv in RSW and ECI at t = 0, the burn;
    numbered ``plan_id``, the CLI's --seq), None for a sweep or when no burn is needed. A plan
    that is not verified is returned with verified_ok false (the CLI then exits 1). The GIL is
    released while planning. Raises evade.InputError with the CLI's message."""
    if int(plan_id) < 0:
        raise _evade.InputError(f"plan_id = {plan_id}: expected an integer >= 0")
    req = _evade.CamRequest()
    req.lead_s, req.pc_max, req.min_miss_m = float(lead_s), float(pc_max), float(min_miss_m)
    req.along_track_only = bool(along_track_only)
    if sweep_lead_s is None or isinstance(sweep_lead_s, str):
        sweep = sweep_lead_s or ""
    else:
        sweep = ":".join(_number_text(v) for v in sweep_lead_s)
    path, text, name = _cdm_args(cdm)
    doc, plan = _evade.plan_cam(scenario_path(scenario) if scenario else "", overrides(set), path,
                                text, name, _hbr(hbr_m, cdm), req, sweep, int(plan_id))
    return PlanResult(doc, plan)
