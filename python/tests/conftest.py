"""Fixtures of the Python suite: the evade CLI beside the module (the same library calls), and
the repository's data files. EVADE_CLI names the CLI (scripts/test: the release build's)."""
from __future__ import annotations

import json
import os
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
    """The message of the CLI's error line ("evade: invalid input: MSG" / "evade: error: MSG")."""
    for line in stderr.splitlines():
        for prefix in ("evade: invalid input: ", "evade: error: "):
            if line.startswith(prefix):
                return line[len(prefix):]
    raise AssertionError(f"no error line in: {stderr}")
