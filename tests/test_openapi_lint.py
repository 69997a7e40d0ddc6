"""docs/openapi.json passes Redocly's recommended rules and Spectral's OpenAPI rules with no
error (warnings allowed), offline.

The linters are the versions tools/lint/package-lock.json pins, installed by ``make test``
(``make openapi-lint-tools``: ``npm ci``); without them this test fails and says how to
install them. They run without a network (``unshare -rn``: an empty network namespace),
with Redocly's telemetry and update check off. tests/test_openapi.py checks that the
committed document is the one the app serves.
"""

from __future__ import annotations

import os
import shutil
import subprocess

from tests.helpers import ROOT

LINT = ROOT / "tools" / "lint"
DOCUMENT = ROOT / "docs" / "openapi.json"
OFFLINE_ENV = {
    **os.environ,
    "REDOCLY_TELEMETRY": "off",
    "REDOCLY_SUPPRESS_UPDATE_NOTICE": "true",
    "NO_COLOR": "1",
}


def _run(tool: str, *args: str) -> subprocess.CompletedProcess[str]:
    binary = LINT / "node_modules" / ".bin" / tool
    assert binary.exists(), f"{binary} missing: run `make openapi-lint-tools` (npm ci)"
    unshare = shutil.which("unshare")
    assert unshare, "unshare (util-linux) is needed to run the linters without a network"
    return subprocess.run(
        [unshare, "-rn", str(binary), *args],
        cwd=LINT,
        env=OFFLINE_ENV,
        capture_output=True,
        text=True,
        timeout=300,
    )


def test_redocly_finds_no_error() -> None:
    done = _run("redocly", "lint", "--config", "redocly.yaml", "--format", "summary", str(DOCUMENT))
    out = done.stdout + done.stderr
    assert done.returncode == 0 and "error " not in out, out


def test_spectral_finds_no_error() -> None:
    done = _run(
        "spectral",
        "lint",
        "--ruleset",
        ".spectral.yaml",
        "--fail-severity",
        "error",
        "--format",
        "text",
        str(DOCUMENT),
    )
    out = done.stdout + done.stderr
    assert done.returncode == 0 and " error " not in out, out
