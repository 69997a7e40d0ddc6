"""The lab scripts of both clients, type-checked and run against one live server.

clients/python/examples/lab.py (with the hand-written modules) under ``mypy --strict``;
clients/typescript/src/lab.ts compiled by ``tsc --strict`` (emitting nothing on an error).
Each then runs the session a lab would (list robots, FK, IK of FK's pose, a Cartesian line,
a Panda package upload with its SRDF, a collision query with a scene, a reachability build
polled to the end); the results are checked against references the scripts do not compute:
the SRDF's own groups, the pedestal's placement around the Panda's base, the samples asked
for, and each other (both clients must see the same answers).
"""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from xml.etree import ElementTree

import pytest

from tests.helpers import serve
from tests.packages import PANDA_DIR, panda_files, zip_bytes

ROOT = Path(__file__).resolve().parents[2]
PY_CLIENT = ROOT / "clients" / "python"
TS_DIR = ROOT / "clients" / "typescript"
HAND_WRITTEN = ["session.py", "arrays.py", "stream.py"]


@pytest.fixture(scope="module")
def lab(tmp_path_factory) -> Iterator[tuple[str, Path]]:
    """(URL of a live server without a token, the Panda package as a zip)."""
    tmp = tmp_path_factory.mktemp("lab")
    archive = tmp / "panda_package.zip"
    archive.write_bytes(zip_bytes(panda_files()))
    with serve(tmp / "data", settings={}) as server:
        yield server.url, archive


def _check(results: dict, name: str) -> None:
    srdf = ElementTree.parse(PANDA_DIR / "srdf" / "panda.srdf").getroot()
    assert results["package_robot"] == name
    assert results["package_groups"] == [g.get("name") for g in srdf.findall("group")]
    assert "ur5" in results["robots"] and name not in results["robots"]  # listed before upload
    assert results["ik_position_error"] <= 1e-6
    assert results["path_fraction"] == 1.0 and results["path_end_error"] <= 1e-4
    # The pedestal (0.3 × 0.3 × 0.2 m box from the floor up) encloses the base's first links.
    assert results["collision"] is True
    assert any(p.endswith("|pedestal") for p in results["collision_pairs"])
    assert results["reachability"] == "done" and results["reachability_samples"] == 2000


def _run(cmd: list[str]) -> dict:
    done = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_the_python_lab_type_checks_under_mypy_strict() -> None:
    files = [str(PY_CLIENT / "examples" / "lab.py")]
    files += [str(PY_CLIENT / "denavit_client" / name) for name in HAND_WRITTEN]
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", *files], cwd=ROOT, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.fixture(scope="module")
def tsc() -> subprocess.CompletedProcess[str]:
    """tsc --strict on the lab script, emitting dist/lab.js only when it type-checks."""
    assert (TS_DIR / "node_modules").is_dir(), "run `make typescript` (npm ci) first"
    command = "node node_modules/typescript/bin/tsc -p tsconfig.json --strict --noEmitOnError"
    return subprocess.run(command.split(), cwd=TS_DIR, capture_output=True, text=True)


def test_the_typescript_lab_compiles_under_tsc_strict(tsc) -> None:
    assert tsc.returncode == 0, tsc.stdout + tsc.stderr


@pytest.fixture(scope="module")
def python_results(lab) -> dict:
    url, archive = lab
    lab_py = str(PY_CLIENT / "examples" / "lab.py")
    return _run([sys.executable, lab_py, url, str(archive), "--name", "lab_py"])


def test_the_python_lab_runs_against_a_live_server(python_results) -> None:
    _check(python_results, "lab_py")


def test_the_typescript_lab_runs_against_a_live_server(lab, tsc, python_results) -> None:
    url, archive = lab
    assert tsc.returncode == 0, tsc.stdout + tsc.stderr
    results = _run(["node", str(TS_DIR / "dist" / "lab.js"), url, str(archive), "lab_ts"])
    _check(results, "lab_ts")
    # Both clients sent the same requests: the same answers.
    for key in ("ik_branches", "path_points", "collision_pairs", "package_groups"):
        assert results[key] == python_results[key], key
