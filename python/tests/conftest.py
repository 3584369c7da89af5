"""Fixtures of the Python suite: the evade CLI beside the module (the same library calls), and
the repository's data files. EVADE_CLI names the CLI (scripts/test: the release build's)."""
from __future__ import annotations

import json
import os
import re
import subprocess
from pathlib import Path
from typing import List, Tuple

import pytest

REPO = Path(__file__).resolve().parents[2]


def _cli_path() -> str:
    path = os.environ.get("EVADE_CLI", str(REPO / "build" / "apps" / "evade"))
    if not Path(path).is_file():
        pytest.skip(f"the evade CLI is not built ({path}; set EVADE_CLI)")
    return path


@pytest.fixture(scope="session")
def repo() -> Path:
    """The repository root (data files: scenarios/, test/data/)."""
    return REPO


@pytest.fixture(scope="session")
def cli_json():
    """cli_json(args) -> the document `evade ARGS --json` prints (exit 0 required)."""
    exe = _cli_path()

    def run(args: List[str]) -> dict:
        p = subprocess.run([exe, *args, "--json"], capture_output=True, text=True, check=False)
        assert p.returncode == 0, f"evade {' '.join(args)} exited {p.returncode}: {p.stderr}"
        return json.loads(p.stdout)

    return run


@pytest.fixture(scope="session")
def cli_error():
    """cli_error(args) -> (exit code, stderr) of a CLI call that must fail."""
    exe = _cli_path()

    def run(args: List[str]) -> Tuple[int, str]:
        p = subprocess.run([exe, *args], capture_output=True, text=True, check=False)
        assert p.returncode != 0, f"evade {' '.join(args)} succeeded"
        return p.returncode, p.stderr

    return run


def cli_message(stderr: str) -> str:
    """The message of the CLI's error line: "evade: invalid input: MSG", "evade: error: MSG", or
    a parameter flag's "--FLAG: MSG (flag --FLAG)" (the declaration's check, run by the flag)."""
    for line in stderr.splitlines():
        for prefix in ("evade: invalid input: ", "evade: error: "):
            if line.startswith(prefix):
                return line[len(prefix):]
        m = re.match(r"^(--[a-z0-9-]+): (.*) \(flag \1\)$", line)
        if m:
            return m.group(2)
    raise AssertionError(f"no error line in: {stderr}")


def without_wall_times(doc):
    """The document without its wall-clock fields (keys holding "wall" or ending in runtime_s):
    the only values two runs of the same input may not share."""
    if isinstance(doc, dict):
        return {k: without_wall_times(v) for k, v in doc.items()
                if "wall" not in k and not k.endswith("runtime_s")}
    if isinstance(doc, list):
        return [without_wall_times(v) for v in doc]
    return doc
