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
import re
import shutil
import subprocess
import sys
import tempfile
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


DOC = ROOT / "docs" / "clients.md"
DOC_ADDRESS = "http://127.0.0.1:8000"


def _ts_blocks() -> list[str]:
    """The ```ts blocks of docs/clients.md (the docs test leaves them to this module)."""
    text = DOC.read_text(encoding="utf-8")
    return re.findall(r"^```ts\n(.*?)^```\n", text, flags=re.M | re.S)


def test_the_typescript_examples_of_the_guide_compile_and_run(lab, tmp_path) -> None:
    """Every ```ts block of docs/clients.md, as printed but for the server's address, is
    compiled by ``tsc --strict`` beside the committed types and run by node against the live
    server; it must exit 0 (a block throws when an answer is not what it expects)."""
    url, _ = lab
    blocks = _ts_blocks()
    assert blocks, "docs/clients.md has no ```ts example"
    assert (TS_DIR / "node_modules").is_dir(), "run `make typescript` (npm ci) first"
    # Inside clients/typescript, so that node_modules resolves; removed afterwards.
    work = Path(tempfile.mkdtemp(prefix=".doc-examples-", dir=TS_DIR))
    try:
        src = work / "src"
        src.mkdir()
        shutil.copy(TS_DIR / "src" / "schema.d.ts", src / "schema.d.ts")
        names = []
        for i, block in enumerate(blocks):
            assert DOC_ADDRESS in block, f"block {i} does not call {DOC_ADDRESS}"
            (src / f"example{i}.ts").write_text(block.replace(DOC_ADDRESS, url))
            names.append(f"example{i}")
        config = {
            "extends": "../tsconfig.json",
            "compilerOptions": {"outDir": "dist", "rootDir": "src"},
            "include": ["src"],
        }
        (work / "tsconfig.json").write_text(json.dumps(config))
        tsc = "node ../node_modules/typescript/bin/tsc -p tsconfig.json --strict --noEmitOnError"
        done = subprocess.run(tsc.split(), cwd=work, capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stdout + done.stderr
        (work / "dist" / "package.json").write_text('{"type": "module"}')
        for name in names:
            run = subprocess.run(
                ["node", f"dist/{name}.js"], cwd=work, capture_output=True, text=True, timeout=300
            )
            assert run.returncode == 0, f"{name}: {run.stdout}{run.stderr}"
    finally:
        shutil.rmtree(work, ignore_errors=True)
