"""evade: onboard evasion guidance, conjunction screening, collision probability and
avoidance planning, from Python (docs/PYTHON.md).

The calls are the C++ library's, the ones the ``evade`` CLI makes: the same inputs give the
same numbers as ``evade ... --json``. Units are SI and in the names (``r_m``, ``dv_mps``);
frames too (``r_eci_m``). Bad input raises :class:`InputError` (a ValueError) with the CLI's
message.
"""
from pathlib import Path as _Path

from ._evade import InputError, __version__
from . import _evade

_evade.set_package_scenario_dir(str(_Path(__file__).resolve().parent / "scenarios"))
from . import sgp4
from .screening import ScreenResult, screen
from ._result import Record, columns
from .assessment import *  # noqa: F401,F403  (their __all__)
from .planners import *  # noqa: F401,F403
from .simulation import *  # noqa: F401,F403
from . import assessment, planners, simulation

__all__ = ["InputError", "__version__", "sgp4", "screen", "ScreenResult", "Record", "columns",
           *assessment.__all__, *planners.__all__, *simulation.__all__]
